#include "geometry/silhouette.h"

#include <algorithm>
#include <map>
#include <tuple>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace patina {

namespace {
struct PositionLess {
    bool operator()(const glm::vec3& a, const glm::vec3& b) const {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    }
};
}  // namespace

EdgeFaces edgeFaces(const Mesh& mesh) {
    // Each position once: a welded corner is the first vertex with its position.
    std::vector<uint32_t> weld(mesh.positions.size());
    std::map<glm::vec3, uint32_t, PositionLess> first;
    for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
        weld[v] = first.try_emplace(mesh.positions[v], v).first->second;
    }
    EdgeFaces result;
    std::unordered_map<uint64_t, size_t> edgeOf;   // (lower corner, higher corner) -> its index
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t c[3] = {weld[mesh.indices[t]], weld[mesh.indices[t + 1]], weld[mesh.indices[t + 2]]};
        const glm::vec3 &p0 = mesh.positions[c[0]], &p1 = mesh.positions[c[1]], &p2 = mesh.positions[c[2]];
        const glm::vec3 normal = glm::cross(p1 - p0, p2 - p0);
        if (!(glm::dot(normal, normal) > 0.0f)) {
            continue;
        }
        const int32_t face = int32_t(result.faceNormals.size());
        result.faceNormals.push_back(normal);
        result.faceCorners.push_back(p0);
        for (int e = 0; e < 3; ++e) {
            const auto [low, high] = std::minmax(c[e], c[(e + 1) % 3]);
            const auto [entry, added] = edgeOf.try_emplace(uint64_t(low) << 32 | high, result.edges.size());
            if (added) {
                result.edges.push_back({mesh.positions[low], mesh.positions[high], face, -1});
            } else {
                EdgeFaces::Edge& edge = result.edges[entry->second];
                edge.left = edge.right == -1 ? edge.left : -2;
                edge.right = face;
            }
        }
    }
    return result;
}

std::vector<std::pair<glm::vec3, glm::vec3>> silhouetteEdges(const EdgeFaces& mesh, const glm::vec3& eye) {
    auto facing = [&](int32_t face) {
        return glm::dot(mesh.faceNormals[size_t(face)], eye - mesh.faceCorners[size_t(face)]) > 0.0f;
    };
    std::vector<std::pair<glm::vec3, glm::vec3>> outline;
    for (const EdgeFaces::Edge& edge : mesh.edges) {
        if (edge.right < 0 || edge.left < 0 || facing(edge.left) != facing(edge.right)) {
            outline.emplace_back(edge.a, edge.b);
        }
    }
    return outline;
}

}  // namespace patina
