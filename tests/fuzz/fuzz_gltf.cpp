// glTF import of one model file, written for each input to PATINA_FUZZ_MODEL in a folder of
// its own (the import reads files only, inside the model's folder): the whole model
// (importGltfModel), exported again, and its draws flattened into one mesh (gltf/flatten.h).
// Refusals are InputErrors; anything else, or a result that breaks the import's promises, is a bug.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "gltf/flatten.h"
#include "gltf/model_export.h"
#include "gltf/model_import.h"
#include "geometry/hidden_faces.h"
#include "files/input_error.h"
#include "scratch_folder.h"

namespace {
const std::filesystem::path& modelPath() {
    static const std::filesystem::path path = patina::fuzz::scratchFolder() / PATINA_FUZZ_MODEL;
    return path;
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// model.h's promises: attributes absent or one per position, indices in range, every index of
// a draw or a map pointing at something, images the size they say.
bool wellFormed(const patina::Mesh& mesh) {
    const size_t n = mesh.positions.size();
    auto absentOrOnePer = [n](size_t size) { return size == 0 || size == n; };
    if (mesh.normals.size() != n || !absentOrOnePer(mesh.uv0.size()) || !absentOrOnePer(mesh.uv1.size()) ||
        !absentOrOnePer(mesh.tangents.size()) || mesh.indices.size() % 3 != 0) {
        return false;
    }
    for (const uint32_t index : mesh.indices) {
        if (index >= n) {
            return false;
        }
    }
    return true;
}

bool wellFormed(const patina::Model& model) {
    for (const patina::Mesh& primitive : model.primitives) {
        if (!wellFormed(primitive)) {
            return false;
        }
    }
    for (const patina::DrawItem& draw : model.draws) {
        if (draw.primitive < 0 || size_t(draw.primitive) >= model.primitives.size() || draw.material < -1 ||
            draw.material >= int(model.materials.size()) ||
            (glm::determinant(glm::dmat3(glm::dmat4(draw.transform))) < 0.0) != draw.mirrored) {
            return false;
        }
    }
    for (const patina::ModelMaterial& material : model.materials) {
        for (const patina::TextureSlot* slot : {&material.baseColor, &material.metallicRoughness, &material.normal,
                                                &material.occlusion, &material.emissive}) {
            if (slot->image >= int(model.images.size()) || slot->texCoord < 0 || slot->texCoord > 1) {
                return false;
            }
        }
    }
    for (const patina::ModelImage& image : model.images) {
        if (image.rgba.size() != size_t(image.width) * size_t(image.height) * 4) {
            return false;
        }
    }
    return !model.draws.empty();
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
    std::optional<patina::Model> imported;
    try {
        imported = patina::importGltfModel(modelPath());
    } catch (const patina::InputError&) {
        return 0;
    }
    if (!wellFormed(*imported)) {
        std::abort();
    }
    // Whatever imports exports (its images as PNG too): the export refuses only a model with no
    // triangles to draw.
    try {
        patina::encodeGltfModel("fuzz.glb", *imported);
    } catch (const patina::InputError&) {
    }
    // Its draws flattened, as the asset cache loads them beside it.
    patina::Mesh mesh;
    try {
        mesh = patina::gltf::flattenDraws(*imported, modelPath().string());
    } catch (const patina::InputError&) {
        return 0;
    }
    // gltf/flatten.h: triangles, a unit normal for every position, indices in range.
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
