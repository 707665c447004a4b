// The outline of a mesh seen from a point (engine/geometry/silhouette.h): the edges where the
// surface turns away, found across split vertices.
#include <algorithm>

#include <gtest/gtest.h>

#include "geometry/silhouette.h"
#include "gltf_builder.h"

namespace patina {
namespace {

Mesh cubeMesh() {   // each face with its own four vertices, as a hard-edged cube is stored
    const test::Cube cube;
    Mesh mesh;
    mesh.positions = cube.positions;
    mesh.normals = cube.normals;
    mesh.indices = cube.indices;
    return mesh;
}

bool hasSegment(const std::vector<std::pair<glm::vec3, glm::vec3>>& outline, glm::vec3 a, glm::vec3 b) {
    return std::any_of(outline.begin(), outline.end(), [&](const auto& s) {
        return (s.first == a && s.second == b) || (s.first == b && s.second == a);
    });
}

TEST(Silhouette, ACubeSeenFaceOnIsOutlinedByThatFacesFourEdges) {
    const EdgeFaces edges = edgeFaces(cubeMesh());
    EXPECT_EQ(edges.edges.size(), 18u);   // 12 sides and 6 diagonals: the split corners are welded
    const auto outline = silhouetteEdges(edges, glm::vec3(0.0f, 0.0f, 10.0f));
    ASSERT_EQ(outline.size(), 4u);
    for (const auto& [a, b] : outline) {
        EXPECT_EQ(a.z, 0.5f);
        EXPECT_EQ(b.z, 0.5f);
        EXPECT_NE(a.x == b.x, a.y == b.y) << "a side, not the diagonal";
    }
    // Seen from a corner, six edges of the hexagon it shows.
    EXPECT_EQ(silhouetteEdges(edges, glm::vec3(10.0f)).size(), 6u);
}

TEST(Silhouette, AnOpenBorderIsAlwaysOutlinedAndAFaceOfNoAreaIsNot) {
    Mesh quad;
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 2, 2}};
    quad.normals.assign(5, glm::vec3(0, 0, 1));
    quad.indices = {0, 1, 2, 0, 2, 3, 4, 4, 4};
    const auto outline = silhouetteEdges(edgeFaces(quad), glm::vec3(0.5f, 0.5f, -3.0f));
    EXPECT_EQ(outline.size(), 4u);
    EXPECT_TRUE(hasSegment(outline, {0, 0, 0}, {1, 0, 0}));
    EXPECT_FALSE(hasSegment(outline, {0, 0, 0}, {1, 1, 0}));
}

}  // namespace
}  // namespace patina
