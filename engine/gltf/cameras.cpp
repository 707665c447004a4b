#include "gltf/cameras.h"

#include <cmath>

#include <glm/glm.hpp>

namespace patina::gltf {

namespace {
// A unit vector along `v`, or nothing when it has no length a float can normalise.
bool unit(glm::dvec3 v, glm::vec3& out) {
    const double length = glm::length(v);
    if (!(length > 1e-12) || !std::isfinite(length)) {
        return false;
    }
    out = glm::vec3(v / length);
    return true;
}

std::string cameraName(const tinygltf::Model& document, const CameraInstance& instance) {
    const std::string& own = document.cameras[size_t(instance.camera)].name;
    if (!own.empty()) {
        return own;
    }
    const std::string& node = document.nodes[size_t(instance.node)].name;
    return node.empty() ? "camera " + std::to_string(instance.camera) : node;
}
}  // namespace

std::vector<ModelCamera> modelCameras(const tinygltf::Model& document, const std::vector<CameraInstance>& instances,
                                      std::vector<std::string>& notes) {
    std::vector<ModelCamera> cameras;
    for (const CameraInstance& instance : instances) {
        const std::string where = "/nodes/" + std::to_string(instance.node);
        if (instance.camera < 0 || size_t(instance.camera) >= document.cameras.size()) {
            notes.push_back(where + "/camera: camera " + std::to_string(instance.camera) +
                            " does not exist, left out");
            continue;
        }
        const tinygltf::Camera& camera = document.cameras[size_t(instance.camera)];
        ModelCamera placed;
        placed.name = cameraName(document, instance);
        placed.node = nodeName(document, instance.node);
        placed.index = instance.camera;
        placed.perspective = camera.type != "orthographic";
        placed.yfov = float(camera.perspective.yfov);
        // The node's axes through its world transform, each normalised: its scale drops out.
        const glm::dmat4& world = instance.world;
        placed.position = glm::vec3(world[3]);
        const bool placeable = unit(-glm::dvec3(world[2]), placed.forward) && unit(glm::dvec3(world[1]), placed.up);
        if (!placeable) {
            notes.push_back("camera \"" + placed.name + "\" (" + where +
                            "): its node's transform has no direction (a zero scale), left out");
            continue;
        }
        if (placed.perspective && !(camera.perspective.yfov > 0.0 && std::isfinite(placed.yfov))) {
            notes.push_back("camera \"" + placed.name + "\": its yfov is not above 0, left out");
            continue;
        }
        cameras.push_back(std::move(placed));
    }
    return cameras;
}

}  // namespace patina::gltf
