#pragma once
// A loaded glTF model's triangles, in world space.
#include <string>

#include <tiny_gltf.h>

#include "geometry/mesh.h"

namespace patina::gltf {

// The default scene's (or scene 0's, or the root nodes') mesh primitives through the node
// hierarchy: TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN as triangles, points and lines
// skipped; missing normals generated. Every index and count is checked before it is used, the
// sizes against the limits in gltf_import.h before anything is allocated. Throws InputError.
Mesh meshFromModel(const tinygltf::Model& model, const std::string& source);

}  // namespace patina::gltf
