#pragma once
// The scene graph (glTF 2.0 section 3.5): which nodes the default scene shows, and where.
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

namespace patina::gltf {

struct MeshInstance {
    int node;
    int mesh;
    glm::dmat4 world;   // parent's world times the node's local transform
};

// A node that places a camera (section 3.10): `camera` is the node's index into `cameras`, not
// checked here.
struct CameraInstance {
    int node;
    int camera;
    glm::dmat4 world;
};

struct SceneInstances {
    std::vector<MeshInstance> meshes;
    std::vector<CameraInstance> cameras;
};

// Every node of the default scene (`scene`, else scene 0, else every root node) that shows a
// mesh or places a camera, depth first in the order of the lists. The whole hierarchy is
// checked first: children that exist, one parent at most, no cycle; and every world transform
// of the scene is finite also in single precision (what the renderer gets). Iterative: any
// depth is fine. Throws InputError naming the node.
SceneInstances sceneInstances(const tinygltf::Model& model, const std::string& source);

// The node's name, or "node N" when it has none: what messages and draw items call it.
std::string nodeName(const tinygltf::Model& model, int node);

}  // namespace patina::gltf
