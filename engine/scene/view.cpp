#include "scene/view.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace patina {

namespace {
// Corner 0-7 of `box`: bit 0 picks x, bit 1 y, bit 2 z.
glm::vec3 boxCorner(const BoundingBox& box, int corner) {
    return {(corner & 1) ? box.high.x : box.low.x, (corner & 2) ? box.high.y : box.low.y,
            (corner & 4) ? box.high.z : box.low.z};
}
}  // namespace

glm::vec3 viewUp(glm::vec3 forward) {
    return std::abs(forward.y) > 0.999f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
}

glm::mat4 viewProjection(const Camera& camera, float aspect) {
    const glm::vec3 forward = camera.target - camera.position;
    const float distance = glm::length(forward);
    const glm::vec3 up = viewUp(forward / distance);
    const float nearPlane = std::max(1e-3f, distance * 0.01f);
    const float farPlane = distance * 10.0f + 10.0f;
    return glm::perspective(glm::radians(camera.fovYDegrees), aspect, nearPlane, farPlane) *
           glm::lookAt(camera.position, camera.target, up);
}

bool beyondNearPlane(const glm::mat4& transform, const BoundingBox& box) {
    if (box.empty()) {
        return false;
    }
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec4 clip = transform * glm::vec4(boxCorner(box, corner), 1.0f);
        // GL's near plane is z = -w; a margin for the rounding of the corners' transform.
        if (!(clip.w > 0.0f && clip.z > -clip.w * (1.0f - 1e-4f))) {
            return false;
        }
    }
    return true;
}

PixelRect screenBounds(const glm::mat4& transform, const BoundingBox& box, int width, int height) {
    if (box.empty()) {
        return {};
    }
    const PixelRect whole{0, 0, width, height};
    glm::vec2 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec4 clip = transform * glm::vec4(boxCorner(box, corner), 1.0f);
        // In front of the eye the projection keeps the box's image inside its corners' hull;
        // at or behind the eye plane it does not.
        if (!(clip.w > 1e-6f)) {
            return whole;
        }
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        low = glm::min(low, ndc);
        high = glm::max(high, ndc);
    }
    // NDC to pixels, out to whole pixels and one more for rounding; clamped so that far-off
    // corners cannot overflow an int.
    auto toPixel = [](float ndc, int size, float direction) {
        const float pixel = (std::clamp(ndc, -2.0f, 2.0f) * 0.5f + 0.5f) * float(size) + direction;
        return direction < 0 ? int(std::floor(pixel)) : int(std::ceil(pixel));
    };
    PixelRect rect{toPixel(low.x, width, -1.0f), toPixel(low.y, height, -1.0f), toPixel(high.x, width, 1.0f),
                   toPixel(high.y, height, 1.0f)};
    rect.x0 = std::clamp(rect.x0, 0, width), rect.x1 = std::clamp(rect.x1, 0, width);
    rect.y0 = std::clamp(rect.y0, 0, height), rect.y1 = std::clamp(rect.y1, 0, height);
    return rect;
}

}  // namespace patina
