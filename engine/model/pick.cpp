#include "model/pick.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace patina {

namespace {
// t where the ray meets triangle (a, b, c), or infinity: Moller and Trumbore 1997, section 2
// (barycentric u, v by Cramer's rule), both faces.
float rayTriangle(const glm::vec3& origin, const glm::vec3& direction, const glm::vec3& a, const glm::vec3& b,
                  const glm::vec3& c) {
    constexpr float kMiss = std::numeric_limits<float>::infinity();
    const glm::vec3 edge1 = b - a, edge2 = c - a;
    const glm::vec3 p = glm::cross(direction, edge2);
    const float determinant = glm::dot(edge1, p);
    if (!(std::abs(determinant) > 0.0f)) {
        return kMiss;   // parallel to the plane, or a triangle of no area
    }
    const float inverse = 1.0f / determinant;
    const glm::vec3 s = origin - a;
    const float u = glm::dot(s, p) * inverse;
    if (!(u >= 0.0f && u <= 1.0f)) {
        return kMiss;
    }
    const glm::vec3 q = glm::cross(s, edge1);
    const float v = glm::dot(direction, q) * inverse;
    if (!(v >= 0.0f && u + v <= 1.0f)) {
        return kMiss;
    }
    const float t = glm::dot(edge2, q) * inverse;
    return t > 0.0f ? t : kMiss;
}
}  // namespace

DrawHit firstDrawHit(const Model& model, const glm::vec3& origin, const glm::vec3& direction) {
    DrawHit hit;
    for (size_t d = 0; d < model.draws.size(); ++d) {
        const DrawItem& item = model.draws[d];
        if (item.primitive < 0 || size_t(item.primitive) >= model.primitives.size()) {
            continue;
        }
        const glm::mat4 inverse = glm::inverse(item.transform);
        const glm::vec3 localOrigin(inverse * glm::vec4(origin, 1.0f));
        const glm::vec3 localDirection(inverse * glm::vec4(direction, 0.0f));
        const Mesh& mesh = model.primitives[size_t(item.primitive)];
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const float distance =
                rayTriangle(localOrigin, localDirection, mesh.positions[mesh.indices[t]],
                            mesh.positions[mesh.indices[t + 1]], mesh.positions[mesh.indices[t + 2]]);
            if (distance < hit.distance) {
                hit = {int(d), distance};
            }
        }
    }
    return hit;
}

}  // namespace patina
