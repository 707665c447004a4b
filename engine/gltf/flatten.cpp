#include "gltf/flatten.h"

#include <cmath>

#include <glm/mat3x3.hpp>

#include "files/input_error.h"
#include "model/placement.h"

namespace patina::gltf {

namespace {

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void appendDraw(Mesh& mesh, const Mesh& primitive, const DrawItem& draw, const std::string& source) {
    const size_t base = mesh.positions.size();
    for (size_t i = 0; i < primitive.positions.size(); ++i) {
        const glm::vec3 p = glm::vec3(draw.transform * glm::vec4(primitive.positions[i], 1.0f));
        if (!isFinite(p)) {
            throw InputError(source + ": " + draw.node + ": position " + std::to_string(i) +
                             " of its mesh is not finite after the node transforms");
        }
        mesh.positions.push_back(p);
    }
    const glm::mat3 normals = normalTransform(draw.transform);
    for (const glm::vec3& n : primitive.normals) {
        mesh.normals.push_back(unitNormal(normals * n));
    }
    for (size_t t = 0; t < primitive.indices.size(); t += 3) {
        const uint32_t a = primitive.indices[t], b = primitive.indices[t + 1], c = primitive.indices[t + 2];
        // A mirror reverses each triangle (its first corner stays) so that it stays counter-clockwise.
        for (const uint32_t corner : {a, draw.mirrored ? c : b, draw.mirrored ? b : c}) {
            mesh.indices.push_back(uint32_t(base) + corner);
        }
    }
}

}  // namespace

Mesh flattenDraws(const Model& model, const std::string& source) {
    size_t vertices = 0, indices = 0;
    for (const DrawItem& draw : model.draws) {
        vertices += model.primitives[size_t(draw.primitive)].positions.size();
        indices += model.primitives[size_t(draw.primitive)].indices.size();
    }
    Mesh mesh;
    mesh.positions.reserve(vertices);
    mesh.normals.reserve(vertices);
    mesh.indices.reserve(indices);
    for (const DrawItem& draw : model.draws) {
        appendDraw(mesh, model.primitives[size_t(draw.primitive)], draw, source);
    }
    return mesh;
}

}  // namespace patina::gltf
