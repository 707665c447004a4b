#pragma once
// The CPU twin of shade.frag's inspectedChannel (PATINA_CHANNEL): a surface point's channel
// inputs (shaders/shared/channels.glsl) gathered by the same shared functions in the same order,
// for the inspector's CPU images, its pixel read-out and the tests that hold the GPU to them.
#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/shading.h"

namespace patina {

enum class BrdfModelId;

// What shade.frag reads at the fragment: the material after its maps, the maps' occlusion and
// emission, the UVs and interpolated tangent (w = 0: none), the unit geometry normal and the
// shading normal N after the normal map, the unit V towards the camera and the position P.
struct ChannelPoint {
    glm::vec3 baseColor{0.0f};
    float alpha = 1.0f, roughness = 0.0f, specular = 0.5f, metallic = 0.0f, occlusion = 1.0f;
    glm::vec3 emission{0.0f};
    glm::vec2 uv0{0.0f}, uv1{0.0f};
    glm::vec4 tangent{0.0f};
    glm::vec3 geometryNormal{0.0f}, N{0.0f}, V{0.0f}, P{0.0f};
};

// The environment as environment.glsl's uniforms give it: its prefiltered chain (any trilinear
// lookup of direction and level), its irradiance map (a lookup of direction), intensity and
// rotation.
struct ChannelEnvironment {
    std::function<glm::vec3(glm::vec3, float)> prefiltered;
    float maxLod = 0.0f;
    std::function<glm::vec3(glm::vec3, float)> irradiance;
    float intensity = 1.0f;
    float rotationDegrees = 0.0f;
};

// `lights` packed (packEnabledLights' order); `asked` and `key` as uChannelLight and uKeyLight
// (scene/channel.h's ChannelLights); `environment` null without one.
shader::ChannelInputs gatherChannelInputs(BrdfModelId id, const ChannelPoint& point,
                                          const std::vector<shader::PackedLight>& lights, int asked, int key,
                                          const ChannelEnvironment* environment);

}  // namespace patina
