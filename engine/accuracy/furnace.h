#pragma once
// The white furnace: each model's specular directional albedo E(mu) with F = 1, against
// roughness, by numerical integration (energy_table.h's directionalAlbedo, compensation applied
// for the models that have it).
#include <string>
#include <vector>

#include "shading/brdf_models.h"
#include "image/chart.h"

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

// The whole material under the furnace (a uniform white environment of radiance 1): a white
// dielectric (F0 0.04), a white metal, diffuse and specular, and a white thin-walled glass
// (KHR_materials_transmission 1: reflected plus transmitted, the furnace's light behind the wall
// seen through it), at mu = 1 and 0.25, as the product's split sum shows them and as the BRDF
// and BTDF integrate (the ground truth, with its standard error; albedo_curve.h). Energy
// conservation asks both to stay at or under 1.
struct MaterialFurnaceRow {
    std::string model, material;
    double mu = 0.0, roughness = 0.0;
    double splitSum = 0.0, truth = 0.0, truthStandardError = 0.0;   // luminance
    double splitSumTransmitted = 0.0, truthTransmitted = 0.0;       // of splitSum and truth, through the wall
};
std::vector<MaterialFurnaceRow> materialFurnace(const std::vector<BrdfModelId>& models, int steps, int samples);
// CSV: model,material,mu,roughness,split_sum,truth,truth_se,split_sum_transmitted,truth_transmitted
std::string materialFurnaceCsv(const std::vector<MaterialFurnaceRow>& rows);

}  // namespace patina
