#include "scene/camera_control.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/camera_placement.h"
#include "scene/view.h"

namespace patina {

namespace {
constexpr float kMaxElevation = glm::radians(89.0f);

struct ViewBasis {
    glm::vec3 forward, right, up;
};

ViewBasis viewBasis(const Camera& camera) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    glm::vec3 right = glm::cross(forward, glm::vec3(0, 1, 0));
    if (glm::dot(right, right) < 1e-8f) {
        right = glm::vec3(1, 0, 0);   // looking straight along y
    }
    right = glm::normalize(right);
    return {forward, right, glm::cross(right, forward)};
}
}  // namespace

void orbitCamera(Camera& camera, float deltaAzimuth, float deltaElevation) {
    const glm::vec3 offset = camera.position - camera.target;
    const float distance = glm::length(offset);
    float azimuth = std::atan2(offset.x, offset.z) + deltaAzimuth;
    float elevation = std::asin(std::clamp(offset.y / distance, -1.0f, 1.0f)) + deltaElevation;
    elevation = std::clamp(elevation, -kMaxElevation, kMaxElevation);
    camera.position = camera.target + distance * glm::vec3(std::cos(elevation) * std::sin(azimuth),
                                                           std::sin(elevation),
                                                           std::cos(elevation) * std::cos(azimuth));
}

Camera turntableCamera(const Camera& start, float degrees) {
    const float turned = std::fmod(degrees, 360.0f);
    if (turned == 0.0f) {
        return start;   // target + (position - target) need not be position to the last bit
    }
    const float radians = glm::radians(turned);
    const float c = std::cos(radians), s = std::sin(radians);
    const glm::vec3 offset = start.position - start.target;
    Camera camera = start;
    // A rotation about +y by the angle: x' = x cos + z sin, z' = z cos - x sin.
    camera.position = start.target + glm::vec3(offset.x * c + offset.z * s, offset.y, offset.z * c - offset.x * s);
    return camera;
}

void panCamera(Camera& camera, float rightFraction, float upFraction) {
    const ViewBasis basis = viewBasis(camera);
    const float distance = glm::length(camera.target - camera.position);
    const float viewHeight = 2.0f * distance * std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    const glm::vec3 shift = viewHeight * (rightFraction * basis.right + upFraction * basis.up);
    camera.position += shift;
    camera.target += shift;
}

void dollyCamera(Camera& camera, float factor) {
    const glm::vec3 offset = camera.position - camera.target;
    const float distance = std::clamp(glm::length(offset) * factor, 0.05f, 1000.0f);
    camera.position = camera.target + distance * glm::normalize(offset);
}

void frameCamera(Camera& camera, glm::vec3 center, float radius) {
    const glm::vec3 back = glm::normalize(camera.position - camera.target);
    const float distance = framingDistance(radius, camera.fovYDegrees) * 1.1f;
    camera.target = center;
    camera.position = center + distance * back;
}

std::optional<glm::vec2> projectToViewport(const Camera& camera, glm::vec2 size, glm::vec3 point) {
    const glm::vec4 clip = viewProjection(camera, size.x / size.y) * glm::vec4(point, 1.0f);
    if (clip.w <= 1e-6f) {
        return std::nullopt;
    }
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return glm::vec2((ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y);
}

glm::vec3 unprojectAtDepthOf(const Camera& camera, glm::vec2 size, glm::vec2 pixel, glm::vec3 depthOf) {
    const ViewBasis basis = viewBasis(camera);
    const float depth = glm::dot(depthOf - camera.position, basis.forward);
    const float halfHeight = depth * std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    const float halfWidth = halfHeight * size.x / size.y;
    const float x = (pixel.x / size.x) * 2.0f - 1.0f;
    const float y = 1.0f - (pixel.y / size.y) * 2.0f;
    return camera.position + depth * basis.forward + x * halfWidth * basis.right + y * halfHeight * basis.up;
}

}  // namespace patina
