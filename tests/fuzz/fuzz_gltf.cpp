// glTF import of one model file, written for each input to PATINA_FUZZ_MODEL in a folder of
// its own (importGltf reads files only, inside the model's folder). Refusals are InputErrors;
// anything else, or a mesh that breaks the import's promises, is a bug.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <glm/geometric.hpp>

#include "gltf/import.h"
#include "geometry/hidden_faces.h"
#include "io/input_error.h"
#include "scratch_folder.h"

namespace {
const std::filesystem::path& modelPath() {
    static const std::filesystem::path path = patina::fuzz::scratchFolder() / PATINA_FUZZ_MODEL;
    return path;
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    {
        std::ofstream file(modelPath(), std::ios::binary | std::ios::trunc);
        file.write(reinterpret_cast<const char*>(data), std::streamsize(size));
        if (!file) {
            std::abort();
        }
    }
    patina::GltfImport model;
    try {
        model = patina::importGltf(modelPath());
    } catch (const patina::InputError&) {
        return 0;
    }
    // gltf_import.h: triangles, a unit normal for every position, indices in range.
    const patina::Mesh& mesh = model.mesh;
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0 || mesh.normals.size() != mesh.positions.size()) {
        std::abort();
    }
    for (const uint32_t index : mesh.indices) {
        if (index >= mesh.positions.size()) {
            std::abort();
        }
    }
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        if (!finite(mesh.positions[i]) || std::abs(glm::length(mesh.normals[i]) - 1.0f) > 1e-3f) {
            std::abort();
        }
    }
    // What the renderer culls (hidden_faces.h) turns over with the winding: every triangle
    // reversed hides the other side, or still none, and is as convex as before.
    const patina::FaceCulling culling = patina::faceCulling(mesh),
                              flipped = patina::faceCulling(patina::reversedWinding(mesh));
    using patina::HiddenFaces;
    if (flipped.hidden != (culling.hidden == HiddenFaces::Back    ? HiddenFaces::Front
                           : culling.hidden == HiddenFaces::Front ? HiddenFaces::Back
                                                                  : HiddenFaces::None) ||
        flipped.convex != culling.convex || (culling.convex && culling.hidden == HiddenFaces::None)) {
        std::abort();
    }
    return 0;
}
