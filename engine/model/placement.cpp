#include "model/placement.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace patina {

glm::mat3 normalTransform(const glm::mat4& transform) {
    // In double: the determinant and the cofactors grow as the cube and the square of the
    // transform's scale, and a scale of 1e-20 or 1e20 is finite in a float.
    const glm::dmat3 linear(transform);
    const glm::dmat3 cofactor(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                              glm::cross(linear[0], linear[1]));
    double largest = 0.0;
    for (int c = 0; c < 3; ++c) {
        largest = std::max({largest, std::abs(cofactor[c].x), std::abs(cofactor[c].y), std::abs(cofactor[c].z)});
    }
    const double scale = largest > 0.0 && std::isfinite(largest) ? 1.0 / largest : 1.0;
    return glm::mat3(cofactor * (glm::determinant(linear) < 0.0 ? -scale : scale));
}

bool mirrors(const glm::mat4& transform) {
    return glm::determinant(glm::dmat3(transform)) < 0.0;
}

}  // namespace patina
