#pragma once
// `patina area-accuracy`: what each area-light shortcut costs against the exact integral
// (reference/area_lights.h). Karis 2013's representative point for the specular lobe with
// both readings of eq. 10's widening (s / (2 d) and s / (3 d)); for the diffuse lobe Karis's
// point at the centre (the line irradiance for a tube) and Frostbite 2014's horizon-clipped
// sphere illuminance; over roughness, the light's angular size s / d, and elevations where the
// light crosses the horizon. Physical lights (inverse square, no window), the "epic" model, on
// the CPU: the shared shader code compiled as C++, so the numbers are the GPU's to rounding.
#include <string>
#include <vector>

#include "image/chart.h"
#include "image/image.h"

namespace patina {

struct AreaAccuracyRow {
    std::string light;        // "sphere" or "tube"
    std::string lobe;         // "specular" or "diffuse"
    std::string method;       // specular: "karis-s/2d", "karis-s/3d"; diffuse: "karis", "frostbite"
    double roughness = 0.0;   // the material's r (1 for the diffuse rows)
    double size = 0.0;        // s / d: source radius over the distance of the light's centre
    double elevationDegrees = 0.0;   // the centre's angle from the normal
    bool crossesHorizon = false;     // part of the light below the surface's horizon
    // Specular: sum |approximation - truth| / sum truth over a sweep of views through the
    // highlight (its shape and its energy). Diffuse: |approximation - truth| over the
    // illuminance I / d^2 of the light straight above.
    double error = 0.0;
    double energyRatio = 1.0;    // sum approximation / sum truth (1: energy kept)
    double truthError = 0.0;     // the ground truth's standard error on the same scale as `error`
};

struct AreaCost {
    std::string method;
    double nanoseconds = 0.0;   // per shaded point, one light, fp32 on one CPU core
};

struct AreaAccuracyResult {
    std::vector<AreaAccuracyRow> rows;
    std::vector<AreaCost> costs;
    int referenceSamples = 0;   // Monte Carlo iterations per probe of the ground truth
};

AreaAccuracyResult runAreaAccuracy(bool quick);
std::string areaAccuracyCsv(const AreaAccuracyResult& result);
std::string areaCostCsv(const AreaAccuracyResult& result);
// Specular error against roughness (sphere, tube), diffuse error across the horizon.
Chart areaAccuracyChart(const AreaAccuracyResult& result);
// Rows of spheres from r = 0.05 to 1 under a sphere light and under a tube light: Karis's
// approximation, the ground truth (probe rows by Monte Carlo) and the error between them.
LdrImage areaLightSpheres(bool quick);

}  // namespace patina
