#pragma once
// A whole glTF 2.0 model, .gltf or .glb: its scene graph as draw items, its primitives with
// their UVs and tangents, all its materials with their texture maps, and the images they use,
// decoded (docs/FORMATS.md, "glTF": what is read, the conventions, the limits).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "common/progress.h"
#include "model/model.h"

namespace patina {

// The default scene (`scene`, else scene 0, else every root node) of the model at `path`: a
// DrawItem for every node that shows a mesh and each of its primitives, each primitive read
// once in its mesh's space. Reads only regular files inside the model's folder, within the
// limits of primitives.h and images.h. What Patina leaves out (points and lines, a map whose image
// is missing or cannot be decoded, an image format it does not read) is a line in
// Model::notes; anything else it cannot use throws InputError naming the file and the place.
Model importGltfModel(const std::filesystem::path& path);
// The same, telling `progress` the share of its images decoded (the slowest step of a model
// with large maps); nothing when `progress` stops it.
std::optional<Model> importGltfModel(const std::filesystem::path& path, const Progress& progress);
// The same from the model file's `bytes`, read already (gltf/files.h readModelFile): the asset
// cache reads a file once, to hash it and to import it.
std::optional<Model> importGltfModel(const std::filesystem::path& path, const std::vector<uint8_t>& bytes,
                                     const Progress& progress);

}  // namespace patina
