#pragma once
#include <filesystem>

#include "gltf/import.h"
#include "model/model.h"

namespace patina {

// The Model a glTF file draws (model/model.h): the one place the assets layer makes one.
// Until gltf/model_import.h's importGltfModel(path) takes its place, it is made from
// `imported`, importGltf's result for `path` (so the file is read once): one primitive, the
// flattened world-space mesh, drawn once where it is, with the file's first material's factors
// (glTF's default material when the file has none). What that import leaves out (the
// material's alpha mode and sides) takes glTF's defaults: opaque, single-sided.
Model loadModel(const std::filesystem::path& path, const GltfImport& imported);

}  // namespace patina
