#pragma once
#include <functional>
#include <memory>
#include <string>

#include <glm/vec3.hpp>

#include "common/hdr_image.h"
#include "environment/cube_map.h"
#include "environment/irradiance.h"
#include "environment/prefilter.h"
#include "shading/brdf_model_id.h"
#include "shading/shading.h"

namespace patina {

struct EnvironmentSettings {
    PrefilterSettings prefilter;
    bool operator==(const EnvironmentSettings&) const = default;
};

// An environment made ready to light with: the source image at full resolution (the ground
// truth and the irradiance read it, never the chain), the prefiltered chain and the irradiance
// map (irradiance.h). Immutable once made; prepared scenes share it (scene/prepared_scene.h).
struct Environment {
    std::string source;      // what it was made from: "builtin:studio", a path
    HdrImage image;          // equirect, invalid pixels replaced
    size_t replacedPixels = 0;
    CubeChain prefiltered;
    CubeLevel irradiance;   // E(n) of irradiance.h, faces of kIrradianceFaceSize texels
    EnvironmentSettings settings;

    float maxLod() const { return float(prefiltered.size() - 1); }
};

// Everything above from an equirect image, prefiltered by `prefilter`; null when `progress`
// stopped it.
std::shared_ptr<const Environment> prepareEnvironment(HdrImage image, std::string source,
                                                      const EnvironmentSettings& settings = {},
                                                      const Progress& progress = {},
                                                      PrefilterFunction prefilter = prefilterCube);

// What a scene's environment light shows: `prepared`, which must have been made from `source`.
// Nothing is made here (assets/ prepares a scene): std::invalid_argument for any other.
std::shared_ptr<const Environment> environmentShown(const std::shared_ptr<const Environment>& prepared,
                                                   const std::string& source);

// The split sum on the CPU for `model`: the same code as the GPU's (ibl_model.glsl), reading
// the chain and the irradiance map with the seamless filters of cube_map.h.
glm::vec3 shadeEnvironmentOnCpu(BrdfModelId model, const shader::SurfaceMaterial& material, const Environment& environment,
                                float intensity, float rotationDegrees, glm::vec3 N, glm::vec3 V, bool dominant = false);

// KHR_materials_transmission's light through the wall under the environment on the CPU
// (transmissionEnvironment of ibl_model.glsl, the GPU's), reading the chain as the split sum
// does; `material` as deriveSurfaceMaterial made it.
glm::vec3 transmissionEnvironmentOnCpu(BrdfModelId model, const shader::SurfaceMaterial& material,
                                       const shader::Transmission& transmission, const Environment& environment,
                                       float intensity, float rotationDegrees, glm::vec3 V);

// The stochastic mode on the CPU (shadeEnvironmentStochastic of ibl_model.glsl), reading
// `sourceChain`: the environment's source cube and its box-filtered mips (sourceMipChain).
glm::vec3 stochasticEnvironmentOnCpu(BrdfModelId model, const shader::SurfaceMaterial& material,
                                     const Environment& environment, const CubeChain& sourceChain, float intensity,
                                     float rotationDegrees, glm::vec3 N, glm::vec3 V, unsigned count,
                                     glm::vec2 jitter);

// The source as a cube of the chain's mip-0 size and its box-filtered mips, as
// glGenerateMipmap makes them on the GPU (what filtered importance sampling reads).
CubeChain sourceMipChain(const Environment& environment);

// The irradiance map as the shared code reads it (ibl.glsl's irradianceFromMap, an
// EnvironmentSource on the CPU): bilinear and seamless, as the GPU's sampler; refers to
// `environment`, which must outlive it.
std::function<glm::vec3(glm::vec3, float)> irradianceReader(const Environment& environment);

}  // namespace patina
