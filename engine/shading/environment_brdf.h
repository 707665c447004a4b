#pragma once
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shading/shading.h"

namespace patina {

enum class BrdfModelId;

// A model's environment BRDF (A, B) of Karis 2013 eq. 8, kEnvironmentBrdfSize^2 values, NoV and
// r at i / (size - 1), row-major by r, integrated in fp32 by the shared GLSL
// (shaders/shared/ibl_model.glsl) with kEnvironmentBrdfSamples Hammersley points per texel on
// first use (thread-safe). Kept as 32-bit floats: 8 bits band, and sRGB would be wrong.
constexpr int kEnvironmentBrdfSize = 64;
constexpr unsigned kEnvironmentBrdfSamples = 1024;
const std::vector<glm::vec2>& environmentBrdfTable(BrdfModelId id);

// The table at any size and sample count, for the accuracy measurements (a LUT's resolution
// is one of the split sum's error sources).
std::vector<glm::vec2> integrateEnvironmentBrdfTable(BrdfModelId id, int size, unsigned samples);
// (A, B) integrated at one point, and the table interpolated as the shaders do it.
glm::vec2 integrateEnvironmentBrdf(BrdfModelId id, float NoV, float roughness, unsigned samples);
glm::vec2 environmentBrdf(BrdfModelId id, float NoV, float roughness);

// (cos, sin) of an environment light's rotationDegrees: what shadeEnvironment takes, on the
// CPU and as the GPU's uniform, computed once here so both turn by the same floats.
glm::vec2 environmentRotation(float rotationDegrees);

// shadeEnvironment of ibl_model.glsl for `id` (the CPU side of the GPU's split sum); `irradiance`
// reads the irradiance map (environment/environment.h's irradianceReader).
glm::vec3 shadeEnvironment(BrdfModelId id, shader::EnvironmentSource prefiltered, float maxLod,
                           shader::EnvironmentSource irradiance, float intensity, float rotationDegrees,
                           const shader::SurfaceMaterial& material, glm::vec3 N, glm::vec3 V, bool dominant);

// clearcoatEnvironment of ibl_model.glsl for `id` times `intensity`: KHR_materials_clearcoat's
// coat under the environment by the split sum (the GPU's, whichever method shades the base).
glm::vec3 clearcoatEnvironment(BrdfModelId id, shader::EnvironmentSource prefiltered, float maxLod, float intensity,
                               float rotationDegrees, const shader::Clearcoat& coat, glm::vec3 V);

// transmissionEnvironment of ibl_model.glsl for `id` times `intensity`: KHR_materials_
// transmission's light through the wall under the environment (the GPU's, whichever method
// shades the base); `material` as deriveSurfaceMaterial made it.
glm::vec3 transmissionEnvironment(BrdfModelId id, shader::EnvironmentSource prefiltered, float maxLod, float intensity,
                                  float rotationDegrees, const shader::SurfaceMaterial& material,
                                  const shader::Transmission& transmission, glm::vec3 V);

// shadeEnvironmentStochastic of ibl_model.glsl for `id`: `count` filtered importance samples at
// the real N and V read from `source`, the box-filtered mip chain of the environment's source.
glm::vec3 shadeEnvironmentStochastic(BrdfModelId id, shader::EnvironmentSource source, float sourceFaceSize,
                                     shader::EnvironmentSource irradiance, float intensity, float rotationDegrees,
                                     const shader::SurfaceMaterial& material, glm::vec3 N, glm::vec3 V,
                                     unsigned count, glm::vec2 jitter);

// The model's f under an environment (environmentVisibility), for the ground truth.
shader::BrdfValue evaluateBrdfUnderEnvironment(BrdfModelId id, const shader::SurfaceMaterial& material,
                                               glm::vec3 N, glm::vec3 V, glm::vec3 L);

}  // namespace patina
