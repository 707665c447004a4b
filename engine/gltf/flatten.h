#pragma once
// A model's draws as one mesh in world space: what the asset cache loads beside the model
// (assets/asset_cache.h), what the camera frames and the one-material view draws.
#include <string>

#include "geometry/mesh.h"
#include "model/model.h"

namespace patina::gltf {

// Every draw's primitive through its transform: positions, unit normals through the cofactor
// matrix (the inverse transpose up to scale, defined also for a zero scale), and the triangles
// of a mirrored draw reversed so that they stay counter-clockwise. Positions, normals and
// indices only. Throws InputError naming the node when a position overflows a float.
Mesh flattenDraws(const Model& model, const std::string& source);

}  // namespace patina::gltf
