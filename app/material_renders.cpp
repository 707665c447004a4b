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

namespace {
// `scene` with `material` where the command puts it: the built-in meshes' material, and over a
// model its parts' (every part, or `part`'s).
void putMaterial(Scene& scene, const PreparedScene& prepared, const Material& material, const std::string& part) {
    scene.material = material;
    scene.modelMaterials = prepared.scene.modelMaterials;
    putMaterialOnParts(scene, prepared.model.get(), material, part);
}
}  // namespace

void renderMaterials(const PreparedScene& prepared, const std::vector<Material>& materials,
                     const MaterialRenders& options, const std::function<void(LdrImage&&)>& each) {
    Scene scene = prepared.scene;
    if (!materials.empty()) {
        putMaterial(scene, prepared, materials.front(), options.part);   // a bad --part fails here, before any render
    }
    HeadlessContext context;
    Renderer renderer;
    RenderSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    // The same image as single or multi to rounding, faster: materials of one scene share one
    // or two compiled shaders (with and without diffuse). Only the sRGB image is needed.
    settings.path = RenderPath::Specialised;
    settings.readHdr = false;
    for (const Material& material : materials) {
        putMaterial(scene, prepared, material, options.part);   // the mesh and the environment stay: loaded once for all
        each(renderer.render({scene, prepared.mesh, prepared.environment, prepared.model}, settings).ldr);
    }
}

std::vector<LdrImage> renderMaterials(const PreparedScene& prepared, const std::vector<Material>& materials,
                                      const MaterialRenders& options) {
    std::vector<LdrImage> images;
    renderMaterials(prepared, materials, options, [&](LdrImage&& image) { images.push_back(std::move(image)); });
    return images;
}

}  // namespace patina::cli
