#include "gltf/nodes.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "files/input_error.h"

namespace patina::gltf {

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw InputError(source + ": " + what);
}

std::string nodeAt(size_t index) { return "/nodes/" + std::to_string(index); }

// A node's optional array of `size` numbers: null when absent. (Finite: checkGltfJson refuses
// numbers a double cannot hold; products that overflow are caught on the world transforms.)
const double* numbers(const std::vector<double>& values, size_t size, const std::string& what,
                      const std::string& source) {
    if (values.empty()) {
        return nullptr;
    }
    if (values.size() != size) {
        fail(source, what + ": must have " + std::to_string(size) + " numbers, not " + std::to_string(values.size()));
    }
    return values.data();
}

// Section 3.5.3: `matrix`, else T * R * S with the rotation a unit quaternion (x, y, z, w).
glm::dmat4 localTransform(const tinygltf::Node& node, const std::string& where, const std::string& source) {
    if (const double* m = numbers(node.matrix, 16, where + "/matrix", source)) {
        return glm::make_mat4(m);   // column-major in glTF as in GLM
    }
    glm::dmat4 transform(1.0);
    if (const double* t = numbers(node.translation, 3, where + "/translation", source)) {
        transform = glm::translate(transform, glm::make_vec3(t));
    }
    if (const double* r = numbers(node.rotation, 4, where + "/rotation", source)) {
        const glm::dquat q(r[3], r[0], r[1], r[2]);   // glTF stores x, y, z, w
        const double length = glm::length(q);
        if (!(length > 0.0) || !std::isfinite(length)) {
            fail(source, where + "/rotation: not a unit quaternion");
        }
        transform *= glm::mat4_cast(q / length);   // normalised: exporters round
    }
    if (const double* s = numbers(node.scale, 3, where + "/scale", source)) {
        transform = glm::scale(transform, glm::make_vec3(s));
    }
    return transform;
}

// Section 3.5.2: the nodes form disjoint strict trees. Each node's parent (-1 for none), every
// child checked to exist and to have one parent only.
std::vector<int> parents(const tinygltf::Model& model, const std::string& source) {
    std::vector<int> parent(model.nodes.size(), -1);
    for (size_t n = 0; n < model.nodes.size(); ++n) {
        for (const int child : model.nodes[n].children) {
            if (child < 0 || size_t(child) >= model.nodes.size()) {
                fail(source, nodeAt(n) + "/children: node " + std::to_string(child) + " does not exist");
            }
            const int other = parent[size_t(child)];
            if (other == int(n)) {
                fail(source, nodeAt(size_t(child)) + ": listed twice in the children of node " + std::to_string(n));
            }
            if (other != -1) {
                fail(source, nodeAt(size_t(child)) + ": has two parents, nodes " + std::to_string(other) + " and " +
                                 std::to_string(n) + " (the node hierarchy must be a set of trees)");
            }
            parent[size_t(child)] = int(n);
        }
    }
    return parent;
}

// With one parent at most, following the parents from any node ends at a root or goes round.
void refuseCycles(const std::vector<int>& parent, const std::string& source) {
    enum State : uint8_t { Unseen, OnPath, Done };
    std::vector<State> state(parent.size(), Unseen);
    std::vector<int> path;
    for (size_t start = 0; start < parent.size(); ++start) {
        int n = int(start);
        for (; n != -1 && state[size_t(n)] == Unseen; n = parent[size_t(n)]) {
            state[size_t(n)] = OnPath;
            path.push_back(n);
        }
        if (n != -1 && state[size_t(n)] == OnPath) {
            fail(source, nodeAt(size_t(n)) + ": is its own ancestor (a cycle in the node hierarchy)");
        }
        for (const int visited : path) {
            state[size_t(visited)] = Done;
        }
        path.clear();
    }
}

// Section 3.5.1: the default scene's root nodes, else scene 0's, else every node without a parent.
std::vector<int> rootNodes(const tinygltf::Model& model, const std::vector<int>& parent, const std::string& source) {
    std::vector<int> roots;
    if (model.scenes.empty()) {
        for (size_t n = 0; n < parent.size(); ++n) {
            if (parent[n] == -1) {
                roots.push_back(int(n));
            }
        }
        return roots;
    }
    if (model.defaultScene < -1 || model.defaultScene >= int(model.scenes.size())) {
        fail(source, "/scene: scene " + std::to_string(model.defaultScene) + " does not exist");
    }
    const size_t scene = model.defaultScene < 0 ? 0 : size_t(model.defaultScene);
    const std::string at = "/scenes/" + std::to_string(scene) + "/nodes";
    std::vector<bool> listed(parent.size(), false);
    for (const int root : model.scenes[scene].nodes) {
        if (root < 0 || size_t(root) >= parent.size()) {
            fail(source, at + ": node " + std::to_string(root) + " does not exist");
        }
        if (parent[size_t(root)] != -1) {
            fail(source, at + ": node " + std::to_string(root) + " is a child of node " +
                             std::to_string(parent[size_t(root)]) + ", not a root");
        }
        if (listed[size_t(root)]) {
            fail(source, at + ": node " + std::to_string(root) + " is listed twice");
        }
        listed[size_t(root)] = true;
        roots.push_back(root);
    }
    return roots;
}

bool finiteAsFloat(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(float(m[c][r]))) {
                return false;
            }
        }
    }
    return true;
}

}  // namespace

std::string nodeName(const tinygltf::Model& model, int node) {
    const std::string& name = model.nodes[size_t(node)].name;
    return name.empty() ? "node " + std::to_string(node) : name;
}

// Depth first with a stack of its own: a hierarchy a million nodes deep must not overflow ours.
SceneInstances sceneInstances(const tinygltf::Model& model, const std::string& source) {
    const std::vector<int> parent = parents(model, source);
    refuseCycles(parent, source);
    const std::vector<int> roots = rootNodes(model, parent, source);
    // Trees now: each node is reached once. Its parent's world is looked up, not copied.
    std::vector<glm::dmat4> worlds(model.nodes.size());
    std::vector<int> stack(roots.rbegin(), roots.rend());
    SceneInstances instances;
    while (!stack.empty()) {
        const int index = stack.back();
        stack.pop_back();
        const tinygltf::Node& node = model.nodes[size_t(index)];
        const std::string where = nodeAt(size_t(index));
        const glm::dmat4 local = localTransform(node, where, source);
        const int up = parent[size_t(index)];
        const glm::dmat4& world = worlds[size_t(index)] = up < 0 ? local : worlds[size_t(up)] * local;
        if (!finiteAsFloat(world)) {
            fail(source, where + ": its world transform is not finite in single precision (numbers too large)");
        }
        if (node.mesh != -1) {
            if (node.mesh < 0 || size_t(node.mesh) >= model.meshes.size()) {
                fail(source, where + "/mesh: mesh " + std::to_string(node.mesh) + " does not exist");
            }
            instances.meshes.push_back({index, node.mesh, world});
        }
        if (node.camera != -1) {
            instances.cameras.push_back({index, node.camera, world});
        }
        stack.insert(stack.end(), node.children.rbegin(), node.children.rend());
    }
    return instances;
}

}  // namespace patina::gltf
