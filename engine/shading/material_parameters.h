#pragma once
#include <cmath>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

#include "shading/brdf_model_id.h"

namespace patina {

// Karis 2013's material as the BRDF reads it: base colour (linear RGB) and three scalars, each
// in [0, 1], a clear coat's two, and the model that shades them. scene/material.h adds what a file keeps beside it.
struct MaterialParameters {
    glm::vec3 baseColor{0.8f, 0.25f, 0.15f};
    float roughness = 0.4f;
    float specular = 0.5f;
    float metallic = 0.0f;
    BrdfModelId model = BrdfModelId::Epic;   // how it is shaded (shading/brdf_models.h)
    // KHR_materials_clearcoat's factors (docs/SHADING.md S5): the coat's weight and its
    // perceptual roughness, each in [0, 1]. A coat of 0 is none: nothing of it is compiled
    // (PATINA_CLEARCOAT), and the material shades as without the extension.
    float clearcoat = 0.0f;
    float clearcoatRoughness = 0.0f;
    // KHR_materials_sheen's factors (docs/SHADING.md S6): the sheen's colour (linear RGB, each in
    // [0, 1]) and its perceptual roughness. A colour of 0 is none: nothing of it is compiled
    // (PATINA_SHEEN), and the material shades as without the extension.
    glm::vec3 sheenColor{0.0f};
    float sheenRoughness = 0.0f;
    // KHR_materials_transmission's factor (docs/SHADING.md S7): the fraction of the dielectric's
    // diffuse that passes through the (thin-walled) surface instead, in [0, 1]. 0 is none:
    // nothing of it is compiled (PATINA_TRANSMISSION), and the material shades as without it.
    float transmission = 0.0f;
    // KHR_materials_volume's (docs/SHADING.md S7), read only where there is a transmission: the
    // thickness in the mesh's units (scaled by the node's scale), and the Beer-Lambert
    // attenuation colour (linear RGB, each in [0, 1]) reached at attenuationDistance (0: the
    // extension's infinite distance, no attenuation).
    float thickness = 0.0f;
    glm::vec3 attenuationColor{1.0f};
    float attenuationDistance = 0.0f;
    // KHR_materials_anisotropy's factors (docs/SHADING.md S8): the strength in [0, 1] that
    // stretches the specular lobe along a direction in the surface, and that direction's
    // rotation counter-clockwise from the mesh's tangent, in radians. A strength of 0 is none:
    // nothing of it is compiled (PATINA_ANISOTROPY), and the material shades as without it.
    float anisotropyStrength = 0.0f;
    float anisotropyRotation = 0.0f;
    // KHR_materials_specular and _ior (docs/SHADING.md S9): the dielectric's F0 is
    // min(0.08 specular specularTint, 1), its Fresnel weighted by specularWeight (glTF's
    // specularFactor, in [0, 1]: F0 and F90 both scaled). The tint's channels are in [0, 12.5]
    // (F0 = 1 at specular 1): its largest 1 up to F0 0.08, above it what an ior beyond 1.79
    // needs. A tint of 1 and a weight of 1 are none: nothing of them is compiled
    // (PATINA_SPECULAR), and the material shades as without the extensions.
    glm::vec3 specularTint{1.0f};
    float specularWeight = 1.0f;
    // KHR_materials_iridescence's factors (docs/SHADING.md S10): the thin film's strength in
    // [0, 1], its ior, and its thickness in nm between the minimum and maximum (the maximum
    // without a thickness map). A strength of 0 (or a thickness of 0) is none: nothing of it is
    // compiled (PATINA_IRIDESCENCE), and the material shades as without the extension.
    float iridescence = 0.0f;
    float iridescenceIor = 1.3f;
    float iridescenceThicknessMinimum = 100.0f;
    float iridescenceThicknessMaximum = 400.0f;
    bool operator==(const MaterialParameters&) const = default;
};

// KHR_materials_volume's thickness is in the mesh's own units: a draw's transform scales it by
// this, the cube root of |det| of its linear part (a uniform scale exactly; the geometric mean
// of a non-uniform one, where the extension would scale along the ray).
inline float thicknessScaleOf(const glm::mat4& transform) {
    return std::cbrt(std::abs(glm::determinant(glm::mat3(transform))));
}

}  // namespace patina
