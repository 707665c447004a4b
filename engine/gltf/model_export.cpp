#include "gltf/model_export.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gltf/glb.h"
#include "gltf/material.h"
#include "image/image.h"
#include "io/file_kinds.h"
#include "files/input_error.h"
#include "model/placement.h"

namespace patina {

namespace fs = std::filesystem;

namespace {

constexpr int kFloat = 5126;            // glTF componentType FLOAT
constexpr int kUnsignedInt = 5125;      // UNSIGNED_INT
constexpr int kArrayBuffer = 34962;     // bufferView targets
constexpr int kElementArrayBuffer = 34963;

// The one buffer, with its views and accessors as the document lists them.
struct Buffer {
    std::vector<uint8_t> bin;
    Json views = Json::array(), accessors = Json::array();

    int view(const void* data, size_t size, std::optional<int> target) {
        bin.resize((bin.size() + 3) / 4 * 4, 0);   // every view starts 4-aligned (5.11.3)
        Json view{{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
        if (target) {
            view["target"] = *target;
        }
        const size_t at = bin.size();
        bin.resize(at + size);
        std::memcpy(bin.data() + at, data, size);
        views.push_back(std::move(view));
        return int(views.size()) - 1;
    }
    template <typename T>
    int accessor(const std::vector<T>& values, const char* type, int componentType, int target) {
        const int v = view(values.data(), values.size() * sizeof(T), target);
        accessors.push_back(
            {{"bufferView", v}, {"componentType", componentType}, {"count", values.size()}, {"type", type}});
        return int(accessors.size()) - 1;
    }
};

Json vec3Json(const glm::vec3& v) { return Json::array({double(v.x), double(v.y), double(v.z)}); }

// Whether `m` is a translation, rotation and scale (glTF 5.25: a node's matrix must be): the
// columns of its linear part at right angles, the last row (0, 0, 0, 1), all finite.
bool decomposes(const glm::mat4& m) {
    if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f) {
        return false;
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = i + 1; j < 3; ++j) {
            const glm::vec3 a(m[i]), b(m[j]);
            if (!(std::abs(glm::dot(a, b)) <= 1e-5f * glm::length(a) * glm::length(b))) {
                return false;
            }
        }
    }
    return true;
}

// `mesh` placed by `transform` in world space, as the renderer places it (mesh.vert): the
// normals through the inverse transpose, the tangents through the linear part with their sign
// turned by a mirror, and a mirror's triangles wound back counter-clockwise.
Mesh baked(Mesh mesh, const glm::mat4& transform) {
    const glm::mat3 linear(transform), normals = normalTransform(transform);
    const bool mirror = mirrors(transform);
    for (glm::vec3& p : mesh.positions) {
        p = glm::vec3(transform * glm::vec4(p, 1.0f));
    }
    for (glm::vec3& n : mesh.normals) {
        n = unitNormal(normals * n);
    }
    for (glm::vec4& t : mesh.tangents) {
        t = glm::vec4(linear * glm::vec3(t), mirror ? -t.w : t.w);
    }
    return mirror ? reversedWinding(std::move(mesh)) : mesh;
}

// Tangents as glTF requires them (3.7.2.1: xyz unit, w +-1). A vertex Patina holds without
// one (w = 0, or no direction: a degenerate UV triangle) gets one at right angles to its
// normal, which shades the same: the normal map's tangent plane has no direction there anyway.
std::vector<glm::vec4> validTangents(const Mesh& mesh) {
    std::vector<glm::vec4> tangents = mesh.tangents;
    for (size_t i = 0; i < tangents.size(); ++i) {
        glm::vec3 t(tangents[i]);
        if (!(glm::dot(t, t) > 1e-20f) || !std::isfinite(glm::dot(t, t))) {
            const glm::vec3 n = mesh.normals[i];
            t = glm::cross(n, std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0));
        }
        tangents[i] = glm::vec4(glm::normalize(t), tangents[i].w < 0.0f ? -1.0f : 1.0f);
    }
    return tangents;
}

// A glTF mesh of one primitive: its attributes and indices as accessors of `buffer`.
Json meshJson(const Mesh& mesh, int material, Buffer& buffer) {
    const int position = buffer.accessor(mesh.positions, "VEC3", kFloat, kArrayBuffer);
    const BoundingBox box = boundingBox(mesh);
    buffer.accessors[size_t(position)]["min"] = vec3Json(box.low);
    buffer.accessors[size_t(position)]["max"] = vec3Json(box.high);
    Json attributes{{"POSITION", position}, {"NORMAL", buffer.accessor(mesh.normals, "VEC3", kFloat, kArrayBuffer)}};
    if (!mesh.tangents.empty()) {
        attributes["TANGENT"] = buffer.accessor(validTangents(mesh), "VEC4", kFloat, kArrayBuffer);
    }
    if (!mesh.uv0.empty()) {
        attributes["TEXCOORD_0"] = buffer.accessor(mesh.uv0, "VEC2", kFloat, kArrayBuffer);
    }
    if (!mesh.uv1.empty()) {
        attributes["TEXCOORD_1"] = buffer.accessor(mesh.uv1, "VEC2", kFloat, kArrayBuffer);
    }
    if (!mesh.colors.empty()) {   // as read: linear RGBA floats
        attributes["COLOR_0"] = buffer.accessor(mesh.colors, "VEC4", kFloat, kArrayBuffer);
    }
    Json primitive{{"attributes", attributes},
                   {"indices", buffer.accessor(mesh.indices, "SCALAR", kUnsignedInt, kElementArrayBuffer)}};
    if (material >= 0) {
        primitive["material"] = material;
    }
    primitive["mode"] = 4;
    return Json{{"primitives", Json::array({primitive})}};
}

Json samplerJson(const TextureSampler& sampler) {
    auto wrap = [](TextureWrap mode) {
        switch (mode) {
        case TextureWrap::ClampToEdge: return 33071;
        case TextureWrap::MirroredRepeat: return 33648;
        case TextureWrap::Repeat: break;
        }
        return 10497;
    };
    // NEAREST / LINEAR, and with mipmaps NEAREST_MIPMAP_LINEAR / LINEAR_MIPMAP_LINEAR: what
    // Patina samples (nearest within a level, levels blended; gl/model_textures.cpp).
    const int minFilter = sampler.mipmaps ? (sampler.nearestMinification ? 9986 : 9987)
                                          : (sampler.nearestMinification ? 9728 : 9729);
    return Json{{"magFilter", sampler.nearestMagnification ? 9728 : 9729},
                {"minFilter", minFilter},
                {"wrapS", wrap(sampler.wrapS)},
                {"wrapT", wrap(sampler.wrapT)}};
}

// The document's textures, samplers and images, each made once for what the maps use.
struct Textures {
    const std::vector<ModelImage>& modelImages;
    Json textures = Json::array(), samplers = Json::array();
    std::vector<int> images;   // exported image -> the model's image
    std::map<std::pair<int, int>, int> byImageAndSampler;
    std::vector<TextureSampler> samplerList;
    std::set<std::string> extensions;

    // One exported image for each picture: a map replaced in the editor by a file the model
    // already holds is a second model image of the same pixels, written once.
    int imageIndex(int image) {
        const ModelImage& wanted = modelImages.at(size_t(image));
        const auto found = std::find_if(images.begin(), images.end(), [&](int exported) {
            const ModelImage& other = modelImages[size_t(exported)];
            return exported == image ||
                   (other.width == wanted.width && other.height == wanted.height && other.rgba == wanted.rgba);
        });
        if (found != images.end()) {
            return int(found - images.begin());
        }
        images.push_back(image);
        return int(images.size()) - 1;
    }
    int samplerIndex(const TextureSampler& sampler) {
        const auto found = std::find(samplerList.begin(), samplerList.end(), sampler);
        if (found != samplerList.end()) {
            return int(found - samplerList.begin());
        }
        samplerList.push_back(sampler);
        samplers.push_back(samplerJson(sampler));
        return int(samplerList.size()) - 1;
    }
    // A textureInfo for `slot` (3.9.2; KHR_texture_transform where it moves the UVs).
    Json info(const TextureSlot& slot) {
        const std::pair key{imageIndex(slot.image), samplerIndex(slot.sampler)};
        auto [entry, added] = byImageAndSampler.try_emplace(key, int(textures.size()));
        if (added) {
            textures.push_back({{"sampler", key.second}, {"source", key.first}});
        }
        Json info{{"index", entry->second}};
        if (slot.texCoord != 0) {
            info["texCoord"] = slot.texCoord;
        }
        if (slot.transform != TextureTransform{}) {
            const TextureTransform& t = slot.transform;
            info["extensions"]["KHR_texture_transform"] = {{"offset", {double(t.offset.x), double(t.offset.y)}},
                                                           {"rotation", double(t.rotation)},
                                                           {"scale", {double(t.scale.x), double(t.scale.y)}}};
            extensions.insert("KHR_texture_transform");
        }
        return info;
    }
};

// KHR_materials_clearcoat where the material has a coat: the factors materialToGltf wrote, and
// the coat's maps (model_materials.cpp reads them back).
void clearcoatJson(const ModelMaterial& material, Textures& textures, Json& json) {
    const char* name = gltf::kClearcoatExtension;
    const bool maps =
        material.clearcoat.present() || material.clearcoatRoughness.present() || material.clearcoatNormal.present();
    if (!maps && !(json.contains("extensions") && json["extensions"].contains(name))) {
        return;
    }
    Json& coat = json["extensions"][name];
    if (!coat.is_object()) {   // maps on a coat of factor 0
        coat = {{"clearcoatFactor", 0.0}, {"clearcoatRoughnessFactor", 0.0}};
    }
    if (material.clearcoat.present()) {
        coat["clearcoatTexture"] = textures.info(material.clearcoat);
    }
    if (material.clearcoatRoughness.present()) {
        coat["clearcoatRoughnessTexture"] = textures.info(material.clearcoatRoughness);
    }
    if (material.clearcoatNormal.present()) {
        coat["clearcoatNormalTexture"] = textures.info(material.clearcoatNormal);
        coat["clearcoatNormalTexture"]["scale"] = double(material.clearcoatNormalScale);
    }
    textures.extensions.insert(name);
}

// KHR_materials_sheen where the material has a sheen: the factors materialToGltf wrote, and
// the sheen's two maps (model_materials.cpp reads them back).
void sheenJson(const ModelMaterial& material, Textures& textures, Json& json) {
    const char* name = gltf::kSheenExtension;
    const bool maps = material.sheenColor.present() || material.sheenRoughness.present();
    if (!maps && !(json.contains("extensions") && json["extensions"].contains(name))) {
        return;
    }
    Json& sheen = json["extensions"][name];
    if (!sheen.is_object()) {   // maps on a sheen of colour 0
        sheen = {{"sheenColorFactor", {0.0, 0.0, 0.0}}, {"sheenRoughnessFactor", 0.0}};
    }
    if (material.sheenColor.present()) {
        sheen["sheenColorTexture"] = textures.info(material.sheenColor);
    }
    if (material.sheenRoughness.present()) {
        sheen["sheenRoughnessTexture"] = textures.info(material.sheenRoughness);
    }
    textures.extensions.insert(name);
}

// KHR_materials_transmission and KHR_materials_volume where the material has them: the factors
// materialToGltf wrote, and their maps (model_materials.cpp reads them back). A map without
// its extension's factors (a transmission of 0) is not written: the volume needs the
// transmission, and a transmission of 0 passes nothing whatever its map.
void volumeJson(const ModelMaterial& material, Textures& textures, Json& json) {
    if (!json.contains("extensions")) {
        return;
    }
    Json& extensions = json["extensions"];
    if (extensions.contains(gltf::kTransmissionExtension)) {
        if (material.transmissionMap.present()) {
            extensions[gltf::kTransmissionExtension]["transmissionTexture"] = textures.info(material.transmissionMap);
        }
        textures.extensions.insert(gltf::kTransmissionExtension);
    }
    if (extensions.contains(gltf::kVolumeExtension)) {
        if (material.thicknessMap.present()) {
            extensions[gltf::kVolumeExtension]["thicknessTexture"] = textures.info(material.thicknessMap);
        }
        textures.extensions.insert(gltf::kVolumeExtension);
    }
}

// KHR_materials_anisotropy where the material has it: the factors materialToGltf wrote, and its
// map (model_materials.cpp reads it back). A map on a strength of 0 is not written: it scales
// the strength, and 0 stretches nothing whatever its map.
void anisotropyJson(const ModelMaterial& material, Textures& textures, Json& json) {
    if (!json.contains("extensions") || !json["extensions"].contains(gltf::kAnisotropyExtension)) {
        return;
    }
    if (material.anisotropyMap.present()) {
        json["extensions"][gltf::kAnisotropyExtension]["anisotropyTexture"] = textures.info(material.anisotropyMap);
    }
    textures.extensions.insert(gltf::kAnisotropyExtension);
}

// KHR_materials_iridescence where the material has a film: the factors materialToGltf wrote, and
// its maps. A map on a strength of 0 is not written, as the anisotropy's.
void iridescenceJson(const ModelMaterial& material, Textures& textures, Json& json) {
    if (!json.contains("extensions") || !json["extensions"].contains(gltf::kIridescenceExtension)) {
        return;
    }
    Json& film = json["extensions"][gltf::kIridescenceExtension];
    if (material.iridescenceMap.present()) {
        film["iridescenceTexture"] = textures.info(material.iridescenceMap);
    }
    if (material.iridescenceThickness.present()) {
        film["iridescenceThicknessTexture"] = textures.info(material.iridescenceThickness);
    }
    textures.extensions.insert(gltf::kIridescenceExtension);
}

// The material as glTF writes it (3.9): the factors as materialToGltf maps them, and every
// map, alpha, emission and sidedness the model read (the inverse of model_materials.cpp).
Json materialJson(const ModelMaterial& material, Textures& textures) {
    Material factors;
    static_cast<MaterialParameters&>(factors) = material.factors;
    factors.name = material.name;
    Json json = gltf::materialToGltf(factors);
    Json& pbr = json["pbrMetallicRoughness"];
    pbr["baseColorFactor"][3] = double(material.baseAlpha);
    if (material.baseColor.present()) {
        pbr["baseColorTexture"] = textures.info(material.baseColor);
    }
    if (material.metallicRoughness.present()) {
        pbr["metallicRoughnessTexture"] = textures.info(material.metallicRoughness);
    }
    if (material.normal.present()) {
        json["normalTexture"] = textures.info(material.normal);
        json["normalTexture"]["scale"] = double(material.normalScale);
    }
    if (material.occlusion.present()) {
        json["occlusionTexture"] = textures.info(material.occlusion);
        json["occlusionTexture"]["strength"] = double(material.occlusionStrength);
    }
    if (material.emissive.present()) {
        json["emissiveTexture"] = textures.info(material.emissive);
    }
    // emissiveFactor holds at most 1 (3.9.3); what is brighter is KHR_materials_emissive_strength.
    const float strength = std::max({material.emissiveFactor.r, material.emissiveFactor.g, material.emissiveFactor.b});
    if (strength > 0.0f) {
        json["emissiveFactor"] = vec3Json(material.emissiveFactor / std::max(strength, 1.0f));
        if (strength > 1.0f) {
            json["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", double(strength)}};
            textures.extensions.insert("KHR_materials_emissive_strength");
        }
    }
    if (material.alphaMode != AlphaMode::Opaque) {
        json["alphaMode"] = material.alphaMode == AlphaMode::Mask ? "MASK" : "BLEND";
    }
    if (material.alphaMode == AlphaMode::Mask) {
        json["alphaCutoff"] = double(material.alphaCutoff);
    }
    if (material.doubleSided) {
        json["doubleSided"] = true;
    }
    clearcoatJson(material, textures, json);
    sheenJson(material, textures, json);
    volumeJson(material, textures, json);
    anisotropyJson(material, textures, json);
    // KHR_materials_specular's maps beside the factors materialToGltf always writes.
    Json& specular = json["extensions"][gltf::kMaterialExtensions[0]];
    if (material.specularColor.present()) {
        specular["specularColorTexture"] = textures.info(material.specularColor);
    }
    if (material.specular.present()) {
        specular["specularTexture"] = textures.info(material.specular);
    }
    iridescenceJson(material, textures, json);
    return json;
}

// The nodes and meshes of the draw items: one mesh for each primitive and material drawn, one
// node for each item (its matrix, or the identity where the matrix is baked in).
void writeDraws(const Model& model, Buffer& buffer, Json& document) {
    Json nodes = Json::array(), meshes = Json::array(), roots = Json::array();
    std::map<std::pair<int, int>, int> meshOf;
    for (const DrawItem& item : model.draws) {
        const Mesh& primitive = model.primitives.at(size_t(item.primitive));
        if (primitive.indices.empty()) {
            continue;   // an accessor holds at least one element (5.1.2)
        }
        Json node = Json::object();
        if (!item.node.empty()) {
            node["name"] = item.node;
        }
        if (decomposes(item.transform)) {
            auto [entry, added] = meshOf.try_emplace({item.primitive, item.material}, int(meshes.size()));
            if (added) {
                meshes.push_back(meshJson(primitive, item.material, buffer));
            }
            node["mesh"] = entry->second;
            if (item.transform != glm::mat4(1.0f)) {
                const float* m = glm::value_ptr(item.transform);
                node["matrix"] = Json::array();
                for (int i = 0; i < 16; ++i) {
                    node["matrix"].push_back(double(m[i]));   // column-major, as glTF and GLM hold them
                }
            }
        } else {
            meshes.push_back(meshJson(baked(primitive, item.transform), item.material, buffer));
            node["mesh"] = int(meshes.size()) - 1;
        }
        roots.push_back(nodes.size());
        nodes.push_back(std::move(node));
    }
    if (nodes.empty()) {
        throw InputError("nothing to export: the model draws no triangles");
    }
    document["scene"] = 0;
    document["scenes"] = Json::array({Json{{"nodes", roots}}});
    document["nodes"] = std::move(nodes);
    document["meshes"] = std::move(meshes);
}

// The exported images as PNG: in the buffer (.glb) or as files beside the .gltf.
Json writeImages(const Model& model, const Textures& textures, const fs::path& path, bool glb, Buffer& buffer,
                 std::vector<OutputFile>& files) {
    Json images = Json::array();
    for (size_t i = 0; i < textures.images.size(); ++i) {
        const ModelImage& image = model.images.at(size_t(textures.images[i]));
        std::vector<uint8_t> png = encodePng(LdrImage{image.width, image.height, image.rgba});
        Json json{{"name", image.name}};
        if (glb) {
            json["bufferView"] = buffer.view(png.data(), png.size(), std::nullopt);
            json["mimeType"] = "image/png";
        } else {
            const fs::path file = fs::path(path).replace_filename(path.stem().string() + "_" + std::to_string(i) + ".png");
            json["uri"] = uriOfFileName(file.filename().string());
            files.push_back({file, std::move(png)});
        }
        images.push_back(std::move(json));
    }
    return images;
}

}  // namespace

std::vector<OutputFile> encodeGltfModel(const fs::path& path, const Model& model, GltfBuffer bufferPlace) {
    const std::string extension = gltfExtension(path);
    if (extension.empty()) {
        throw InputError(path.string() + ": a glTF file must end in .gltf or .glb");
    }
    const bool glb = extension == ".glb";
    Json document = Json::object();
    document["asset"] = {{"version", "2.0"}, {"generator", "Patina"}};
    document["extensionsUsed"] = Json::array();   // its place in the file; filled in below
    Buffer buffer;
    try {
        writeDraws(model, buffer, document);
    } catch (const InputError& error) {
        throw InputError(path.string() + ": " + error.what());
    }
    Textures textures{model.images};
    Json materials = Json::array();
    for (const ModelMaterial& material : model.materials) {
        materials.push_back(materialJson(material, textures));
    }
    std::vector<OutputFile> files;
    // The material's own two first, as every export has them, then what the maps and emission use.
    std::vector<std::string> used(gltf::kMaterialExtensions, gltf::kMaterialExtensions + 2);
    used.insert(used.end(), textures.extensions.begin(), textures.extensions.end());
    document["extensionsUsed"] = used;
    if (!materials.empty()) {
        document["materials"] = std::move(materials);
    }
    if (!textures.textures.empty()) {
        document["textures"] = std::move(textures.textures);
        document["samplers"] = std::move(textures.samplers);
        document["images"] = writeImages(model, textures, path, glb, buffer, files);
    }
    document["accessors"] = std::move(buffer.accessors);
    document["bufferViews"] = std::move(buffer.views);
    Json bufferJson{{"byteLength", buffer.bin.size()}};
    const fs::path binPath = fs::path(path).replace_extension(".bin");
    if (!glb && bufferPlace == GltfBuffer::Embedded) {
        bufferJson["uri"] = "data:application/octet-stream;base64," + base64(buffer.bin);
    } else if (!glb) {
        bufferJson["uri"] = uriOfFileName(binPath.filename().string());
    }
    document["buffers"] = Json::array({bufferJson});

    const std::string json = document.dump();
    if (glb) {
        return {{path, gltf::joinGlb(json, buffer.bin.data(), buffer.bin.size())}};
    }
    if (bufferPlace == GltfBuffer::BinFile) {
        files.insert(files.begin(), {binPath, std::move(buffer.bin)});
    }
    files.push_back({path, std::vector<uint8_t>(json.begin(), json.end())});
    return files;
}

void exportGltfModel(const fs::path& path, const Model& model, GltfBuffer buffer) {
    writeOutputFiles(encodeGltfModel(path, model, buffer));
}

}  // namespace patina
