#pragma once
// The white furnace: each model's specular directional albedo E(mu) with F = 1, against
// roughness, by numerical integration (energy_table.h's directionalAlbedo, compensation applied
// for the models that have it).
#include <string>
#include <vector>

#include "shading/brdf_models.h"
#include "accuracy/chart.h"

namespace patina {

struct FurnaceCurve {
    std::string model;
    double mu;
    std::vector<double> roughness, albedo;
};

// For every model, E at mu = 1 and mu = 0.25 over `steps` + 1 roughness values.
std::vector<FurnaceCurve> whiteFurnace(int steps, int samples);
std::string furnaceCsv(const std::vector<FurnaceCurve>& curves);
Chart furnaceChart(const std::vector<FurnaceCurve>& curves);

}  // namespace patina
