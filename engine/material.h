#pragma once
#include <string>

#include <glm/vec3.hpp>

#include "brdf_model_id.h"
#include "json_value.h"

namespace patina {

// Karis 2013's material: base colour (linear RGB) and three scalars, each in [0, 1].
struct Material {
    std::string name = "default";
    glm::vec3 baseColor{0.8f, 0.25f, 0.15f};
    float roughness = 0.4f;
    float specular = 0.5f;
    float metallic = 0.0f;
    BrdfModelId model = BrdfModelId::Epic;   // how it is shaded (engine/brdf_models.h)
    std::string notes{};            // where the numbers come from; shading ignores it
    // Keys of the file Patina does not know, kept so that saving writes them back.
    Json extras = Json::object();

    bool operator==(const Material&) const = default;
};

}  // namespace patina
