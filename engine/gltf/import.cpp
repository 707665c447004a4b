#include "gltf/import.h"

#include "gltf/document.h"
#include "gltf/draws.h"
#include "gltf/flatten.h"
#include "gltf/material.h"

namespace patina {

// The same document, scene graph and primitives as importGltfModel (model_import.h), flattened;
// no image is decoded.
GltfImport importGltf(const std::filesystem::path& path) {
    const std::string source = path.string();
    const tinygltf::Model document = gltf::loadDocument(path, source);
    GltfImport result;
    result.mesh = gltf::flattenDraws(gltf::modelGeometry(document, source), source);
    if (!document.materials.empty()) {
        result.material = gltf::materialFromGltf(document.materials[0], "/materials/0", source, path.stem().string());
    }
    result.materialCount = document.materials.size();
    result.textureCount = document.textures.size();
    return result;
}

GltfImport flattenedImport(const Model& model, const std::filesystem::path& path) {
    GltfImport result;
    result.mesh = gltf::flattenDraws(model, path.string());
    if (!model.materials.empty()) {
        Material first;
        static_cast<MaterialParameters&>(first) = model.materials[0].factors;
        first.name = model.materials[0].name;
        result.material = first;
    }
    result.materialCount = model.materials.size();
    result.textureCount = model.images.size();   // the images its materials use, decoded
    return result;
}

}  // namespace patina
