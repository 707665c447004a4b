#include "gl/shader_specialisation.h"

#include <cmath>


#include "scene/light_packing.h"

namespace patina {

namespace {
void append(std::string& list, const std::string& entry) {
    if (!entry.empty()) {
        list += (list.empty() ? "" : " ") + entry;
    }
}

// `call` weighed by the light's shadow map (shade.frag's SHADOWED), given the direction towards
// the light from `light`, the fragment's expression for it, as its map looks.
std::string shadowed(const std::string& call, const shader::PackedLight& light, const std::string& source) {
    std::string towards;
    if (light.type == shader::LIGHT_DIRECTIONAL) {
        towards = source + ".directionToLight";
    } else if (light.type == shader::LIGHT_TUBE) {
        towards = "safeNormalize(0.5f * (" + source + ".position + " + source + ".tubeEnd) - vPosition)";
    } else {
        towards = "safeNormalize(" + source + ".position - vPosition)";
    }
    // A cube map's six layers (a negative shadowMap): the face the light sees the fragment in.
    const std::string first = std::to_string(int(std::abs(light.shadowMap)) - 1);
    const std::string layer = light.shadowMap < 0.0f ? first + " + cubeFace(-(" + towards + "))" : first;
    return "SHADOWED(" + towards + ", " + layer + ", " + call + ")";
}
}  // namespace

LightSource sourceOf(size_t i, size_t flatSlots, const char* flatWrite) {
    const std::string index = std::to_string(i);
    if (i < flatSlots) {
        return {"FLAT(" + index + ")", std::string(flatWrite) + "(" + index + ")"};
    }
    return {"BLOCK(" + index + ")", ""};
}

void addLight(ShaderSpecialisation& key, size_t i, const std::string& call, const LightSource& source) {
    append(key.lights, call);
    if (!source.vertex.empty()) {
        append(key.flatLightRows, source.vertex);
        key.flatLightCount = int(i) + 1;
    }
}

std::vector<std::string> ShaderSpecialisation::defines() const {
    std::vector<std::string> result{"PATINA_SINGLE_PASS", "PATINA_SPECIALISED", "PATINA_LIGHTS " + lights};
    if (flatLightCount > 0) {
        result.push_back("PATINA_FLAT_LIGHT_COUNT " + std::to_string(flatLightCount));
        result.push_back("PATINA_FLAT_LIGHTS " + flatLightRows);
    }
    if (noDiffuse) {
        result.push_back("PATINA_NO_DIFFUSE");
    }
    if (environment) {
        result.push_back("PATINA_ENVIRONMENT");
    }
    if (mapSet >= 0) {
        result.push_back("PATINA_MAP_SET " + std::to_string(mapSet));
    }
    if (shadows) {
        result.push_back("PATINA_SHADOWS");
    }
    return result;
}

bool hasNoDiffuse(const MaterialParameters& material) {
    const glm::vec3 diffuseColor = (1.0f - material.metallic) * material.baseColor;
    return diffuseColor == glm::vec3(0.0f);
}

ShaderSpecialisation specialiseFor(const std::vector<shader::PackedLight>& lights, bool noDiffuse, size_t flatSlots) {
    ShaderSpecialisation key;
    key.noDiffuse = noDiffuse;
    for (size_t i = 0; i < lights.size(); ++i) {
        const shader::PackedLight& light = lights[i];
        std::string call;
        LightSource source;
        // Point, sphere and tube lights share the window and coefficient switches.
        const auto falloff = [&](const char* shade, const char* flatWrite) {
            source = sourceOf(i, flatSlots, flatWrite);
            call = std::string(shade) + "(" + source.fragment + (light.inverseRange > 0.0f ? ", true, " : ", false, ") +
                   (hasKarisAttenuation(light) ? "true)" : "false)");
        };
        if (light.type == shader::LIGHT_POINT) {
            falloff("SHADE_POINT", "FLAT_POINT");
        } else if (light.type == shader::LIGHT_SPHERE) {
            falloff("SHADE_SPHERE", "FLAT_SPHERE");
        } else if (light.type == shader::LIGHT_TUBE) {
            falloff("SHADE_TUBE", "FLAT_TUBE");
        } else if (light.type == shader::LIGHT_DIRECTIONAL) {
            source = sourceOf(i, flatSlots, "FLAT_DIRECTIONAL");
            call = "SHADE_DIRECTIONAL(" + source.fragment + ")";
        } else if (!key.noDiffuse) {
            source = sourceOf(i, flatSlots, "FLAT_HEMISPHERE");
            call = "SHADE_HEMISPHERE(" + source.fragment + ")";
        }
        if (!call.empty() && light.shadowMap != 0.0f) {
            call = shadowed(call, light, source.fragment);
            key.shadows = true;
        }
        if (!call.empty()) {
            addLight(key, i, call, source);
        }
    }
    return key;
}

bool flatLightsPay(double pixels, double trianglesDrawn) {
    return pixels >= kFlatLightPixelsPerTriangle * trianglesDrawn;
}

}  // namespace patina
