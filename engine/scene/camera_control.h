#pragma once
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace patina {

// Turntable camera moves, all about camera.target with +y up. Angles in radians, distances in
// scene units; the elevation stays inside (-89, 89) degrees so "up" never flips.
void orbitCamera(Camera& camera, float deltaAzimuth, float deltaElevation);
// The turntable's camera: `start` turned `degrees` about the vertical (+y) axis through its
// target, the eye moving from +z towards +x as model-viewer's camera-orbit theta grows; the
// height, distance and field of view stay. The angle is taken modulo 360 first, so a whole turn
// (360, 720, ...) gives `start` back exactly: the frame after a turntable's last is its first.
Camera turntableCamera(const Camera& start, float degrees);
// Moves position and target together, in the view plane, by a fraction of the view height.
void panCamera(Camera& camera, float rightFraction, float upFraction);
// Multiplies the distance to the target by `factor` (clamped to [0.05, 1000]).
void dollyCamera(Camera& camera, float factor);
// Keeps the view direction and aims at a sphere of `radius` around `center`, filling the view
// (at 110% of camera_placement.h's framingDistance).
void frameCamera(Camera& camera, glm::vec3 center, float radius);

// Window coordinates (pixels, y down) of a world point in a viewport of `size` pixels, or
// nothing when it lies behind the camera.
std::optional<glm::vec2> projectToViewport(const Camera& camera, glm::vec2 size, glm::vec3 point);
// The world point at `depthOf`'s distance along the view direction under a viewport pixel.
glm::vec3 unprojectAtDepthOf(const Camera& camera, glm::vec2 size, glm::vec2 pixel, glm::vec3 depthOf);

}  // namespace patina
