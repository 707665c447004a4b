#pragma once
// The CPU twin of shade.frag's inspectedChannel (PATINA_CHANNEL): a surface point's channel
// inputs (shaders/shared/channels.glsl) gathered by the same shared functions in the same order,
// for the inspector's CPU images, its pixel read-out and the tests that hold the GPU to them.
#include <cmath>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/material_parameters.h"
#include "shading/shading.h"

namespace patina {

enum class BrdfModelId;

// What shade.frag reads at the fragment: the material after its maps, the maps' occlusion and
// emission, the UVs and interpolated tangent (w = 0: none), the unit geometry normal and the
// shading normal N after the normal map, the unit V towards the camera and the position P.
struct ChannelPoint {
    glm::vec3 baseColor{0.0f};
    float alpha = 1.0f, roughness = 0.0f, specular = 0.5f, metallic = 0.0f, occlusion = 1.0f;
    // KHR_materials_specular's tint of F0 and weight of its Fresnel (shader::withSpecular).
    glm::vec3 specularTint{1.0f};
    float specularWeight = 1.0f;
    glm::vec3 emission{0.0f};
    glm::vec2 uv0{0.0f}, uv1{0.0f};
    glm::vec4 tangent{0.0f};
    glm::vec3 geometryNormal{0.0f}, N{0.0f}, V{0.0f}, P{0.0f};
    // KHR_materials_clearcoat's and KHR_materials_sheen's factors after their maps (0: none). The
    // coat lies on the geometry normal, as shade.frag lays it where the coat has no normal map of
    // its own (that map is the GPU's alone), the sheen on N.
    float clearcoat = 0.0f, clearcoatRoughness = 0.0f;
    glm::vec3 sheenColor{0.0f};
    float sheenRoughness = 0.0f;
    // KHR_materials_transmission's factor after its map (0: none) and KHR_materials_volume's
    // attenuation T over the draw's thickness (transmission.glsl's volumeAttenuation).
    float transmission = 0.0f;
    glm::vec3 transmissionAttenuation{1.0f};
    // KHR_materials_iridescence's strength after its map (0: none), film ior and thickness in nm
    // after its map.
    float iridescence = 0.0f, iridescenceIor = 1.3f, iridescenceThickness = 0.0f;
    // KHR_materials_anisotropy's strength (0: none) and rotation after its map, turned from
    // `anisotropyTangent` (mesh.vert's, as the truth reads it: PixelSurfaces::tangents; w = 0: the
    // fallback's).
    float anisotropyStrength = 0.0f, anisotropyRotation = 0.0f;
    glm::vec4 anisotropyTangent{0.0f};
};

// A point of `material`'s factors (its maps already applied, if any), the rest at ChannelPoint's
// defaults: the caller places it (normals, V, P) and adds what its maps gave.
ChannelPoint channelPointOf(const MaterialParameters& material);

// The point's layers as shade.frag derives them for a part that has them (PATINA_CLEARCOAT,
// PATINA_SHEEN, PATINA_TRANSMISSION, PATINA_ANISOTROPY); a factor of 0 is none, which shades
// the same as the layer at 0.
inline shader::ChannelLayers channelPointLayers(const ChannelPoint& p) {
    shader::ChannelLayers layers = shader::noChannelLayers();
    if (p.clearcoat > 0.0f) {
        layers.coated = true;
        layers.coat = shader::deriveClearcoat(p.clearcoat, p.clearcoatRoughness, p.geometryNormal, p.V);
    }
    if (p.sheenColor != glm::vec3(0.0f)) {
        layers.sheened = true;
        layers.sheen = shader::deriveSheen(p.sheenColor, p.sheenRoughness, p.N, p.V);
    }
    if (p.transmission > 0.0f) {
        layers.transmits = true;
        layers.transmissionFactor = p.transmission;
        // The material shade.frag derives it from: its specular and its film (what the film
        // reflects does not pass).
        layers.transmission = shader::deriveTransmission(
            shader::withIridescence(
                shader::withSpecular(shader::deriveSurfaceMaterial(p.baseColor, p.roughness, p.specular, p.metallic),
                                     p.specularTint, p.specularWeight),
                p.iridescence, p.iridescenceIor, p.iridescenceThickness),
            p.transmission, p.transmissionAttenuation, p.N, p.V);
    }
    // As surfaceMaterialAt (cpu_shading.h) stretches the lobe: where the strength is above 0.
    if (p.anisotropyStrength > 0.0f) {
        layers.anisotropic = true;
        layers.anisotropy =
            glm::vec3(std::cos(p.anisotropyRotation), std::sin(p.anisotropyRotation), p.anisotropyStrength);
        layers.anisotropyTangent = p.anisotropyTangent;
    }
    layers.iridescence = p.iridescence;
    layers.iridescenceIor = p.iridescenceIor;
    layers.iridescenceThickness = p.iridescenceThickness;
    return layers;
}

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
