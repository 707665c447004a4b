#include "material_renders.h"

#include "gl/headless_context.h"
#include "gl/renderer.h"
#include "inputs.h"
#include "mesh.h"

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

std::vector<LdrImage> renderMaterials(Scene scene, const std::vector<Material>& materials,
                                      int width, int height) {
    HeadlessContext context;
    Renderer renderer;
    renderer.setMesh(makeMesh(scene));
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    // The same image as single or multi to rounding, faster: materials of one scene share one
    // or two compiled shaders (with and without diffuse). Only the sRGB image is needed.
    settings.passes = PassMode::Specialised;
    settings.readHdr = false;
    std::vector<LdrImage> images;
    for (const Material& material : materials) {
        scene.material = material;
        images.push_back(renderer.render(scene, settings).ldr);
    }
    return images;
}

}  // namespace patina::cli
