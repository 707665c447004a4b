#pragma once
// A model's geometry: its primitives, each read once in its mesh's space, and a draw item for
// every (node instance, primitive) of the default scene (glTF 2.0 sections 3.5 and 3.7).
#include <string>

#include <tiny_gltf.h>

#include "model/model.h"

namespace patina::gltf {

// The primitives, draws, cameras and notes of a Model (its materials and images are left empty). The
// counts are checked against the kGltfMax* limits of primitives.h, instances counted, before any
// primitive is read. Points and lines are skipped with a note. Throws InputError, also for a
// scene without triangles.
Model modelGeometry(const tinygltf::Model& document, const std::string& source);

}  // namespace patina::gltf
