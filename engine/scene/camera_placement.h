#pragma once
// Where the camera goes as the ecosystem puts it: model-viewer's orbit about a target and its
// framing of a model just loaded, and a glTF file's own cameras.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "model/model.h"
#include "scene/scene.h"

namespace patina {

// model-viewer's camera-orbit (modelviewer.dev, attribute camera-orbit): theta turns about +Y
// from +Z towards +X, phi is measured down from +Y, radius is the distance to the target;
// degrees and scene units.
struct Orbit {
    float thetaDegrees = 0.0f;
    float phiDegrees = 75.0f;
    float radius = 1.0f;
};

// The eye's offset from the target: r (sin phi sin theta, cos phi, sin phi cos theta).
glm::vec3 orbitOffset(const Orbit& orbit);
// The camera at target + orbitOffset(orbit), looking at `target` with +Y up (as model-viewer's
// camera-target and camera-orbit set it); the field of view stays.
void placeOnOrbit(Camera& camera, glm::vec3 target, const Orbit& orbit);

// The distance at which a sphere of `radius` just fills a vertical field of view of
// `fovYDegrees`: radius / sin(fov / 2) (model-viewer's idealCameraDistance).
float framingDistance(float radius, float fovYDegrees);

// model-viewer's default view of a model it loads (its camera-orbit default "0deg 75deg 105%"
// and camera-target "auto"): looking at the centre of `bounds` (the bounding box's centre, the
// sphere about it holding every vertex) from theta 0 and phi 75 degrees, so from the front (+Z)
// and 15 degrees above, at 105% of the framing distance for the camera's field of view. Never
// from where the camera was.
void frameAsModelViewer(Camera& camera, const BoundingSphere& bounds);

// A file's perspective camera as Patina's `camera`: at its position, looking along its forward,
// the target (what the camera orbits) on that line at the depth of the model's centre (`bounds`;
// a tenth of its radius ahead at least), the field of view its yfov within the scene file's 1 to
// 179 degrees. Patina's camera keeps +Y up: the returned angle (degrees, about the view) is how
// far the file's camera is rolled from level, which is not shown.
float placeModelCamera(Camera& camera, const ModelCamera& file, const BoundingSphere& bounds);

// The camera `nameOrIndex` names: the first of `cameras` of that name, else (all digits) the
// first placed by the file's camera of that index. std::invalid_argument, the message naming
// the cameras there are, for one that is not there, or saying that an orthographic one is not
// drawn.
const ModelCamera& findModelCamera(const std::vector<ModelCamera>& cameras, const std::string& nameOrIndex);

// "0 \"Front\" (perspective), 1 \"Plan\" (orthographic)", or "none": for messages.
std::string modelCameraList(const std::vector<ModelCamera>& cameras);

}  // namespace patina
