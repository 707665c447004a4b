#include "gltf/geometry.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <numeric>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "gltf/accessor.h"
#include "gltf/import.h"
#include "io/input_error.h"

namespace patina::gltf {

namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw InputError(source + ": " + what);
}

std::string at(const char* collection, size_t index) {
    return std::string("/") + collection + "/" + std::to_string(index);
}

// A node's optional array of `size` numbers: null when absent. (Finite: checkGltfJson refuses
// numbers a double cannot hold; products that overflow are caught on the positions.)
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
        transform *= glm::mat4_cast(q / length);
    }
    if (const double* s = numbers(node.scale, 3, where + "/scale", source)) {
        transform = glm::scale(transform, glm::make_vec3(s));
    }
    return transform;
}

struct Instance {
    size_t mesh;
    glm::dmat4 world;
};

// Depth first with a stack of its own: a hierarchy a million nodes deep must not overflow ours.
std::vector<Instance> meshInstances(const tinygltf::Model& model, const std::string& source) {
    const size_t nodeCount = model.nodes.size();
    std::vector<int> roots;
    std::string rootsAt;
    if (!model.scenes.empty()) {
        if (model.defaultScene < -1 || model.defaultScene >= int(model.scenes.size())) {
            fail(source, "/scene: scene " + std::to_string(model.defaultScene) + " does not exist");
        }
        const size_t scene = model.defaultScene < 0 ? 0 : size_t(model.defaultScene);
        roots = model.scenes[scene].nodes;
        rootsAt = at("scenes", scene) + "/nodes";
    } else {
        std::vector<bool> isChild(nodeCount, false);
        for (const tinygltf::Node& node : model.nodes) {
            for (const int child : node.children) {
                if (child >= 0 && size_t(child) < nodeCount) {
                    isChild[size_t(child)] = true;
                }
            }
        }
        for (size_t i = 0; i < nodeCount; ++i) {
            if (!isChild[i]) {
                roots.push_back(int(i));
            }
        }
    }
    // (node, parent or -1): the parent's world transform is looked up, not copied, so that a
    // long list of children costs 8 bytes an entry.
    std::vector<std::pair<int, int>> stack;
    auto push = [&](int node, int parent, const std::string& from) {   // from: the list, or the parent
        if (node < 0 || size_t(node) >= nodeCount) {
            fail(source, from + (parent < 0 ? "" : "/children") + ": node " + std::to_string(node) +
                             " does not exist");
        }
        stack.emplace_back(node, parent);
    };
    for (auto root = roots.rbegin(); root != roots.rend(); ++root) {
        push(*root, -1, rootsAt);
    }
    std::vector<bool> visited(nodeCount, false);
    std::vector<glm::dmat4> worlds(nodeCount);
    std::vector<Instance> instances;
    while (!stack.empty()) {
        const auto [index, parent] = stack.back();
        stack.pop_back();
        const std::string where = at("nodes", size_t(index));
        if (visited[size_t(index)]) {
            fail(source, where + ": reached twice (a cycle, or a node with two parents)");
        }
        visited[size_t(index)] = true;
        const tinygltf::Node& node = model.nodes[size_t(index)];
        const glm::dmat4 local = localTransform(node, where, source);
        const glm::dmat4& world = worlds[size_t(index)] = parent < 0 ? local : worlds[size_t(parent)] * local;
        if (node.mesh != -1) {
            if (node.mesh < 0 || size_t(node.mesh) >= model.meshes.size()) {
                fail(source, where + "/mesh: mesh " + std::to_string(node.mesh) + " does not exist");
            }
            instances.push_back({size_t(node.mesh), world});
        }
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
            push(*child, index, where);
        }
    }
    return instances;
}

// One primitive of one instance, its accessors checked. Small: there may be many.
struct Part {
    const glm::dmat4* world;
    size_t mesh, primitive;
    int mode;
    AccessorView positions, normals, indices;   // normals and indices: count 0 when absent
    bool hasNormals, hasIndices;
    size_t triangles;

    std::string where() const { return at("meshes", mesh) + at("primitives", primitive); }
};

Part planPart(const tinygltf::Model& model, const Instance& instance, size_t primitiveIndex,
              const std::string& source) {
    const tinygltf::Primitive& primitive = model.meshes[instance.mesh].primitives[primitiveIndex];
    Part part{&instance.world, instance.mesh, primitiveIndex, primitive.mode, {}, {}, {}, false, false, 0};
    const std::string where = part.where();
    part.positions = viewAccessor(model, primitive.attributes.at("POSITION"), TINYGLTF_TYPE_VEC3,
                                  {TINYGLTF_COMPONENT_TYPE_FLOAT}, where + "/attributes/POSITION", source);
    if (const auto normal = primitive.attributes.find("NORMAL"); normal != primitive.attributes.end()) {
        part.normals = viewAccessor(model, normal->second, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                                    where + "/attributes/NORMAL", source);
        part.hasNormals = true;
        if (part.normals.count != part.positions.count) {
            fail(source, where + "/attributes/NORMAL: " + std::to_string(part.normals.count) + " normals for " +
                             std::to_string(part.positions.count) + " positions");
        }
    }
    if (primitive.indices != -1) {
        part.indices = viewAccessor(model, primitive.indices, TINYGLTF_TYPE_SCALAR,
                                    {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                    where + "/indices", source);
        part.hasIndices = true;
    }
    const size_t corners = part.hasIndices ? part.indices.count : part.positions.count;
    part.triangles = part.mode == TINYGLTF_MODE_TRIANGLES ? corners / 3 : corners >= 3 ? corners - 2 : 0;
    return part;
}

template <typename T>
void readIndices(const Part& part, std::vector<uint32_t>& corners, const std::string& source) {
    const AccessorView& view = part.indices;
    const size_t vertices = part.positions.count;
    for (size_t i = 0; i < view.count; ++i) {
        T value;
        std::memcpy(&value, view.data + i * view.stride, sizeof value);
        if (value >= vertices) {
            fail(source, part.where() + "/indices: element " + std::to_string(i) + " is " + std::to_string(value) +
                             " but the primitive has " + std::to_string(vertices) + " vertices");
        }
        corners[i] = uint32_t(value);
    }
}

void readCorners(const Part& part, std::vector<uint32_t>& corners, const std::string& source) {
    corners.resize(part.hasIndices ? part.indices.count : part.positions.count);
    if (!part.hasIndices) {
        std::iota(corners.begin(), corners.end(), 0u);
        return;
    }
    switch (part.indices.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: readIndices<uint8_t>(part, corners, source); break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: readIndices<uint16_t>(part, corners, source); break;
    default: readIndices<uint32_t>(part, corners, source); break;
    }
}

// Triangle lists from the corners, in glTF's order for strips and fans; `flip` reverses each
// triangle, for a transform that mirrors.
void assembleTriangles(const Part& part, const std::vector<uint32_t>& c, bool flip, std::vector<uint32_t>& out) {
    out.resize(part.triangles * 3);
    for (size_t t = 0; t < part.triangles; ++t) {
        uint32_t a, b, d;
        if (part.mode == TINYGLTF_MODE_TRIANGLES) {
            a = c[3 * t], b = c[3 * t + 1], d = c[3 * t + 2];
        } else if (part.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            a = c[t + (t % 2)], b = c[t + 1 - (t % 2)], d = c[t + 2];
        } else {
            a = c[t + 1], b = c[t + 2], d = c[0];
        }
        out[3 * t] = a;
        out[3 * t + 1] = flip ? d : b;
        out[3 * t + 2] = flip ? b : d;
    }
}

glm::vec3 readVec3(const AccessorView& view, size_t i) {
    glm::vec3 v;
    std::memcpy(&v[0], view.data + i * view.stride, sizeof(float) * 3);
    return v;
}

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void appendPart(Mesh& mesh, const Part& part, std::vector<uint32_t>& corners, std::vector<uint32_t>& triangles,
                const std::string& source) {
    const glm::mat4 world(*part.world);
    // In double: the determinant and the cofactor matrix grow as the cube and the square of the
    // node's scale, and a scale of 1e-20 or 1e20 is finite in a float.
    const glm::dmat3 linear(*part.world);
    const double determinant = glm::determinant(linear);
    // The cofactor matrix: the inverse transpose times the determinant, defined even at 0.
    // Only its directions matter, so it is scaled to its largest entry, and negated for a mirror.
    const glm::dmat3 cofactor(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                              glm::cross(linear[0], linear[1]));
    double largest = 0.0;
    for (int c = 0; c < 3; ++c) {
        largest = std::max({largest, std::abs(cofactor[c].x), std::abs(cofactor[c].y), std::abs(cofactor[c].z)});
    }
    const double scale = largest > 0.0 && std::isfinite(largest) ? 1.0 / largest : 1.0;
    const glm::mat3 normalMatrix(cofactor * (determinant < 0.0 ? -scale : scale));
    const size_t base = mesh.positions.size();
    for (size_t i = 0; i < part.positions.count; ++i) {
        const glm::vec3 p = glm::vec3(world * glm::vec4(readVec3(part.positions, i), 1.0f));
        if (!isFinite(p)) {
            fail(source, part.where() + "/attributes/POSITION: element " + std::to_string(i) +
                             " is not finite (after the node transforms)");
        }
        mesh.positions.push_back(p);
    }
    readCorners(part, corners, source);
    assembleTriangles(part, corners, determinant < 0.0, triangles);
    if (part.hasNormals) {
        for (size_t i = 0; i < part.normals.count; ++i) {
            const glm::vec3 n = normalMatrix * readVec3(part.normals, i);
            if (!isFinite(n)) {
                fail(source, part.where() + "/attributes/NORMAL: element " + std::to_string(i) + " is not finite");
            }
            mesh.normals.push_back(unitNormal(n));
        }
    } else {
        const std::vector<glm::vec3> normals =
            smoothNormals(std::span(mesh.positions).subspan(base, part.positions.count), triangles);
        mesh.normals.insert(mesh.normals.end(), normals.begin(), normals.end());
    }
    for (const uint32_t index : triangles) {
        mesh.indices.push_back(uint32_t(base) + index);
    }
}

}  // namespace

Mesh meshFromModel(const tinygltf::Model& model, const std::string& source) {
    const std::vector<Instance> instances = meshInstances(model, source);
    std::vector<Part> parts;
    size_t vertices = 0, triangles = 0;
    for (const Instance& instance : instances) {
        const tinygltf::Mesh& mesh = model.meshes[instance.mesh];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            if (primitive.mode < TINYGLTF_MODE_POINTS || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN) {
                fail(source, at("meshes", instance.mesh) + at("primitives", p) + "/mode: unknown mode " +
                                 std::to_string(primitive.mode));
            }
            if (primitive.mode < TINYGLTF_MODE_TRIANGLES || !primitive.attributes.count("POSITION")) {
                continue;   // points and lines; a primitive without positions draws nothing
            }
            if (parts.size() == kGltfMaxPrimitives) {
                fail(source, "the scene draws more than " + std::to_string(kGltfMaxPrimitives) +
                                 " mesh primitives (Patina's limit)");
            }
            parts.push_back(planPart(model, instance, p, source));
            vertices += parts.back().positions.count;
            triangles += parts.back().triangles;
            if (vertices > kGltfMaxVertices || triangles > kGltfMaxTriangles) {
                fail(source, "the scene has more than " + std::to_string(kGltfMaxVertices) + " vertices or " +
                                 std::to_string(kGltfMaxTriangles) + " triangles (Patina's limit)");
            }
        }
    }
    if (triangles == 0) {
        fail(source, "the scene has no triangles");
    }
    Mesh mesh;
    mesh.positions.reserve(vertices);
    mesh.normals.reserve(vertices);
    mesh.indices.reserve(triangles * 3);
    std::vector<uint32_t> corners, partTriangles;
    for (const Part& part : parts) {
        appendPart(mesh, part, corners, partTriangles, source);
    }
    return mesh;
}

}  // namespace patina::gltf
