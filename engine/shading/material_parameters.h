#pragma once
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
    bool operator==(const MaterialParameters&) const = default;
};

}  // namespace patina
