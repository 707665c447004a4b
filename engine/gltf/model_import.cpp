#include "gltf/model_import.h"

#include <array>

#include "gltf/document.h"
#include "gltf/draws.h"
#include "gltf/images.h"
#include "gltf/model_materials.h"

namespace patina {

namespace {

std::array<TextureSlot*, 5> mapsOf(ModelMaterial& material) {
    return {&material.baseColor, &material.metallicRoughness, &material.normal, &material.occlusion, &material.emissive};
}

// Only the images a material uses are decoded; the slots then point into Model::images (or
// lose their map when the image could not be had).
void attachImages(const tinygltf::Model& document, Model& model, const std::string& source) {
    std::vector<bool> used(document.images.size(), false);
    for (ModelMaterial& material : model.materials) {
        for (TextureSlot* slot : mapsOf(material)) {
            if (slot->present()) {
                used[size_t(slot->image)] = true;
            }
        }
    }
    const std::vector<int> decoded = gltf::decodeImages(document, used, model, source);
    for (ModelMaterial& material : model.materials) {
        for (TextureSlot* slot : mapsOf(material)) {
            if (slot->present()) {
                slot->image = decoded[size_t(slot->image)];
            }
        }
    }
}

}  // namespace

Model importGltfModel(const std::filesystem::path& path) {
    const std::string source = path.string();
    const tinygltf::Model document = gltf::loadDocument(path, source);
    Model model = gltf::modelGeometry(document, source);
    model.materials = gltf::modelMaterials(document, source, model.notes);
    attachImages(document, model, source);
    return model;
}

}  // namespace patina
