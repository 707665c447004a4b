#include "scene/camera_placement.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/glm.hpp>

#include "scene/view.h"

namespace patina {

namespace {
// model-viewer's DEFAULT_CAMERA_ORBIT, "0deg 75deg 105%" (controls.ts).
constexpr float kDefaultTheta = 0.0f, kDefaultPhi = 75.0f, kDefaultRadiusShare = 1.05f;

// `v` without its part along the unit `axis`, normalised (zero when nothing is left).
glm::vec3 across(glm::vec3 v, glm::vec3 axis) {
    const glm::vec3 rest = v - axis * glm::dot(v, axis);
    const float length = glm::length(rest);
    return length > 1e-6f ? rest / length : glm::vec3(0.0f);
}

bool allDigits(const std::string& text) {
    return !text.empty() && text.size() <= 9 &&
           std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}
}  // namespace

glm::vec3 orbitOffset(const Orbit& orbit) {
    const float theta = glm::radians(orbit.thetaDegrees), phi = glm::radians(orbit.phiDegrees);
    return orbit.radius * glm::vec3(std::sin(phi) * std::sin(theta), std::cos(phi), std::sin(phi) * std::cos(theta));
}

void placeOnOrbit(Camera& camera, glm::vec3 target, const Orbit& orbit) {
    camera.target = target;
    camera.position = target + orbitOffset(orbit);
}

float framingDistance(float radius, float fovYDegrees) {
    return radius / std::sin(glm::radians(fovYDegrees) * 0.5f);
}

void frameAsModelViewer(Camera& camera, const BoundingSphere& bounds) {
    const float radius = kDefaultRadiusShare * framingDistance(bounds.radius, camera.fovYDegrees);
    placeOnOrbit(camera, bounds.center, {kDefaultTheta, kDefaultPhi, radius});
}

float placeModelCamera(Camera& camera, const ModelCamera& file, const BoundingSphere& bounds) {
    const glm::vec3 forward = glm::normalize(file.forward);
    const float depth = std::max(glm::dot(bounds.center - file.position, forward), 0.1f * bounds.radius);
    camera.position = file.position;
    camera.target = file.position + depth * forward;
    camera.fovYDegrees = std::clamp(glm::degrees(file.yfov), 1.0f, 179.0f);
    // The up Patina's view takes for this direction, against the file camera's up.
    const glm::vec3 level = across(viewUp(forward), forward), up = across(file.up, forward);
    if (up == glm::vec3(0.0f)) {
        return 0.0f;
    }
    return glm::degrees(std::atan2(glm::dot(glm::cross(level, up), forward), glm::dot(level, up)));
}

std::string modelCameraList(const std::vector<ModelCamera>& cameras) {
    std::string list;
    for (const ModelCamera& camera : cameras) {
        list += (list.empty() ? "" : ", ") + std::to_string(camera.index) + " \"" + camera.name + "\" (" +
                (camera.perspective ? "perspective" : "orthographic") + ")";
    }
    return list.empty() ? "none" : list;
}

const ModelCamera& findModelCamera(const std::vector<ModelCamera>& cameras, const std::string& nameOrIndex) {
    auto found = std::find_if(cameras.begin(), cameras.end(),
                              [&](const ModelCamera& camera) { return camera.name == nameOrIndex; });
    if (found == cameras.end() && allDigits(nameOrIndex)) {
        const int index = std::stoi(nameOrIndex);
        found = std::find_if(cameras.begin(), cameras.end(),
                             [&](const ModelCamera& camera) { return camera.index == index; });
    }
    if (found == cameras.end()) {
        throw std::invalid_argument("the model has no camera \"" + nameOrIndex +
                                    "\" (its cameras, by index and name: " + modelCameraList(cameras) + ")");
    }
    if (!found->perspective) {
        throw std::invalid_argument("camera " + std::to_string(found->index) + " \"" + found->name +
                                    "\" is orthographic: Patina draws perspective cameras only");
    }
    return *found;
}

}  // namespace patina
