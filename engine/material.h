#pragma once
#include <string>

#include <glm/vec3.hpp>

#include "brdf_model_id.h"

namespace patina {

// Karis 2013's material: base colour (linear RGB) and three scalars, each in [0, 1].
struct Material {
    std::string name = "default";
    glm::vec3 baseColor{0.8f, 0.25f, 0.15f};
    float roughness = 0.4f;
    float specular = 0.5f;
    float metallic = 0.0f;
    BrdfModelId model = BrdfModelId::Epic;   // how it is shaded (engine/brdf_models.h)

    bool operator==(const Material&) const = default;
};

}  // namespace patina
