#pragma once
// glTF 2.0 import, .gltf and .glb, through tinygltf (docs/FORMATS.md, "glTF": what is read,
// the material mapping, the confinement rules and the limits).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "geometry/mesh.h"
#include "io/file_kinds.h"
#include "model/model.h"
#include "scene/material.h"

namespace patina {

constexpr size_t kGltfMaxVertices = size_t(16) << 20;     // over all node instances
constexpr size_t kGltfMaxTriangles = size_t(16) << 20;
constexpr size_t kGltfMaxPrimitives = size_t(256) << 10;    // mesh primitives drawn, instances counted

struct GltfImport {
    Mesh mesh;                          // world space, counter-clockwise, unit normals (flat without NORMAL)
    std::optional<Material> material;   // the file's first material, when it has one
    size_t materialCount = 0;           // all of the file's: Patina takes the first only
    size_t textureCount = 0;            // the file's textures; the flattened mesh takes none
};

// The triangles of every mesh primitive of the default scene (or scene 0, or every root node
// when there is no scene) with the node transforms applied, and the first material: the draws
// of importGltfModel's model (model_import.h) flattened, positions and normals only, no image
// decoded. Reads only regular files inside the model's folder. Throws InputError naming the
// file and what is wrong for anything it cannot use; nothing else changes.
GltfImport importGltf(const std::filesystem::path& path);

// What importGltf(path) returns, made from `model`, importGltfModel(path)'s result, so that a
// caller wanting both reads and parses the file once (the asset cache).
GltfImport flattenedImport(const Model& model, const std::filesystem::path& path);

}  // namespace patina
