// Which faces of a mesh no outside eye can see (hidden_faces.h): only for closed meshes.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "geometry/hidden_faces.h"

namespace patina {
namespace {

// A unit cube [0, 1]^3 with four vertices of its own per face (flat normals, as a glTF cube
// has), wound counter-clockwise seen from outside.
Mesh splitCube() {
    Mesh mesh;
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = sign;
            glm::vec3 u(0.0f);
            u[(axis + 1) % 3] = 1.0f;
            const glm::vec3 v = glm::cross(n, u);   // u x v = n: counter-clockwise about n
            const glm::vec3 centre = glm::vec3(0.5f) + 0.5f * n;
            const auto base = uint32_t(mesh.positions.size());
            for (glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                mesh.positions.push_back(centre + 0.5f * (corner.x * u + corner.y * v));
                mesh.normals.push_back(n);
            }
            mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    }
    return mesh;
}

// Both meshes in one, the second moved by `offset`.
Mesh merged(Mesh a, const Mesh& b, glm::vec3 offset) {
    const auto base = uint32_t(a.positions.size());
    for (size_t v = 0; v < b.positions.size(); ++v) {
        a.positions.push_back(b.positions[v] + offset);
        a.normals.push_back(b.normals[v]);
    }
    for (uint32_t index : b.indices) {
        a.indices.push_back(base + index);
    }
    return a;
}

TEST(HiddenFaces, BuiltInMeshesHideTheirBackFaces) {
    // Their seams and poles repeat positions: that only holds if the copies are equal to the bit.
    EXPECT_EQ(hiddenFaces(makeUvSphere()), HiddenFaces::Back);
    EXPECT_EQ(hiddenFaces(makeUvSphere(3, 5)), HiddenFaces::Back);
    EXPECT_EQ(hiddenFaces(makeTorus()), HiddenFaces::Back);
}

TEST(HiddenFaces, VerticesAtOnePositionAreOneVertex) {
    Mesh cube = splitCube();
    EXPECT_EQ(hiddenFaces(cube), HiddenFaces::Back);
    // -0 and +0 are one position.
    for (glm::vec3& p : cube.positions) {
        if (p.x == 0.0f) {
            p.x = -0.0f;
            break;
        }
    }
    EXPECT_EQ(hiddenFaces(cube), HiddenFaces::Back);
}

TEST(HiddenFaces, InwardWindingHidesTheFrontFaces) {
    EXPECT_EQ(hiddenFaces(reversedWinding(makeUvSphere(8, 16))), HiddenFaces::Front);
    EXPECT_EQ(hiddenFaces(reversedWinding(splitCube())), HiddenFaces::Front);
}

TEST(HiddenFaces, OpenMeshesShowEveryFace) {
    Mesh sphere = makeUvSphere(8, 16);
    // A hole at the equator (a pole's triangles are half degenerate: they leave no hole).
    const size_t middle = sphere.indices.size() / 6 * 3;
    sphere.indices.erase(sphere.indices.begin() + std::ptrdiff_t(middle), sphere.indices.begin() + std::ptrdiff_t(middle) + 3);
    EXPECT_EQ(hiddenFaces(sphere), HiddenFaces::None);
    Mesh quad = splitCube();
    quad.indices.resize(6);
    EXPECT_EQ(hiddenFaces(quad), HiddenFaces::None);
    EXPECT_EQ(hiddenFaces(Mesh{}), HiddenFaces::None);
}

TEST(HiddenFaces, InconsistentWindingShowsEveryFace) {
    Mesh cube = splitCube();
    std::swap(cube.indices[1], cube.indices[2]);   // one triangle the other way round
    EXPECT_EQ(hiddenFaces(cube), HiddenFaces::None);
}

TEST(HiddenFaces, AnEdgeOfMoreThanTwoTrianglesShowsEveryFace) {
    // Two cubes meeting along one edge: closed each, but that edge joins four triangles.
    EXPECT_EQ(hiddenFaces(merged(splitCube(), splitCube(), {1.0f, 1.0f, 0.0f})), HiddenFaces::None);
    // A triangle twice.
    Mesh cube = splitCube();
    cube.indices.insert(cube.indices.end(), {cube.indices[0], cube.indices[1], cube.indices[2]});
    EXPECT_EQ(hiddenFaces(cube), HiddenFaces::None);
}

TEST(HiddenFaces, EveryPartMustWindTheSameWay) {
    const Mesh cube = splitCube();
    EXPECT_EQ(hiddenFaces(merged(cube, cube, {3.0f, 0.0f, 0.0f})), HiddenFaces::Back);
    EXPECT_EQ(hiddenFaces(merged(cube, reversedWinding(cube), {3.0f, 0.0f, 0.0f})), HiddenFaces::None);
    // A part far from the origin keeps its sign.
    EXPECT_EQ(hiddenFaces(merged(cube, cube, {1e6f, 0.0f, 0.0f})), HiddenFaces::Back);
}

// Parts are joined across edges, not corners: a cube wound inward that touches an outward
// one at a corner, or a two-sided fin hung off a corner, is a part of its own.
TEST(HiddenFaces, PartsTouchingAtACornerAreJudgedApart) {
    const Mesh cube = splitCube();
    Mesh small = splitCube();
    for (glm::vec3& p : small.positions) {
        p *= 0.5f;
    }
    EXPECT_EQ(hiddenFaces(merged(cube, small, {1.0f, 1.0f, 1.0f})), HiddenFaces::Back);
    EXPECT_EQ(hiddenFaces(merged(cube, reversedWinding(small), {1.0f, 1.0f, 1.0f})), HiddenFaces::None);
    Mesh fin = cube;
    const auto base = uint32_t(fin.positions.size());
    fin.positions.insert(fin.positions.end(), {{1.0f, 1.0f, 1.0f}, {2.0f, 1.0f, 1.0f}, {1.0f, 2.0f, 1.0f}});
    fin.normals.resize(fin.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    fin.indices.insert(fin.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 1});
    EXPECT_EQ(hiddenFaces(fin), HiddenFaces::None);
}

TEST(HiddenFaces, TwoSidesOfOneSheetShowEither) {
    // A square and the same square the other way round: closed, but enclosing nothing.
    Mesh quad = splitCube();
    quad.indices.resize(6);
    EXPECT_EQ(hiddenFaces(merged(quad, reversedWinding(quad), glm::vec3(0.0f))), HiddenFaces::None);
}

// An octahedron with its top corner at height `top` (below 0: a dent).
Mesh octahedron(float top) {
    Mesh mesh;
    mesh.positions = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, top}, {0, 0, -1}};
    mesh.normals = mesh.positions;
    for (uint32_t i = 0; i < 4; ++i) {
        const uint32_t next = (i + 1) % 4;
        mesh.indices.insert(mesh.indices.end(), {i, next, 4, next, i, 5});
    }
    return mesh;
}

// Convex: one part whose edges all fold away from the visible side (or lie flat, as a cube's
// faces and a UV sphere's quads do); then the renderer needs no depth test once it culls.
TEST(HiddenFaces, ConvexOnlyForOnePartThatNeverFoldsTowardsTheEye) {
    for (const Mesh& mesh : {makeUvSphere(), makeUvSphere(3, 5), splitCube(), octahedron(1.0f), octahedron(0.3f)}) {
        EXPECT_EQ(faceCulling(mesh).hidden, HiddenFaces::Back);
        EXPECT_TRUE(faceCulling(mesh).convex);
        EXPECT_EQ(faceCulling(reversedWinding(mesh)).hidden, HiddenFaces::Front);
        EXPECT_TRUE(faceCulling(reversedWinding(mesh)).convex);
    }
    const Mesh dented = octahedron(-0.3f);
    EXPECT_EQ(faceCulling(dented).hidden, HiddenFaces::Back);
    EXPECT_FALSE(faceCulling(dented).convex);
    EXPECT_FALSE(faceCulling(reversedWinding(dented)).convex);
    EXPECT_FALSE(faceCulling(makeTorus()).convex);
    EXPECT_FALSE(faceCulling(merged(splitCube(), splitCube(), {3.0f, 0.0f, 0.0f})).convex);   // two parts
    Mesh open = makeUvSphere(8, 16);
    open.indices.resize(open.indices.size() / 2);
    EXPECT_FALSE(faceCulling(open).convex);
}

TEST(HiddenFaces, TrianglesThatCoverNothingDoNotCount) {
    Mesh cube = splitCube();
    cube.indices.insert(cube.indices.end(), {0, 0, 1});
    EXPECT_EQ(hiddenFaces(cube), HiddenFaces::Back);
}

TEST(HiddenFaces, BadInputShowsEveryFace) {
    Mesh cube = splitCube();
    cube.indices.push_back(uint32_t(cube.positions.size()));   // out of range, and not a triangle
    cube.indices.insert(cube.indices.end(), {0, 1});
    EXPECT_EQ(hiddenFaces(cube), HiddenFaces::None);
    cube = splitCube();
    cube.positions[0].x = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(hiddenFaces(cube), HiddenFaces::None);
}

}  // namespace
}  // namespace patina
