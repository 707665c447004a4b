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
