#include "geometry/mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "common/enum_names.h"

namespace patina {

namespace {

// Indices of a (rows + 1) x (columns + 1) vertex grid, two triangles per cell, wound so that
// the outward normal faces the viewer (counter-clockwise).
std::vector<uint32_t> gridIndices(int rows, int columns) {
    std::vector<uint32_t> indices;
    indices.reserve(size_t(rows) * size_t(columns) * 6);
    const uint32_t stride = uint32_t(columns) + 1;
    for (uint32_t row = 0; row < uint32_t(rows); ++row) {
        for (uint32_t column = 0; column < uint32_t(columns); ++column) {
            const uint32_t a = row * stride + column;
            const uint32_t b = a + stride;
            indices.insert(indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    }
    return indices;
}

// (sin, cos) of the angle k / n of a full turn. The last column of a grid is its first again:
// the same position to the bit, so the seam is closed (hidden_faces.h), as sin(float(2 pi))
// is not 0.
glm::vec2 turn(int k, int n) {
    n = std::max(n, 1);
    const float angle = 2.0f * std::numbers::pi_v<float> * float(k % n) / float(n);
    return {std::sin(angle), std::cos(angle)};
}
}  // namespace

Mesh makeUvSphere(int rings, int segments) {
    Mesh mesh;
    for (int ring = 0; ring <= rings; ++ring) {
        const float theta = std::numbers::pi_v<float> * float(ring) / float(rings);   // from +y down
        // sin(float(pi)) is not 0: the south pole's copies would differ.
        const float sinTheta = ring == rings ? 0.0f : std::sin(theta);
        const float cosTheta = ring == rings ? -1.0f : std::cos(theta);
        for (int segment = 0; segment <= segments; ++segment) {
            const glm::vec2 phi = turn(segment, segments);
            const glm::vec3 n(sinTheta * phi.x, cosTheta, sinTheta * phi.y);
            mesh.positions.push_back(n);
            mesh.normals.push_back(n);
        }
    }
    mesh.indices = gridIndices(rings, segments);
    return mesh;
}

Mesh makeTorus(float majorRadius, float minorRadius, int rings, int segments) {
    Mesh mesh;
    for (int ring = 0; ring <= rings; ++ring) {
        const glm::vec2 u = turn(ring, rings);   // around the y axis
        const glm::vec3 tubeCenter(majorRadius * u.x, 0.0f, majorRadius * u.y);
        const glm::vec3 outward(u.x, 0.0f, u.y);
        for (int segment = 0; segment <= segments; ++segment) {
            const glm::vec2 v = turn(segment, segments);
            const glm::vec3 n = v.y * outward + v.x * glm::vec3(0.0f, 1.0f, 0.0f);
            mesh.positions.push_back(tubeCenter + minorRadius * n);
            mesh.normals.push_back(n);
        }
    }
    mesh.indices = gridIndices(rings, segments);
    return mesh;
}

std::string_view meshKindName(MeshKind mesh) {
    switch (mesh) {
    case MeshKind::Sphere: return "sphere";
    case MeshKind::Torus: return "torus";
    }
    return "sphere";
}

std::optional<MeshKind> meshKindFromName(std::string_view name) {
    static const MeshKind all[] = {MeshKind::Sphere, MeshKind::Torus};
    return enumFromName(name, all, meshKindName);
}

Mesh makeMesh(MeshKind kind) {
    switch (kind) {
    case MeshKind::Torus: return makeTorus();
    case MeshKind::Sphere: break;
    }
    return makeUvSphere();
}

std::shared_ptr<const Mesh> builtinMesh(MeshKind kind) {
    static const std::shared_ptr<const Mesh> sphere = std::make_shared<const Mesh>(makeMesh(MeshKind::Sphere));
    static const std::shared_ptr<const Mesh> torus = std::make_shared<const Mesh>(makeMesh(MeshKind::Torus));
    return kind == MeshKind::Torus ? torus : sphere;
}

Mesh reversedWinding(Mesh mesh) {
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    }
    return mesh;
}

glm::vec3 unitNormal(const glm::vec3& n) {
    const glm::vec3 size = glm::abs(n);
    const float largest = std::max({size.x, size.y, size.z});
    if (!(largest > 0.0f) || !std::isfinite(size.x) || !std::isfinite(size.y) || !std::isfinite(size.z)) {
        return glm::vec3(0.0f, 1.0f, 0.0f);
    }
    // Scaled first: the square of 1e-22 is a denormal with a few bits left, so its root
    // would be off by percents, and the square of 1e20 overflows.
    const glm::vec3 scaled = n / largest;
    return scaled / glm::length(scaled);
}

std::vector<glm::vec3> smoothNormals(std::span<const glm::vec3> positions,
                                     std::span<const uint32_t> triangles) {
    // The cross product's length is twice the triangle's area: the weight comes for free.
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const uint32_t a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
        const glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for (glm::vec3& n : normals) {
        n = unitNormal(n);
    }
    return normals;
}

BoundingBox boundingBox(const Mesh& mesh) {
    if (mesh.positions.empty()) {
        return {};
    }
    BoundingBox box{mesh.positions.front(), mesh.positions.front()};
    for (const glm::vec3& p : mesh.positions) {
        box.low = glm::min(box.low, p);
        box.high = glm::max(box.high, p);
    }
    return box;
}

BoundingSphere boundingSphere(const Mesh& mesh) {
    const BoundingBox box = boundingBox(mesh);
    if (box.empty()) {
        return {};
    }
    BoundingSphere sphere;
    sphere.center = 0.5f * (box.low + box.high);
    for (const glm::vec3& p : mesh.positions) {
        sphere.radius = std::max(sphere.radius, glm::length(p - sphere.center));
    }
    return sphere;
}

}  // namespace patina
