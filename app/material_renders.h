#pragma once
#include <functional>
#include <string>
#include <vector>

#include "image/image.h"
#include "scene/prepared_scene.h"

namespace patina::cli {

// What compare and sheet share: every material file is read before anything is rendered, so
// a bad one fails fast and leaves no output.
// Warnings go to stderr; errors throw InputError.
std::vector<Material> loadMaterials(const std::vector<std::string>& paths);

// The prepared scene once per material, all with one headless context and one compiled
// renderer, each image handed to `each` as it is read back. Over a model each material goes on
// every part, or on the parts named `part` (setPartMaterials: each keeps its maps), the others
// as the scene has them. InputError, before anything is rendered, for a `part` that the scene
// has no model for or that its model lacks.
struct MaterialRenders {
    int width = 512, height = 512;
    std::string part;
};
void renderMaterials(const PreparedScene& prepared, const std::vector<Material>& materials,
                     const MaterialRenders& options, const std::function<void(LdrImage&&)>& each);
std::vector<LdrImage> renderMaterials(const PreparedScene& prepared, const std::vector<Material>& materials,
                                      const MaterialRenders& options);

}  // namespace patina::cli
