#include "bench/brdf_floor.h"

namespace patina {

ShaderSpecialisation brdfFloorFor(size_t count, size_t flatSlots) {
    ShaderSpecialisation key;
    for (size_t i = 0; i < count; ++i) {
        // The floor's scene has directional lights only (brdfFloorScene). One line of GLSL per
        // light: the key becomes a #define, and GLSL 3.30 has no line continuation.
        const LightSource source = sourceOf(i, flatSlots, "FLAT_DIRECTIONAL");
        const std::string& light = source.fragment;
        addLight(key, i,
                 "{ vec3 L = " + light + ".directionToLight; BrdfValue f = evaluateBrdf(material, N, V, L); " +
                     "radiance += " + light + ".radiance * max(dot(N, L), 0.0f) * (f.diffuse + f.specular); }",
                 source);
    }
    return key;
}

Scene brdfFloorScene(const Scene& scene) {
    Scene floor = scene;
    // The floor is the analytic lights' BRDF cost: an environment has no direction to take.
    std::erase_if(floor.lights, [](const Light& light) { return light.type == LightType::Environment; });
    for (Light& light : floor.lights) {
        if (light.type == LightType::Point) {
            light.direction = -light.position;
        } else if (light.type == LightType::Hemisphere) {
            light.direction = {0.0f, -1.0f, 0.0f};
        }
        light.type = LightType::Directional;
    }
    return floor;
}

RenderSettings brdfFloorSettings(RenderSettings settings) {
    settings.path = RenderPath::Specialised;
    settings.lightCode = [](const std::vector<shader::PackedLight>& lights, size_t flatSlots) {
        return brdfFloorFor(lights.size(), flatSlots);
    };
    return settings;
}

}  // namespace patina
