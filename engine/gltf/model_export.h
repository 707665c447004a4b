#pragma once
// glTF 2.0 export of a whole model: its draw items, materials and texture maps
// (docs/FORMATS.md, "glTF": export), so that importing the export draws the same.
#include <filesystem>
#include <vector>

#include "gltf/export.h"
#include "model/model.h"

namespace patina {

// The files of PATH for `model`: a .glb holds its buffer and its images (PNG) in the BIN
// chunk; a .gltf has its images beside it as PNG files (STEM_N.png, N the exported image's
// index) and its buffer as a data: URI or, with BinFile, in STEM.bin. Each draw item is a node
// of the scene with its world matrix, drawing a mesh of its primitive with its material; a
// matrix that no translation, rotation and scale make (a shear) is baked into the vertices
// instead, as glTF requires node matrices to decompose (5.25). Every material keeps its
// factors, maps, samplers, transforms, alpha, emission and sidedness. InputError for a path
// that ends in neither .gltf nor .glb, or a model with nothing to draw.
std::vector<OutputFile> encodeGltfModel(const std::filesystem::path& path, const Model& model,
                                        GltfBuffer buffer = GltfBuffer::Embedded);

// Writes encodeGltfModel's files as writeOutputFiles does: all or none.
void exportGltfModel(const std::filesystem::path& path, const Model& model, GltfBuffer buffer = GltfBuffer::Embedded);

}  // namespace patina
