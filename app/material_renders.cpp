#include "material_renders.h"

#include "gl/headless_context.h"
#include "gl/renderer.h"
#include "inputs.h"

namespace patina::cli {

std::vector<Material> loadMaterials(const std::vector<std::string>& paths) {
    std::vector<Material> materials;
    for (const std::string& path : paths) {
        SceneInputs inputs;   // its load() reports the file's warnings as every command does
        inputs.materialPath = path;
        materials.push_back(inputs.load().material);
    }
    return materials;
}

void renderMaterials(const PreparedScene& prepared, const std::vector<Material>& materials, int width, int height,
                     const std::function<void(LdrImage&&)>& each) {
    HeadlessContext context;
    Renderer renderer;
    Scene scene = prepared.scene;
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    // The same image as single or multi to rounding, faster: materials of one scene share one
    // or two compiled shaders (with and without diffuse). Only the sRGB image is needed.
    settings.path = RenderPath::Specialised;
    settings.readHdr = false;
    for (const Material& material : materials) {
        scene.material = material;   // the mesh and the environment stay: loaded once for all
        // Each material over the whole shape: a model's flattened mesh without its draw items,
        // whose own materials would hide the one compared.
        each(renderer.render({scene, prepared.mesh, prepared.environment, nullptr}, settings).ldr);
    }
}

std::vector<LdrImage> renderMaterials(const PreparedScene& prepared, const std::vector<Material>& materials,
                                      int width, int height) {
    std::vector<LdrImage> images;
    renderMaterials(prepared, materials, width, height, [&](LdrImage&& image) { images.push_back(std::move(image)); });
    return images;
}

}  // namespace patina::cli
