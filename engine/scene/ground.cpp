#include "scene/ground.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace patina {

GroundPlane groundUnder(const BoundingBox& bounds) {
    if (bounds.empty()) {
        return {};
    }
    const glm::vec3 middle = 0.5f * (bounds.low + bounds.high);
    const float radius = 0.5f * glm::length(bounds.high - bounds.low);
    return {{middle.x, bounds.low.y, middle.z}, std::max(kGroundRadii * radius, 1e-3f)};
}

Mesh groundMesh(const GroundPlane& plane) {
    const glm::vec3 c = plane.centre;
    const float s = plane.halfSize;
    Mesh mesh;
    mesh.positions = {c + glm::vec3(-s, 0.0f, -s), c + glm::vec3(-s, 0.0f, s), c + glm::vec3(s, 0.0f, s),
                      c + glm::vec3(s, 0.0f, -s)};
    mesh.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.uv0 = {{0.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}};
    mesh.tangents.assign(4, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    return mesh;
}

Mesh groundGrid(const GroundPlane& plane, int cells) {
    const int n = std::max(cells, 1);
    const float s = plane.halfSize;
    Mesh mesh;
    for (int row = 0; row <= n; ++row) {
        for (int column = 0; column <= n; ++column) {
            const glm::vec2 uv(float(column) / float(n), float(row) / float(n));
            mesh.positions.push_back(plane.centre + glm::vec3((2.0f * uv.x - 1.0f) * s, 0.0f, (2.0f * uv.y - 1.0f) * s));
            mesh.uv0.push_back(uv);
        }
    }
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
    mesh.tangents.assign(mesh.positions.size(), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    for (int row = 0; row < n; ++row) {
        for (int column = 0; column < n; ++column) {
            const uint32_t a = uint32_t(row * (n + 1) + column), b = a + uint32_t(n + 1);   // b: the next row (+z)
            mesh.indices.insert(mesh.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
        }
    }
    return mesh;
}

MaterialParameters groundMaterial(const DisplaySettings& display) {
    MaterialParameters material;
    material.model = BrdfModelId::Gltf;
    material.baseColor = display.groundColor;
    material.roughness = display.groundRoughness;
    material.metallic = 0.0f;
    material.specular = 0.5f;
    return material;
}

}  // namespace patina
