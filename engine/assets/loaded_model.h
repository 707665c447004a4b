#pragma once
// A glTF model as the asset cache loads it (asset_cache.h): its file read and hashed once, the
// model it draws and the same draws flattened into one mesh.
#include <cstdint>
#include <string>

#include "geometry/mesh.h"
#include "model/model.h"

namespace patina {

struct LoadedModel {
    // What the file draws (gltf/model_import.h): its scene graph as draw items, primitives,
    // materials with their maps, images decoded.
    Model model;
    // `model`'s draws flattened into world space (gltf/flatten.h): what the camera frames and
    // what a caller showing one material over the whole shape draws.
    Mesh mesh;
    // What the cache knows the file by: its absolute, normal path and the hash of its bytes
    // (common/content_hash.h).
    std::string path;
    uint64_t hash = 0;
};

}  // namespace patina
