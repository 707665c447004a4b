#pragma once
// Whole materials under an environment, by BRDF model: what the product shows (the model's own
// split sum, shadeEnvironmentOnCpu: its Fresnel, its diffuse weighting and, for `gltf`,
// Fdez-Aguera's multiple scattering) against the ground truth of the same model's BRDF under the
// same environment (reference/radiance.h, both lobes), by roughness. The specular-only split sum
// of every error source is split_sum_accuracy.h's; this one is the glTF look's question: how far
// is the picture of a dielectric or a metal from what its BRDF integrates to. docs/LIGHTING.md.
#include <string>
#include <vector>

#include "accuracy/split_sum_accuracy.h"
#include "shading/brdf_model_id.h"

namespace patina {

// One model, material and roughness under one environment: over the grid's surface
// orientations and view angles, the mean of (split sum - truth) / truth (luminance) and of its
// magnitude, and the truth's own relative standard error.
struct ModelSplitSumRow {
    std::string environment, model, material;
    float roughness = 0.0f;
    double meanSignedError = 0.0, meanRelativeError = 0.0;
    double truthRelativeStandardError = 0.0;
};

// The materials measured: a grey dielectric (base 0.5) and a white metal, each at F0 0.04 where
// a dielectric.
std::vector<std::string> modelSplitSumMaterials();

// `models` under each environment; `quick`: a small grid and 256 ground-truth iterations per
// point (else 2048).
std::vector<ModelSplitSumRow> measureModelSplitSum(const std::vector<NamedEnvironment>& environments,
                                                   const std::vector<BrdfModelId>& models, bool quick);

// CSV: environment,model,material,roughness,mean_signed_error,mean_relative_error,truth_relative_se
std::string modelSplitSumCsv(const std::vector<ModelSplitSumRow>& rows);

}  // namespace patina
