#include "reference/visibility.h"

#include <limits>

#include <glm/geometric.hpp>

namespace patina {

bool lightReaches(const RayCaster* occluders, const shader::PackedLight& light, glm::vec3 P, glm::vec3 N) {
    if (!occluders) {
        return true;
    }
    if (light.type == shader::LIGHT_DIRECTIONAL) {
        return unoccluded(occluders, P, N, light.directionToLight, std::numeric_limits<float>::infinity());
    }
    if (light.type != shader::LIGHT_POINT) {
        return true;
    }
    const glm::vec3 toLight = light.position - P;
    const float distance = glm::length(toLight);
    return !(distance > 0.0f) || unoccluded(occluders, P, N, toLight / distance, distance);
}

}  // namespace patina
