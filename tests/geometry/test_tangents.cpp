// MikkTSpace tangents (tangents.h): against the tangent frames the UV layouts give analytically.
// glTF's v grows down the image and a normal map's +Y points up it, so the bitangent a tangent
// implies, cross(N, T) * w, must point along -dP/dv.
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

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

// The up-the-image direction a layout gives (-dP/dv), unit.
glm::vec3 analyticUp(const Layout& layout) {
    return glm::normalize(glm::vec3(-glm::inverse(layout.matrix)[1], 0.0f));
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

// The triangle a, b, c of the xy plane, UVs by `layout`.
void addTriangle(Mesh& mesh, glm::vec2 a, glm::vec2 b, glm::vec2 c, const Layout& layout) {
    for (glm::vec2 xy : {a, b, c}) {
        mesh.indices.push_back(vertexAt(mesh, glm::vec3(xy, 0.0f), layout.matrix * xy + layout.offset));
    }
}

// The square [low, high] in the xy plane, wound counter-clockwise about +z, UVs by `layout`.
void addQuad(Mesh& mesh, glm::vec2 low, glm::vec2 high, const Layout& layout) {
    const glm::vec2 right(high.x, low.y), left(low.x, high.y);
    addTriangle(mesh, low, right, high, layout);
    addTriangle(mesh, low, high, left, layout);
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
            expectNear(tangents[v], analyticTangent(layout),
                       std::to_string(degrees) + " degrees, vertex " + std::to_string(v));
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

// makeUvSphere's grid: (rings + 1) rows of (segments + 1) vertices from the north pole down,
// the last column repeating the first. Its UVs as a glTF UV sphere has them: u round the
// longitude, v from the north pole (the image's top) down.
Mesh sphereWithUvs(int rings, int segments) {
    Mesh sphere = makeUvSphere(rings, segments);
    EXPECT_TRUE(sphere.uv0.empty());   // the built-in sphere has none: made here
    EXPECT_EQ(sphere.positions.size(), size_t(rings + 1) * size_t(segments + 1));
    for (int ring = 0; ring <= rings; ++ring) {
        for (int segment = 0; segment <= segments; ++segment) {
            sphere.uv0.emplace_back(float(segment) / float(segments), float(ring) / float(rings));
        }
    }
    return sphere;
}

TEST(Tangents, SphereTangentsFollowTheLongitude) {
    const int rings = 16, segments = 32;
    const Mesh sphere = sphereWithUvs(rings, segments);
    const std::vector<glm::vec4> tangents = mikkTSpaceTangents(sphere, 0);
    expectValidTangents(sphere, tangents);
    for (size_t v = size_t(segments + 1); v < size_t(rings) * size_t(segments + 1); ++v) {   // off the poles
        const glm::vec3 n = sphere.normals[v];
        // u grows with the longitude: d/dphi of (sin phi, ., cos phi) is (cos phi, 0, -sin phi);
        // up the image is north, +y in the tangent plane.
        const glm::vec3 east = glm::normalize(glm::vec3(n.z, 0.0f, -n.x));
        const glm::vec3 north = glm::normalize(glm::vec3(0.0f, 1.0f, 0.0f) - n * n.y);
        // A face's dP/du is its chord along a ring, half a segment off the tangent at its ends:
        // a seam vertex, with faces on one side only, keeps that turn; elsewhere both sides cancel it.
        const bool seam = v % size_t(segments + 1) == 0 || v % size_t(segments + 1) == size_t(segments);
        const float halfSegment = std::cos(std::numbers::pi_v<float> / float(segments));
        EXPECT_GT(glm::dot(glm::vec3(tangents[v]), east), seam ? halfSegment - 1e-5f : 0.9995f) << "vertex " << v;
        EXPECT_EQ(tangents[v].w, glm::dot(glm::cross(n, east), north) > 0.0f ? 1.0f : -1.0f) << "vertex " << v;
    }
    // Every face at a vertex agrees (the seam is already two columns): nothing splits.
    EXPECT_EQ(withTangents(sphere, 0).positions.size(), sphere.positions.size());
}

TEST(Tangents, TriangleSoupWeldsToTheIndexedTangents) {
    // A glTF primitive without indices: three vertices of its own per triangle.
    const Mesh indexed = sphereWithUvs(8, 16);
    Mesh soup;
    for (uint32_t index : indexed.indices) {
        soup.indices.push_back(uint32_t(soup.positions.size()));
        soup.positions.push_back(indexed.positions[index]);
        soup.normals.push_back(indexed.normals[index]);
        soup.uv0.push_back(indexed.uv0[index]);
    }
    const std::vector<glm::vec4> smooth = mikkTSpaceTangents(indexed, 0);
    const std::vector<glm::vec4> welded = mikkTSpaceTangents(soup, 0);
    expectValidTangents(soup, welded);
    for (size_t corner = 0; corner < soup.indices.size(); ++corner) {
        expectNear(welded[corner], smooth[indexed.indices[corner]], "corner " + std::to_string(corner));
    }
}

TEST(Tangents, DegenerateFacesGiveFiniteTangents) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Mesh triangle;
    triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    triangle.normals.assign(3, kUp);
    triangle.indices = {0, 1, 2};
    // One UV for all corners, UVs on a line, a NaN UV; then corners on a line, and no UVs.
    for (const std::vector<glm::vec2>& uvs : std::vector<std::vector<glm::vec2>>{
             {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}}, {{0, 0}, {1, 1}, {2, 2}}, {{0, 0}, {1, 0}, {nan, 1}}}) {
        triangle.uv0 = uvs;
        const std::vector<glm::vec4> tangents = mikkTSpaceTangents(triangle, 0);
        expectValidTangents(triangle, tangents);
        for (const glm::vec4& t : tangents) {
            EXPECT_EQ(t, glm::vec4(fallbackTangent(kUp), 1.0f));
        }
        const Mesh split = withTangents(triangle, 0);
        expectValidTangents(split, split.tangents);
    }
    Mesh sliver = triangle;
    sliver.positions[2] = {2, 0, 0};
    sliver.uv0 = {{0, 0}, {1, 0}, {0, 1}};
    expectValidTangents(sliver, mikkTSpaceTangents(sliver, 0));
    expectValidTangents(sliver, mikkTSpaceTangents(sliver, 1));   // no uv1
}

TEST(Tangents, DegenerateFaceInheritsItsNeighboursTangent) {
    // A rotated layout, so that the neighbour's tangent is not the fallback's +x.
    const float a = glm::radians(60.0f);
    const Layout layout{glm::mat2(std::cos(a), std::sin(a), -std::sin(a), std::cos(a)) * gltfLayout().matrix};
    Mesh quad;
    addQuad(quad, {0.0f, 0.0f}, {1.0f, 1.0f}, layout);
    ASSERT_EQ(quad.indices[3], 0u);
    quad.uv0[quad.indices[5]] = quad.uv0[0];   // the second triangle: no UV area
    const Mesh split = withTangents(quad, 0);
    expectValidTangents(split, split.tangents);
    EXPECT_EQ(split.positions.size(), quad.positions.size());   // one group at each vertex
    for (uint32_t v : {quad.indices[3], quad.indices[4]}) {   // shared with the first triangle
        expectNear(split.tangents[v], analyticTangent(layout), "vertex " + std::to_string(v));
    }
    expectNear(split.tangents[quad.indices[5]], glm::vec4(fallbackTangent(kUp), 1.0f), "its own vertex");
}

TEST(Tangents, MeshWithoutNormalsGetsSmoothOnes) {
    Mesh sphere = sphereWithUvs(8, 16);
    sphere.normals.clear();
    const std::vector<glm::vec3> smooth = smoothNormals(sphere.positions, sphere.indices);
    sphere.indices.insert(sphere.indices.end(), {0, 1, uint32_t(sphere.positions.size())});   // left out
    const Mesh tangents = withTangents(sphere, 0);
    ASSERT_EQ(tangents.normals.size(), smooth.size());   // nothing split: one per position
    for (size_t v = 0; v < smooth.size(); ++v) {
        EXPECT_NEAR(glm::length(tangents.normals[v] - smooth[v]), 0.0f, 1e-6f) << "vertex " << v;
    }
    expectValidTangents(tangents, tangents.tangents);
}

// The normal a shader makes of tangent-space normal `map` with a vertex's frame (glTF's).
glm::vec3 perturbed(const glm::vec3& map, const glm::vec3& normal, const glm::vec4& tangent) {
    const glm::vec3 t(tangent), bitangent = glm::cross(normal, t) * tangent.w;
    return glm::normalize(t * map.x + bitangent * map.y + normal * map.z);
}

TEST(Tangents, MirroredStripeLightsFromTheSameSide) {
    // One stripe of a normal map, painted once and used by both halves: its slope faces the
    // map's +X (across the stripe) or +Y (along it).
    const Mesh model = withTangents(mirroredModel(), 0);
    const glm::vec3 across = glm::normalize(glm::vec3(0.3f, 0.0f, 1.0f));
    const glm::vec3 along = glm::normalize(glm::vec3(0.0f, 0.3f, 1.0f));
    for (const glm::vec3& map : {across, along}) {
        for (size_t corner = 0; corner < model.indices.size(); ++corner) {
            const bool mirrored = onMirroredHalf(model, corner);
            const Layout half = mirrored ? mirroredLayout() : gltfLayout();
            const uint32_t v = model.indices[corner];
            const glm::vec3 bumped = perturbed(map, model.normals[v], model.tangents[v]);
            // Tilted as the map says, in this half's own UV directions: across the stripe
            // towards growing u (mirrored in the world), along it up the image (not mirrored).
            const glm::vec3 du = glm::vec3(analyticTangent(half)), up = analyticUp(half);
            const glm::vec3 expected = glm::normalize(du * map.x + up * map.y + kUp * map.z);
            EXPECT_NEAR(glm::length(bumped - expected), 0.0f, 1e-5f)
                << "corner " << corner << (mirrored ? ", mirrored" : "");
            // So a light on the stripe's sloped side, seen in each half's UVs, lights it on both.
            const glm::vec3 light = glm::normalize(du * map.x + up * map.y + kUp);
            EXPECT_GT(glm::dot(bumped, light), glm::dot(kUp, light)) << "corner " << corner;
        }
    }
}

TEST(Tangents, FanWhoseTangentsTurnRoundSplits) {
    // A disc with polar UVs, as at a UV sphere's pole made of one vertex: u runs round the rim,
    // so each face's dP/du is its rim chord and the tangents at the centre turn a full circle.
    const int sides = 8;
    Mesh disc;
    disc.positions = {glm::vec3(0.0f)};
    disc.uv0 = {{0.5f, 0.0f}};
    for (int k = 0; k <= sides; ++k) {   // the last repeats the first, at u = 1: the seam
        const float a = 2.0f * std::numbers::pi_v<float> * float(k % sides) / float(sides);
        disc.positions.emplace_back(std::cos(a), std::sin(a), 0.0f);
        disc.uv0.emplace_back(float(k) / float(sides), 1.0f);
    }
    disc.normals.assign(disc.positions.size(), kUp);
    for (uint32_t k = 1; k <= uint32_t(sides); ++k) {
        disc.indices.insert(disc.indices.end(), {0, k, k + 1});
    }
    const Mesh split = withTangents(disc, 0);
    expectValidTangents(split, split.tangents);
    EXPECT_GT(split.positions.size(), disc.positions.size());   // the centre, at least
    for (size_t corner = 0; corner < split.indices.size(); corner += 3) {
        const glm::vec3& rim = split.positions[split.indices[corner + 1]];
        const glm::vec3 chord = glm::normalize(split.positions[split.indices[corner + 2]] - rim);
        // Each face's centre corner keeps a tangent on the chord's side, not a cancelled sum.
        EXPECT_GT(glm::dot(glm::vec3(split.tangents[split.indices[corner]]), chord), 0.0f) << "face " << corner / 3;
    }
}

TEST(Tangents, CuttingAFaceLeavesTheVertexTangent) {
    // Two faces at the origin with UV maps that meet along x = 0 and give tangents 45 degrees
    // apart; the second is then cut in two through the origin (its angle there halved in
    // each), or away from it (its area at the origin halved). The origin's tangent is each
    // face's weighted by its angle there, so neither cut moves it.
    const Layout second{glm::mat2(3.0f, 1.0f, 0.0f, -1.0f), glm::vec2(0.0f, 1.0f)};
    const glm::vec2 origin(0.0f), right(1.0f, 0.0f), top(0.0f, 1.0f), left(-1.0f, 0.0f);
    auto tangentAtOrigin = [&](const std::vector<std::array<glm::vec2, 3>>& cut) {
        Mesh mesh;
        addTriangle(mesh, origin, right, top, gltfLayout());
        for (const std::array<glm::vec2, 3>& t : cut) {
            addTriangle(mesh, t[0], t[1], t[2], second);
        }
        EXPECT_EQ(mesh.positions.front(), glm::vec3(0.0f));
        const Mesh split = withTangents(mesh, 0);
        EXPECT_EQ(split.positions.size(), mesh.positions.size());   // one group at the origin
        return split.tangents.front();
    };
    const glm::vec4 whole = tangentAtOrigin({{origin, top, left}});
    const glm::vec2 edgeMiddle = 0.5f * (top + left), sideMiddle = 0.5f * left;
    const glm::vec4 throughIt = tangentAtOrigin({{origin, top, edgeMiddle}, {origin, edgeMiddle, left}});
    const glm::vec4 awayFromIt = tangentAtOrigin({{origin, top, sideMiddle}, {sideMiddle, top, left}});
    EXPECT_GT(glm::dot(glm::vec3(whole), glm::vec3(analyticTangent(gltfLayout()))), 0.9f);
    EXPECT_LT(glm::dot(glm::vec3(whole), glm::vec3(analyticTangent(gltfLayout()))), 0.99f);   // both faces count
    expectNear(throughIt, whole, "cut through the origin");
    expectNear(awayFromIt, whole, "cut away from the origin");
}

}  // namespace
}  // namespace patina
