#include "assets/model_loading.h"

namespace patina {

Model loadModel(const std::filesystem::path& path, const GltfImport& imported) {
    Model model;
    model.primitives.push_back(imported.mesh);
    DrawItem draw;
    draw.node = path.filename().string();
    if (imported.material) {
        ModelMaterial material;
        material.name = imported.material->name;
        material.factors = *imported.material;
        model.materials.push_back(material);
        draw.material = 0;
    }
    model.draws.push_back(draw);
    return model;
}

}  // namespace patina
