#pragma once
// A glTF file's cameras as the default scene's nodes place them (glTF 2.0 section 3.10).
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "gltf/nodes.h"
#include "model/model.h"

namespace patina::gltf {

// Each camera node of the default scene as a ModelCamera, in node order: a camera placed by two
// nodes is listed twice. A node whose camera does not exist, or whose transform leaves no
// direction (a zero scale), is left out with a line in `notes`; so is a perspective camera
// without a yfov above 0. Orthographic cameras are listed (ModelCamera::perspective false).
std::vector<ModelCamera> modelCameras(const tinygltf::Model& document, const std::vector<CameraInstance>& instances,
                                      std::vector<std::string>& notes);

}  // namespace patina::gltf
