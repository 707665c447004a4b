#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace patina {

// The built-in meshes.
enum class MeshKind { Sphere, Torus };
std::string_view meshKindName(MeshKind mesh);
std::optional<MeshKind> meshKindFromName(std::string_view name);

// An indexed triangle mesh with per-vertex normals (world space for the built-in meshes and a
// flattened model; a model's primitive is in its own space, placed by its draw's transform).
// The optional attributes are empty when the mesh has none, else one per position.
struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<uint32_t> indices;
    std::vector<glm::vec2> uv0, uv1;     // glTF TEXCOORD_0 / _1: (0, 0) the image's top-left
    std::vector<glm::vec4> tangents;     // xyz unit, w = +-1: bitangent = cross(N, T.xyz) * w
    // glTF COLOR_0, linear RGBA (an RGB accessor's alpha 1): multiplies the base colour and its
    // alpha (glTF 2.0 section 3.9.2).
    std::vector<glm::vec4> colors;
};

// Unit sphere at the origin: `rings` latitude bands, `segments` longitude bands.
Mesh makeUvSphere(int rings = 64, int segments = 128);
// Torus around the y axis: major radius R, tube radius r.
Mesh makeTorus(float majorRadius = 0.75f, float minorRadius = 0.3f, int rings = 96,
               int segments = 48);
Mesh makeMesh(MeshKind kind);
// The built-in mesh of `kind`, made once and shared: every scene of that kind draws these very
// triangles (immutable, so sharing them is safe across threads).
std::shared_ptr<const Mesh> builtinMesh(MeshKind kind);
// Every triangle wound the other way (its last two corners swapped): front faces turn back.
Mesh reversedWinding(Mesh mesh);

// `n` at length 1, or +y when it has no direction (zero or not finite); correct to rounding
// also where its squared length would overflow or underflow a float (components above 1e19
// or below 1e-19).
glm::vec3 unitNormal(const glm::vec3& n);

// Area-weighted vertex normals of `positions` over `triangles` (three indices each); a vertex
// on no triangle of non-zero area gets +y.
std::vector<glm::vec3> smoothNormals(std::span<const glm::vec3> positions,
                                     std::span<const uint32_t> triangles);

// The axis-aligned box around every position; low > high (empty) for a mesh with none.
struct BoundingBox {
    glm::vec3 low{1.0f}, high{-1.0f};
    bool empty() const { return low.x > high.x; }
};
BoundingBox boundingBox(const Mesh& mesh);

// Where the camera frames a mesh: the centre of its bounding box and the distance from there
// to the farthest vertex.
struct BoundingSphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};
BoundingSphere boundingSphere(const Mesh& mesh);

}  // namespace patina
