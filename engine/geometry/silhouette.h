#pragma once
// The edges that outline a mesh seen from a point: where the surface turns from facing the
// eye to facing away, and where it ends. What the editor draws around a selected part.
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"

namespace patina {

// A mesh's edges with the faces on each side, made once for a mesh and asked from any eye.
// Corners at the same position are one (a seam of UVs or normals splits vertices, not the
// surface); triangles of no area are left out.
struct EdgeFaces {
    struct Edge {
        glm::vec3 a, b;
        int32_t left = -1, right = -1;   // its faces; right -1: a border; left -2: three or more faces
    };
    std::vector<Edge> edges;
    std::vector<glm::vec3> faceNormals, faceCorners;   // a face's plane: its (unnormalised) normal and a corner
};
EdgeFaces edgeFaces(const Mesh& mesh);

// The outline seen from `eye` (in the mesh's space): each edge between a face that faces the eye
// and one that does not, each border edge, and each edge of three or more faces.
std::vector<std::pair<glm::vec3, glm::vec3>> silhouetteEdges(const EdgeFaces& mesh, const glm::vec3& eye);

}  // namespace patina
