#pragma once
#include <string>
#include <string_view>
#include <optional>

#include <glm/vec3.hpp>

#include "scene/json_value.h"
#include "environment/builtin_environments.h"

namespace patina {

enum class LightType { Point, Directional, Hemisphere, Environment, Sphere, Tube };

std::string_view lightTypeName(LightType type);
std::optional<LightType> lightTypeFromName(std::string_view name);
// Whether a light of `type` can cast shadows: it has a place or a direction (point, sphere, tube,
// directional); a hemisphere or an environment has neither.
bool castsShadows(LightType type);

// One light of any type; fields a type does not use keep their defaults and are ignored.
// c_light = color * intensity (docs/SHADING.md S1).
struct Light {
    LightType type = LightType::Point;
    std::string name = "light";
    bool enabled = true;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    // point, directional, sphere, tube: the model casts shadows of this light (a shadow map,
    // docs/LIGHTING.md "Shadows"); the scene file's "shadows", written only when true.
    bool shadows = false;
    // point; sphere: its centre
    glm::vec3 position{0.0f, 2.0f, 2.0f};
    // point, sphere, tube: the attenuation window: the light reaches this far (Karis 2013 eq. 9);
    // <= 0: no window.
    float range = 0.0f;
    glm::vec3 attenuation{1.0f, 0.0f, 1.0f};   // a_c, a_l, a_q
    // sphere, tube: the radius of the sphere, or of the capsule around the tube's segment
    // (Karis 2013, "Area lights"); 0 makes a sphere the point light at its centre.
    float sourceRadius = 0.1f;
    // tube: the segment's ends (equal ends: the sphere light of the same radius)
    glm::vec3 start{-0.5f, 2.0f, 2.0f};
    glm::vec3 end{0.5f, 2.0f, 2.0f};
    // directional: where the light travels
    glm::vec3 direction{0.0f, -1.0f, 0.0f};
    // hemisphere (colour acts as a tint on both)
    glm::vec3 sky{1.0f};
    glm::vec3 ground{0.0f};
    // environment (PreparedScene::environment holds it made ready): "builtin:NAME" or a file's
    // absolute path; turned about +Y, lighting and background alike. Radiance = image * intensity
    // (colour is not used).
    std::string source = builtinSource("studio");
    float rotationDegrees = 0.0f;
    // Keys of the file Patina does not know (another type's too), written back on save.
    Json extras = Json::object();

    bool operator==(const Light&) const = default;
};

}  // namespace patina
