#pragma once
#include <compare>

#include <glm/mat4x4.hpp>

#include "geometry/mesh.h"
#include "scene/scene.h"

namespace patina {

// The up vector of a view along the unit `forward`: +Y, or -Z looking straight up or down (where
// +Y cannot be one).
glm::vec3 viewUp(glm::vec3 forward);

// Where the camera looks, as GL's clip space: perspective of camera.fovYDegrees at `aspect`,
// near and far planes scaled to the camera's distance from its target.
glm::mat4 viewProjection(const Camera& camera, float aspect);

// Pixels [x0, x1) x [y0, y1) of a w x h image, GL's bottom-up rows.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
    auto operator<=>(const PixelRect&) const = default;
};
// Every pixel that anything inside `box` can cover, seen through `transform`: the projected
// corners' bounds, a pixel wider on each side; the whole image when a corner is not in front of
// the eye (the projection of the box is then unbounded); empty for an empty box.
PixelRect screenBounds(const glm::mat4& transform, const BoundingBox& box, int width, int height);

// Whether every point of `box` lies beyond the near plane of `transform` (a perspective
// view-projection): then the eye is outside it and the near plane cuts nothing inside open.
bool beyondNearPlane(const glm::mat4& transform, const BoundingBox& box);

}  // namespace patina
