#include "gltf/model_import.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "gltf/document.h"
#include "gltf/draws.h"
#include "gltf/extensions.h"
#include "gltf/files.h"
#include "gltf/images.h"
#include "gltf/model_materials.h"
#include "geometry/tangents.h"

namespace patina {

namespace {

// Only the images a material uses are decoded; the slots then point into Model::images (or
// lose their map when the image could not be had).
// False when `progress` stopped the decoding.
bool attachImages(const tinygltf::Model& document, Model& model, const std::string& source, const Progress& progress) {
    auto forEachSlot = [&](auto visit) {
        for (ModelMaterial& material : model.materials) {
            for (const auto& map : mapsOf(material)) {
                visit(*map.slot);
            }
        }
    };
    std::vector<bool> used(document.images.size(), false);
    forEachSlot([&](const TextureSlot& slot) {
        if (slot.present()) {
            used[size_t(slot.image)] = true;
        }
    });
    const std::optional<std::vector<int>> decoded = gltf::decodeImages(document, used, model, source, progress);
    if (!decoded) {
        return false;
    }
    forEachSlot([&](TextureSlot& slot) {
        if (slot.present()) {
            slot.image = (*decoded)[size_t(slot.image)];
        }
    });
    return true;
}

// glTF 2.0 section 3.7.2.1: a normal-mapped primitive without TANGENT gets MikkTSpace
// tangents, the frames the map was baked in, for the UV set its (first drawn) normal map reads:
// the material's, else its clear coat's (KHR_materials_clearcoat's clearcoatNormalTexture).
// An anisotropic one (KHR_materials_anisotropy: its direction turns from the tangent) gets them
// too, for its anisotropy map's UV set, else the first.
void addMissingTangents(Model& model) {
    std::vector<int> normalUvSet(model.primitives.size(), -1);
    for (const DrawItem& draw : model.draws) {
        if (draw.material < 0 || normalUvSet[size_t(draw.primitive)] >= 0) {
            continue;
        }
        const ModelMaterial& material = model.materials[size_t(draw.material)];
        const TextureSlot& normal = material.normal.present() ? material.normal : material.clearcoatNormal;
        if (normal.present()) {
            normalUvSet[size_t(draw.primitive)] = normal.texCoord;
        } else if (material.factors.anisotropyStrength > 0.0f) {
            normalUvSet[size_t(draw.primitive)] = material.anisotropyMap.present() ? material.anisotropyMap.texCoord : 0;
        }
    }
    for (size_t i = 0; i < model.primitives.size(); ++i) {
        Mesh& primitive = model.primitives[i];
        const int uvSet = normalUvSet[i];
        const bool hasUvs = (uvSet == 0 && !primitive.uv0.empty()) || (uvSet == 1 && !primitive.uv1.empty());
        if (uvSet >= 0 && hasUvs && primitive.tangents.empty()) {
            primitive = withTangents(std::move(primitive), uvSet);
        }
    }
}

// Every extension the file uses, and a note for each whose effect the picture lacks.
void tellExtensions(const tinygltf::Model& document, Model& model) {
    model.extensions = gltf::modelExtensions(document.extensionsUsed, document.extensionsRequired);
    for (const ModelExtension& extension : model.extensions) {
        if (extension.support == ExtensionSupport::NotDrawn || extension.support == ExtensionSupport::Unknown) {
            model.notes.push_back("uses " + gltf::extensionLine(extension));
        }
    }
}

// Whether any texel of the image is less than opaque.
bool seeThrough(const ModelImage& image) {
    for (size_t i = 3; i < image.rgba.size(); i += 4) {
        if (image.rgba[i] < 255) {
            return true;
        }
    }
    return false;
}

// A note for each BLEND material whose alpha varies over the surface (its base colour map's, or
// its primitives' vertex colours'): Patina composites a BLEND item by its factor's alpha alone
// (docs/FORMATS.md), so the file's per-pixel transparency (a decal's edge, a leaf's cut-out)
// is not drawn, and the picture shows it opaque where the factor is 1.
void tellBlendedAlpha(Model& model) {
    for (size_t m = 0; m < model.materials.size(); ++m) {
        const ModelMaterial& material = model.materials[m];
        if (material.alphaMode != AlphaMode::Blend) {
            continue;
        }
        const int image = material.baseColor.image;
        bool varies = image >= 0 && size_t(image) < model.images.size() && seeThrough(model.images[size_t(image)]);
        for (const DrawItem& draw : model.draws) {
            if (draw.material == int(m) && size_t(draw.primitive) < model.primitives.size()) {
                const std::vector<glm::vec4>& colors = model.primitives[size_t(draw.primitive)].colors;
                varies |= std::any_of(colors.begin(), colors.end(), [](const glm::vec4& c) { return c.a < 1.0f; });
            }
        }
        if (varies) {
            char alpha[32];
            std::snprintf(alpha, sizeof alpha, "%.3g", double(material.baseAlpha));
            model.notes.push_back("material \"" + material.name + "\" is BLEND with a varying alpha: Patina blends it by "
                                  "its factor's alpha (" + alpha + ") alone, not its map's or vertex colours' alpha "
                                  "pixel by pixel");
        }
    }
}

}  // namespace

std::optional<Model> importGltfModel(const std::filesystem::path& path, const std::vector<uint8_t>& bytes,
                                     const Progress& progress) {
    const std::string source = path.string();
    const tinygltf::Model document = gltf::loadDocument(path, bytes, source);
    Model model = gltf::modelGeometry(document, source);
    tellExtensions(document, model);
    std::vector<gltf::SpecGlossMaterial> specGloss;
    model.materials = gltf::modelMaterials(document, source, model.notes, &specGloss);
    if (!attachImages(document, model, source, progress)) {
        return std::nullopt;
    }
    gltf::convertSpecularGlossiness(model, specGloss, gltf::kGltfMaxImageBytes);
    tellBlendedAlpha(model);
    addMissingTangents(model);
    return model;
}

std::optional<Model> importGltfModel(const std::filesystem::path& path, const Progress& progress) {
    return importGltfModel(path, gltf::readModelFile(path), progress);
}

Model importGltfModel(const std::filesystem::path& path) {
    return *importGltfModel(path, Progress{});   // nothing stops it
}

}  // namespace patina
