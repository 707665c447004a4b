#pragma once
#include <string>
#include <vector>

#include "image.h"
#include "scene.h"

namespace patina::cli {

// What compare and sheet share: every material file is read before anything is rendered, so
// a bad one fails fast and leaves no output.
// Warnings go to stderr; errors throw InputError.
std::vector<Material> loadMaterials(const std::vector<std::string>& paths);

// The scene once per material, all with one headless context and one compiled renderer.
std::vector<LdrImage> renderMaterials(Scene scene, const std::vector<Material>& materials,
                                      int width, int height);

}  // namespace patina::cli
