#pragma once
// Mesh primitives (glTF 2.0 section 3.7.2) as Patina's meshes, each in its mesh's own space:
// checked and counted first, read only once the whole model is known to fit the limits.
#include <cstddef>
#include <optional>
#include <string>

#include <tiny_gltf.h>

#include "geometry/mesh.h"
#include "gltf/accessor.h"
#include "gltf/draco.h"

namespace patina {

constexpr size_t kGltfMaxVertices = size_t(16) << 20;     // over all node instances
constexpr size_t kGltfMaxTriangles = size_t(16) << 20;
constexpr size_t kGltfMaxPrimitives = size_t(256) << 10;    // mesh primitives drawn, instances counted

}  // namespace patina

namespace patina::gltf {

// One primitive's accessors, checked (types, views, counts); nothing read yet.
struct PrimitivePlan {
    std::string where;   // "/meshes/M/primitives/P"
    int mode = TINYGLTF_MODE_TRIANGLES;
    int material = -1;
    CheckedAccessor positions;
    std::optional<CheckedAccessor> normals, tangents, indices;
    std::optional<CheckedAccessor> texCoords[2];
    std::optional<CheckedAccessor> colors;   // COLOR_0: 3 or 4 components
    size_t triangles = 0;
    // KHR_draco_mesh_compression: the stream the compressed accessors are decoded from when the
    // primitive is read (their own views, if any, are the file's uncompressed fallback).
    std::optional<DracoStream> draco;
};

// Why the primitive draws no triangles ("points", "lines", "no POSITION"), or "" when it does.
// Throws InputError for a mode glTF does not define.
std::string whyNotDrawn(const tinygltf::Primitive& primitive, const std::string& where, const std::string& source);

// A primitive that draws triangles, planned: a Draco-compressed one by its accessors' counts,
// its stream checked inside its buffer but not yet decoded. Throws InputError naming the
// accessor or index.
PrimitivePlan planPrimitive(const tinygltf::Model& model, int mesh, int primitive, const std::string& source);

// The planned primitive read: triangles counter-clockwise (strips and fans in glTF's order),
// unit normals, TEXCOORD_0 / _1 into uv0 / uv1, TANGENT and COLOR_0, each attribute either absent or one
// per position. Without NORMAL, flat normals (section 3.7.2.1), which may copy vertices: more
// than kGltfMaxVertices is refused. A Draco-compressed primitive is decoded first, its stream
// holding as many points and corners as its accessors say. Throws InputError for an index out
// of range or a number that is not finite.
Mesh readPrimitive(const PrimitivePlan& plan, const std::string& source);

}  // namespace patina::gltf
