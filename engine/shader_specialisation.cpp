#include "shader_specialisation.h"

#include "light_packing.h"

namespace patina {

std::vector<std::string> ShaderSpecialisation::defines() const {
    std::vector<std::string> result{"PATINA_SINGLE_PASS", "PATINA_SPECIALISED", "PATINA_LIGHTS " + lights};
    if (noDiffuse) {
        result.push_back("PATINA_NO_DIFFUSE");
    }
    return result;
}

ShaderSpecialisation specialiseFor(const std::vector<shader::PackedLight>& lights, const Material& material) {
    ShaderSpecialisation key;
    // The same fp32 product as deriveSurfaceMaterial, so "exactly 0" means what the shader sees.
    const glm::vec3 diffuseColor = (1.0f - material.metallic) * material.baseColor;
    key.noDiffuse = diffuseColor == glm::vec3(0.0f);
    for (size_t i = 0; i < lights.size(); ++i) {
        const shader::PackedLight& light = lights[i];
        const std::string index = std::to_string(i);
        std::string call;
        if (light.type == shader::LIGHT_POINT) {
            call = "SHADE_POINT(" + index + (light.inverseRadius > 0.0f ? ", true, " : ", false, ") +
                   (hasKarisAttenuation(light) ? "true)" : "false)");
        } else if (light.type == shader::LIGHT_DIRECTIONAL) {
            call = "SHADE_DIRECTIONAL(" + index + ")";
        } else if (!key.noDiffuse) {
            call = "SHADE_HEMISPHERE(" + index + ")";
        }
        if (!call.empty()) {
            key.lights += (key.lights.empty() ? "" : " ") + call;
        }
    }
    return key;
}

ShaderSpecialisation brdfFloorFor(size_t count) {
    ShaderSpecialisation key;
    for (size_t i = 0; i < count; ++i) {
        key.lights += (i ? " BRDF_ONLY(" : "BRDF_ONLY(") + std::to_string(i) + ")";
    }
    return key;
}

}  // namespace patina
