#pragma once
// The ground truth's visibility of a light: shadow rays through the scene's triangles
// (geometry/ray_caster.h, which the product's ambient occlusion casts through too).
#include <glm/vec3.hpp>

#include "geometry/ray_caster.h"
#include "shading/shading.h"

namespace patina {

// Whether a point or directional light reaches P: one shadow ray to the point light's position,
// or along the directional light's direction to infinity; any other light is not shadowed here
// (hemisphere lights have no direction; sphere and tube lights are sampled, area_lights.h).
bool lightReaches(const RayCaster* occluders, const shader::PackedLight& light, glm::vec3 P, glm::vec3 N);

}  // namespace patina
