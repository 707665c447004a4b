// MikkTSpace tangents (tangents.h): against the tangent frames the UV layouts give analytically.
// glTF's v grows down the image and a normal map's +Y points up it, so the bitangent a tangent
// implies, cross(N, T) * w, must point along -dP/dv.
#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/mat2x2.hpp>
#include <glm/matrix.hpp>

#include "geometry/tangents.h"

namespace patina {
namespace {

constexpr glm::vec3 kUp(0.0f, 0.0f, 1.0f);   // the normal of the planar test meshes

// A planar UV layout: uv = matrix * (x, y) + offset.
struct Layout {
    glm::mat2 matrix;
    glm::vec2 offset{0.0f};
};

// u along +x and v along -y: the image's top at the top of the plane, as glTF's v grows down.
Layout gltfLayout() {
    return {glm::mat2(1.0f, 0.0f, 0.0f, -1.0f), glm::vec2(0.0f, 1.0f)};
}

// The frame a layout gives: T along dP/du, w from whether cross(N, T) points up the image
// (-dP/dv). dP/d(u, v) is the inverse of the layout's matrix.
glm::vec4 analyticTangent(const Layout& layout) {
    const glm::mat2 inverse = glm::inverse(layout.matrix);
    const glm::vec3 du(inverse[0], 0.0f), upImage(-inverse[1], 0.0f);
    const glm::vec3 t = glm::normalize(du);
    return {t, glm::dot(glm::cross(kUp, t), upImage) > 0.0f ? 1.0f : -1.0f};
}

// The vertex at `p` with `uv`, made when the mesh has none yet: quads that meet along an edge
// with the same UVs there share its vertices, as an indexed glTF mesh does.
uint32_t vertexAt(Mesh& mesh, glm::vec3 p, glm::vec2 uv) {
    for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
        if (mesh.positions[v] == p && mesh.uv0[v] == uv) {
            return v;
        }
    }
    mesh.positions.push_back(p);
    mesh.normals.push_back(kUp);
    mesh.uv0.push_back(uv);
    return uint32_t(mesh.positions.size() - 1);
}

// The square [low, high] in the xy plane, wound counter-clockwise about +z, UVs by `layout`.
void addQuad(Mesh& mesh, glm::vec2 low, glm::vec2 high, const Layout& layout) {
    uint32_t corner[4];
    const glm::vec2 xy[4] = {low, {high.x, low.y}, high, {low.x, high.y}};
    for (int k = 0; k < 4; ++k) {
        corner[k] = vertexAt(mesh, glm::vec3(xy[k], 0.0f), layout.matrix * xy[k] + layout.offset);
    }
    mesh.indices.insert(mesh.indices.end(), {corner[0], corner[1], corner[2], corner[0], corner[2], corner[3]});
}

// The contract of every tangent: finite, xyz unit and orthogonal to the normal, w = +-1.
void expectValidTangents(const Mesh& mesh, const std::vector<glm::vec4>& tangents) {
    ASSERT_EQ(tangents.size(), mesh.positions.size());
    for (size_t v = 0; v < tangents.size(); ++v) {
        const glm::vec4& t = tangents[v];
        ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) << "vertex " << v;
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f) << "vertex " << v;
        EXPECT_NEAR(glm::dot(glm::vec3(t), unitNormal(mesh.normals[v])), 0.0f, 1e-4f) << "vertex " << v;
        EXPECT_TRUE(t.w == 1.0f || t.w == -1.0f) << "vertex " << v << ": w " << t.w;
    }
}

void expectNear(const glm::vec4& actual, const glm::vec4& expected, const std::string& where) {
    EXPECT_NEAR(glm::length(glm::vec3(actual) - glm::vec3(expected)), 0.0f, 1e-5f) << where;
    EXPECT_EQ(actual.w, expected.w) << where;
}

// The two halves of a mirrored model: [0, 1]^2 laid out as glTF's, [1, 2] x [0, 1] with u
// mirrored, meeting at x = 1 where both have u = 1 (so they share that edge's vertices).
Layout mirroredLayout() {
    return {glm::mat2(-1.0f, 0.0f, 0.0f, -1.0f), glm::vec2(2.0f, 1.0f)};
}
Mesh mirroredModel() {
    Mesh mesh;
    addQuad(mesh, {0.0f, 0.0f}, {1.0f, 1.0f}, gltfLayout());
    addQuad(mesh, {1.0f, 0.0f}, {2.0f, 1.0f}, mirroredLayout());
    return mesh;
}
// Whether the triangle of `corner` lies on the mirrored half (x > 1), by its centroid.
bool onMirroredHalf(const Mesh& mesh, size_t corner) {
    const size_t start = corner - corner % 3;
    const float x = (mesh.positions[mesh.indices[start]].x + mesh.positions[mesh.indices[start + 1]].x +
                     mesh.positions[mesh.indices[start + 2]].x) / 3.0f;
    return x > 1.0f;
}

TEST(Tangents, GltfQuadGivesTheAnalyticFrame) {
    Mesh quad;
    addQuad(quad, {0.0f, 0.0f}, {1.0f, 1.0f}, gltfLayout());
    const std::vector<glm::vec4> tangents = mikkTSpaceTangents(quad, 0);
    expectValidTangents(quad, tangents);
    const glm::vec4 expected = analyticTangent(gltfLayout());
    EXPECT_EQ(glm::vec3(expected), glm::vec3(1.0f, 0.0f, 0.0f));   // u grows along +x
    for (size_t v = 0; v < tangents.size(); ++v) {
        expectNear(tangents[v], expected, "vertex " + std::to_string(v));
        // v grows along -y, so the map's +Y (up the image) is +y.
        const glm::vec3 bitangent = glm::cross(kUp, glm::vec3(tangents[v])) * tangents[v].w;
        EXPECT_NEAR(glm::length(bitangent - glm::vec3(0.0f, 1.0f, 0.0f)), 0.0f, 1e-5f);
    }
}

TEST(Tangents, RotatedLayoutRotatesTheTangent) {
    for (float degrees : {30.0f, 90.0f, 135.0f, 250.0f}) {
        const float a = glm::radians(degrees);
        const glm::mat2 rotation(std::cos(a), std::sin(a), -std::sin(a), std::cos(a));
        const Layout layout{rotation * gltfLayout().matrix, glm::vec2(0.5f)};
        Mesh quad;
        addQuad(quad, {0.0f, 0.0f}, {1.0f, 1.0f}, layout);
        const std::vector<glm::vec4> tangents = mikkTSpaceTangents(quad, 0);
        expectValidTangents(quad, tangents);
        for (size_t v = 0; v < tangents.size(); ++v) {
            expectNear(tangents[v], analyticTangent(layout), std::to_string(degrees) + " degrees, vertex " + std::to_string(v));
        }
    }
}

TEST(Tangents, MirroredIslandSplitsItsSharedEdge) {
    const Mesh model = mirroredModel();
    ASSERT_EQ(model.positions.size(), 6u);   // the shared edge's two vertices are shared
    const Mesh split = withTangents(model, 0);
    expectValidTangents(split, split.tangents);
    ASSERT_EQ(split.positions.size(), 8u);   // ... and split
    ASSERT_EQ(split.indices.size(), model.indices.size());
    for (size_t corner = 0; corner < split.indices.size(); ++corner) {
        const bool mirrored = onMirroredHalf(split, corner);
        const uint32_t v = split.indices[corner];
        expectNear(split.tangents[v], analyticTangent(mirrored ? mirroredLayout() : gltfLayout()),
                   "corner " + std::to_string(corner));
        EXPECT_EQ(split.tangents[v].w, mirrored ? -1.0f : 1.0f) << "corner " << corner;
        // A copy is its vertex again: only the tangent differs.
        const uint32_t original = model.indices[corner];
        EXPECT_EQ(split.positions[v], model.positions[original]);
        EXPECT_EQ(split.normals[v], model.normals[original]);
        EXPECT_EQ(split.uv0[v], model.uv0[original]);
    }
    // One tangent per vertex: the shared ones keep their first face's.
    const std::vector<glm::vec4> perVertex = mikkTSpaceTangents(model, 0);
    for (size_t v = 0; v < perVertex.size(); ++v) {
        expectNear(perVertex[v], split.tangents[v], "vertex " + std::to_string(v));
    }
}

}  // namespace
}  // namespace patina
