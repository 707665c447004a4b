#include "scene/light_packing.h"

namespace patina {

namespace {
int shaderLightType(LightType type) {
    switch (type) {
    case LightType::Point: return shader::LIGHT_POINT;
    case LightType::Directional: return shader::LIGHT_DIRECTIONAL;
    case LightType::Hemisphere: return shader::LIGHT_HEMISPHERE;
    case LightType::Environment: return -1;   // not a packed light: the renderer's own pass
    }
    return shader::LIGHT_POINT;
}
}  // namespace

shader::PackedLight packLight(const Light& light) {
    const glm::vec3 radiance = light.color * light.intensity;
    shader::PackedLight packed{};
    packed.radiance = radiance;
    packed.type = shaderLightType(light.type);
    packed.position = light.position;
    packed.inverseRange = light.range > 0.0f ? 1.0f / light.range : 0.0f;
    // Spec: L = -normalize(direction). A zero direction (rejected by the loaders) gives no light
    // rather than NaN.
    packed.directionToLight = -shader::safeNormalize(light.direction);
    packed.attenuation = light.attenuation;
    packed.sky = light.sky * radiance;
    packed.ground = light.ground * radiance;
    return packed;
}

bool hasKarisAttenuation(const shader::PackedLight& light) {
    return light.type == shader::LIGHT_POINT && light.attenuation == shader::KARIS_ATTENUATION;
}

std::vector<shader::PackedLight> packEnabledLights(const std::vector<Light>& lights) {
    std::vector<shader::PackedLight> packed;
    for (int type : {shader::LIGHT_POINT, shader::LIGHT_DIRECTIONAL, shader::LIGHT_HEMISPHERE}) {
        for (const Light& light : lights) {
            if (light.enabled && shaderLightType(light.type) == type) {
                packed.push_back(packLight(light));
            }
        }
    }
    return packed;
}

glm::ivec4 packedLightCounts(const std::vector<shader::PackedLight>& packed) {
    glm::ivec4 counts(int(packed.size()), 0, 0, 0);
    for (const shader::PackedLight& light : packed) {
        counts[1 + light.type] += 1;
    }
    return counts;
}

}  // namespace patina
