#pragma once
// What each approximation of image-based lighting costs in accuracy (issue 18; docs/LIGHTING.md
// L2, L3 and L5): Karis's split sum against the Monte Carlo ground truth of the same BRDF under the
// same environment, over a grid of (NoV, r, F0), with its error split by source, the dominant
// direction variant and the stochastic mode. Nobody publishes these numbers; docs/LIGHTING.md
// shows them.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "environment/environment.h"

namespace patina {

struct NamedEnvironment {
    std::string name;
    std::shared_ptr<const Environment> environment;
};

struct SplitSumAccuracyOptions {
    bool quick = false;            // a small grid and fewer samples (CI)
    // Ground-truth iterations per grid point (3 directions each); 0: 4096, or 256 when quick.
    int referenceSamples = 0;
};

// One measured value: `method` at one grid point of one environment, as the mean over the
// grid's surface orientations of |approximation - truth| / truth (luminance). For the rows that
// isolate one error source ("mip quantisation", "LUT 32x32 fp16", ...) the difference is
// between the variant and the same estimate with that source made exact, still over the truth.
struct SplitSumErrorRow {
    std::string environment, method;
    float NoV = 0.0f, roughness = 0.0f, f0 = 0.0f;
    double relativeError = 0.0;
    double truthRelativeStandardError = 0.0;   // of the ground truth itself
};

// Diffuse: the 9-coefficient irradiance (with and without its guards) against the ground truth
// of a white Lambert surface, over many normals.
struct ShErrorRow {
    std::string environment, method;
    double meanRelativeError = 0.0, maxRelativeError = 0.0;
    double negativeFraction = 0.0;   // of normals where the unguarded series is below 0
};

struct SplitSumAccuracy {
    std::vector<SplitSumErrorRow> rows;
    std::vector<ShErrorRow> sh;
};

// `count` unit vectors spread evenly over the sphere (a Fibonacci lattice): surfaces facing up,
// down and sideways, so a sun, a floor and the horizon all count.
std::vector<glm::vec3> spreadNormals(int count);
// V at NoV to N, turned about N by an azimuth of its own for each `index`.
glm::vec3 viewAt(glm::vec3 N, float NoV, int index);

// The methods and error sources measured, in the order they are reported.
std::vector<std::string> splitSumMethods(bool quick);

SplitSumAccuracy measureSplitSum(const std::vector<NamedEnvironment>& environments,
                                 const SplitSumAccuracyOptions& options);

// CSV: environment,method,NoV,roughness,f0,relative_error,truth_relative_se
std::string splitSumCsv(const std::vector<SplitSumErrorRow>& rows);
// CSV: environment,method,mean_relative_error,max_relative_error,negative_fraction
std::string shCsv(const std::vector<ShErrorRow>& rows);

// The mean of a method's rows (all environments when `environment` is empty); NaN for none.
double meanError(const std::vector<SplitSumErrorRow>& rows, const std::string& method,
                 const std::string& environment = "");

}  // namespace patina
