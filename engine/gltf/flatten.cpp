#include "gltf/flatten.h"

#include <algorithm>
#include <cmath>

#include <glm/mat3x3.hpp>

#include "io/input_error.h"

namespace patina::gltf {

namespace {

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The cofactor matrix: the inverse transpose times the determinant, defined even at 0. Only its
// directions matter, so it is scaled to its largest entry, and negated for a mirror. In double:
// it grows as the square of the scale, and a scale of 1e-20 or 1e20 is finite in a float.
glm::mat3 normalMatrix(const glm::mat4& transform) {
    const glm::dmat3 linear(transform);
    const glm::dmat3 cofactor(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                              glm::cross(linear[0], linear[1]));
    double largest = 0.0;
    for (int c = 0; c < 3; ++c) {
        largest = std::max({largest, std::abs(cofactor[c].x), std::abs(cofactor[c].y), std::abs(cofactor[c].z)});
    }
    const double scale = largest > 0.0 && std::isfinite(largest) ? 1.0 / largest : 1.0;
    return glm::mat3(cofactor * (glm::determinant(linear) < 0.0 ? -scale : scale));
}

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
    const glm::mat3 normals = normalMatrix(draw.transform);
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
