#pragma once
// glTF 2.0 export of a mesh with a material (docs/FORMATS.md, "glTF": export).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "gltf/output_files.h"
#include "scene/material.h"
#include "geometry/mesh.h"

namespace patina {

// Where a .gltf keeps its buffer. A .glb always holds it in its BIN chunk.
enum class GltfBuffer { Embedded, BinFile };   // a base64 data: URI, or PATH.bin beside it

// The files of PATH: a .glb, or a .gltf and with BinFile its .bin. One node, one mesh of one
// indexed triangle primitive (POSITION, NORMAL), one pbrMetallicRoughness material with
// KHR_materials_specular and KHR_materials_ior (gltf/material.h): encodeGltfModel's file of
// a model of one draw. InputError for a path that ends in neither .gltf nor .glb, or an empty
// mesh.
std::vector<OutputFile> encodeGltf(const std::filesystem::path& path, const Mesh& mesh,
                                   const Material& material, GltfBuffer buffer = GltfBuffer::Embedded);

// Writes encodeGltf's files, each atomically, the .bin first; if one cannot be written, those
// written before it are removed again. Throws std::runtime_error naming the path.
void exportGltf(const std::filesystem::path& path, const Mesh& mesh, const Material& material,
                GltfBuffer buffer = GltfBuffer::Embedded);

}  // namespace patina
