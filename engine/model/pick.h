#pragma once
// Which part of a model is under the pointer: the draw item a ray from the eye meets first.
#include <limits>

#include <glm/vec3.hpp>

#include "model/model.h"

namespace patina {

struct DrawHit {
    int draw = -1;   // index in Model::draws; -1: the ray meets none
    float distance = std::numeric_limits<float>::infinity();   // along the ray, in units of `direction`
};

// The first draw item of `model` that the ray origin + t direction (t > 0) meets, either face of
// any triangle (Moller and Trumbore 1997, "Fast, minimum storage ray/triangle intersection",
// in each item's own space: the ray goes through the inverse of its transform, which keeps t).
DrawHit firstDrawHit(const Model& model, const glm::vec3& origin, const glm::vec3& direction);

}  // namespace patina
