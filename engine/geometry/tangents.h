#pragma once
// MikkTSpace tangents (M. S. Mikkelsen, "Simulation of wrinkled surfaces revisited", master's
// thesis, University of Copenhagen, 2008, and the behaviour its reference implementation
// documents): the tangent frames normal maps are baked in, so a glTF primitive with a normal
// texture and no TANGENT reads its map back as it was baked.
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "geometry/mesh.h"

namespace patina {

// One tangent per vertex of `mesh` (Mesh::tangents' form) for its UVs of set `uvSet` (0: uv0,
// 1: uv1; another number, or a set the mesh lacks, has no UVs).
//
// The steps, as Mikkelsen's:
// - Vertices equal to the bit in position, normal and UV are one vertex (the reference welds
//   them), so a glTF primitive without indices gets smooth tangents too; a UV seam repeats a
//   position with other UVs, so the faces on its two sides never share a tangent.
// - Each face's tangent is its dP/du; its sign is +1 where its UVs, with v read up the image
//   (glTF's v grows down), wind as its corners do, and -1 on a mirrored face. That is the
//   right sign for faces wound counter-clockwise about their normals (glTF's front faces).
// - At a vertex, faces of one sign whose tangents, made orthogonal to the vertex's normal, lie
//   within 90 degrees of the group's first face's (in index order) form a group: the sum of
//   their tangents, weighted by each face's angle at the vertex, made unit, is the group's.
//   A mirrored face never shares a tangent with an unmirrored one; a fan whose tangents turn
//   right round (a pole with one vertex) splits instead of cancelling. (The reference's
//   default merges every face of one sign; the two differ only where faces at a vertex turn
//   more than 90 degrees apart, where its sum may cancel to noise.)
// - A face with no UV gradient (zero UV area) or no area joins the vertex's first group and
//   adds nothing; a vertex with no other face gets fallbackTangent(normal) and w = +1.
// A vertex whose faces form several groups takes its first corner's (in index order):
// withTangents gives each group its own vertex. A mesh without one normal per position uses
// smoothNormals; a triangle with an index outside the positions is left out.
// Every tangent is finite, its xyz unit and orthogonal to the vertex's normal, and w is +1 or
// -1: bitangent = cross(N, xyz) * w points up the normal map's image (its +Y).
std::vector<glm::vec4> mikkTSpaceTangents(const Mesh& mesh, int uvSet);

// `mesh` with `tangents` filled as mikkTSpaceTangents's, and a vertex whose faces form several
// groups split: each further group gets a copy of the vertex (positions, normals, uv0, uv1)
// at the end, with that group's tangent, and its faces' indices point at the copy. A mesh
// without normals gets the smooth ones it was given tangents for.
Mesh withTangents(Mesh mesh, int uvSet);

// The tangent where UVs give none: the coordinate axis least along `normal` (the first of x, y,
// z on a tie), made orthogonal to it and unit. That axis is at least 54 degrees from the normal,
// so the result never shrinks to nothing.
glm::vec3 fallbackTangent(const glm::vec3& normal);

}  // namespace patina
