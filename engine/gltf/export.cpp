#include "gltf/export.h"

#include "gltf/model_export.h"
#include "io/file_kinds.h"
#include "files/input_error.h"

namespace patina {

namespace fs = std::filesystem;

std::vector<OutputFile> encodeGltf(const fs::path& path, const Mesh& mesh, const Material& material,
                                   GltfBuffer buffer) {
    if (gltfExtension(path).empty()) {
        throw InputError(path.string() + ": a glTF file must end in .gltf or .glb");
    }
    if (mesh.positions.empty() || mesh.indices.empty() || mesh.normals.size() != mesh.positions.size()) {
        throw InputError(path.string() + ": nothing to export: the mesh has no triangles");
    }
    // The model of one draw of the mesh with the material: written as every model is.
    Model model;
    model.primitives = {Mesh{mesh.positions, mesh.normals, mesh.indices, {}, {}, {}}};
    ModelMaterial written;
    written.name = material.name;
    written.factors = material;
    model.materials = {written};
    model.draws = {DrawItem{0, 0, glm::mat4(1.0f), ""}};
    return encodeGltfModel(path, model, buffer);
}

void exportGltf(const fs::path& path, const Mesh& mesh, const Material& material, GltfBuffer buffer) {
    writeOutputFiles(encodeGltf(path, mesh, material, buffer));
}

}  // namespace patina
