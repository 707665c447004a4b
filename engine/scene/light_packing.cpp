#include "scene/light_packing.h"

namespace patina {

namespace {
// A sphere of source radius 0 is the point light at its centre, and a tube whose ends meet the
// sphere there (Karis's formulas reduce to them, to rounding): packed as those, they render bit
// for bit as those, and cost what those cost.
int shaderLightType(const Light& light) {
    switch (light.type) {
    case LightType::Point: return shader::LIGHT_POINT;
    case LightType::Directional: return shader::LIGHT_DIRECTIONAL;
    case LightType::Hemisphere: return shader::LIGHT_HEMISPHERE;
    case LightType::Environment: return -1;   // not a packed light: the renderer's own pass
    case LightType::Sphere: return light.sourceRadius > 0.0f ? shader::LIGHT_SPHERE : shader::LIGHT_POINT;
    case LightType::Tube:
        if (light.start != light.end) {
            return shader::LIGHT_TUBE;
        }
        return light.sourceRadius > 0.0f ? shader::LIGHT_SPHERE : shader::LIGHT_POINT;
    }
    return shader::LIGHT_POINT;
}
}  // namespace

shader::PackedLight packLight(const Light& light) {
    const glm::vec3 radiance = light.color * light.intensity;
    shader::PackedLight packed{};
    packed.radiance = radiance;
    packed.type = shaderLightType(light);
    // A tube starts at its start (the sphere or point it packs as, when its ends meet).
    packed.position = light.type == LightType::Tube ? light.start : light.position;
    packed.sourceRadius = packed.type == shader::LIGHT_POINT ? 0.0f : light.sourceRadius;
    packed.tubeEnd = light.end;
    packed.inverseRange = light.range > 0.0f ? 1.0f / light.range : 0.0f;
    // L = -normalize(direction) (docs/SHADING.md S1). A zero direction (rejected by the loaders) gives no light
    // rather than NaN.
    packed.directionToLight = -shader::safeNormalize(light.direction);
    packed.attenuation = light.attenuation;
    packed.sky = light.sky * radiance;
    packed.ground = light.ground * radiance;
    return packed;
}

bool hasKarisAttenuation(const shader::PackedLight& light) {
    return (light.type == shader::LIGHT_POINT || light.type == shader::LIGHT_SPHERE ||
            light.type == shader::LIGHT_TUBE) &&
           light.attenuation == shader::KARIS_ATTENUATION;
}

std::vector<size_t> enabledLightOrder(const std::vector<Light>& lights) {
    std::vector<size_t> order;
    // Area lights last, so a scene without them sums in the order it always did.
    for (int type : {shader::LIGHT_POINT, shader::LIGHT_DIRECTIONAL, shader::LIGHT_HEMISPHERE, shader::LIGHT_SPHERE,
                     shader::LIGHT_TUBE}) {
        for (size_t i = 0; i < lights.size(); ++i) {
            if (lights[i].enabled && shaderLightType(lights[i]) == type) {
                order.push_back(i);
            }
        }
    }
    return order;
}

std::vector<shader::PackedLight> packEnabledLights(const std::vector<Light>& lights) {
    std::vector<shader::PackedLight> packed;
    for (size_t i : enabledLightOrder(lights)) {
        packed.push_back(packLight(lights[i]));
    }
    return packed;
}

namespace {
int countOf(const std::vector<shader::PackedLight>& packed, int type) {
    int count = 0;
    for (const shader::PackedLight& light : packed) {
        count += light.type == type ? 1 : 0;
    }
    return count;
}
}  // namespace

glm::ivec4 packedLightCounts(const std::vector<shader::PackedLight>& packed) {
    return {int(packed.size()), countOf(packed, shader::LIGHT_POINT), countOf(packed, shader::LIGHT_DIRECTIONAL),
            countOf(packed, shader::LIGHT_HEMISPHERE)};
}

glm::ivec4 packedAreaLightCounts(const std::vector<shader::PackedLight>& packed) {
    return {countOf(packed, shader::LIGHT_SPHERE), countOf(packed, shader::LIGHT_TUBE), 0, 0};
}

}  // namespace patina
