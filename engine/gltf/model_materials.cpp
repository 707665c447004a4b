#include "gltf/model_materials.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "gltf/material.h"
#include "gltf/spec_gloss.h"
#include "gltf/values.h"
#include "files/input_error.h"

namespace patina::gltf {

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw InputError(source + ": " + what);
}

std::string at(const char* collection, int index) { return std::string("/") + collection + "/" + std::to_string(index); }

// Section 3.8.4.3 (wrapping): the WebGL enums.
TextureWrap wrapFrom(int value, const std::string& where, const std::string& source) {
    switch (value) {
    case 10497: return TextureWrap::Repeat;
    case 33071: return TextureWrap::ClampToEdge;
    case 33648: return TextureWrap::MirroredRepeat;
    }
    fail(source, where + ": " + std::to_string(value) + " is not 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or "
                                                      "33648 (MIRRORED_REPEAT)");
}

// Section 3.8.4.2 (filtering); -1 is tinygltf's "absent": linear, with mipmaps for minification.
TextureSampler samplerFrom(const tinygltf::Sampler& sampler, const std::string& where, const std::string& source) {
    TextureSampler result;
    result.wrapS = wrapFrom(sampler.wrapS, where + "/wrapS", source);
    result.wrapT = wrapFrom(sampler.wrapT, where + "/wrapT", source);
    if (sampler.magFilter != -1 && sampler.magFilter != 9728 && sampler.magFilter != 9729) {
        fail(source, where + "/magFilter: " + std::to_string(sampler.magFilter) + " is not 9728 (NEAREST) or 9729 (LINEAR)");
    }
    result.nearestMagnification = sampler.magFilter == 9728;
    const int min = sampler.minFilter;
    if (min != -1 && min != 9728 && min != 9729 && (min < 9984 || min > 9987)) {
        fail(source, where + "/minFilter: " + std::to_string(min) + " is not 9728, 9729 or 9984 to 9987");
    }
    // 9728 NEAREST, 9984 NEAREST_MIPMAP_NEAREST, 9986 NEAREST_MIPMAP_LINEAR: nearest texels.
    result.nearestMinification = min == 9728 || min == 9984 || min == 9986;
    result.mipmaps = min == -1 || min >= 9984;
    return result;
}

// textureInfo.texCoord, or KHR_texture_transform's: the UV sets a Mesh has.
int texCoordFrom(double value, const std::string& where, const std::string& source) {
    if (value != 0.0 && value != 1.0) {
        fail(source, where + ": " + numberText(value) +
                         ": Patina reads TEXCOORD_0 and TEXCOORD_1 only");
    }
    return int(value);
}

// The extensions that hold an image in a format Patina does not decode, in a texture (each
// has its own `source`; glTF's `source` is the fallback for readers without them). WebP's,
// EXT_texture_webp, is decoded.
constexpr const char* kOtherImageFormats[] = {"KHR_texture_basisu", "MSFT_texture_dds"};

class MaterialReader {
public:
    MaterialReader(const tinygltf::Model& document, const std::string& source, std::vector<std::string>& notes)
        : document_(document), source_(source), notes_(notes), noted_(document.textures.size(), false) {}

    ModelMaterial read(int index);
    // KHR_materials_pbrSpecularGlossiness of material `index`, if it has one: its factors and
    // maps, which `result`'s base colour and metallic-roughness slots take until converted.
    std::optional<SpecGlossMaterial> specularGlossiness(int index, ModelMaterial& result);

private:
    template <typename Info>
    TextureSlot slot(const Info& info, const std::string& where);
    // The glTF image of texture `index`, or -1 with a note when it has none Patina can read.
    int imageOf(int index, const std::string& where);
    TextureSampler samplerOf(const tinygltf::Texture& texture, int index) const;
    void transform(const tinygltf::ExtensionMap& extensions, const std::string& where, TextureSlot& slot) const;
    void clearcoatMaps(const tinygltf::Material& material, const std::string& where, ModelMaterial& result);
    void sheenMaps(const tinygltf::Material& material, const std::string& where, ModelMaterial& result);
    void volumeMaps(const tinygltf::Material& material, const std::string& where, ModelMaterial& result);
    // The map `key` of extension `name` (a textureInfo read as the core maps are), or none.
    TextureSlot extensionMap(const tinygltf::Material& material, const std::string& where, const char* name,
                             const char* key);

    const tinygltf::Model& document_;
    const std::string& source_;
    std::vector<std::string>& notes_;
    std::vector<bool> noted_;   // a texture's note once, however many materials use it
};

int MaterialReader::imageOf(int index, const std::string& where) {
    if (index < 0 || size_t(index) >= document_.textures.size()) {
        fail(source_, where + "/index: texture " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Texture& texture = document_.textures[size_t(index)];
    if (texture.source != -1 && (texture.source < 0 || size_t(texture.source) >= document_.images.size())) {
        fail(source_, at("textures", index) + "/source: image " + std::to_string(texture.source) + " does not exist");
    }
    // EXT_texture_webp: a reader that decodes WebP takes the extension's image, glTF's `source`
    // being the fallback for those that do not.
    if (const tinygltf::Value* webp = extensionOf(texture.extensions, "EXT_texture_webp"); webp && webp->Has("source")) {
        const std::string where = at("textures", index) + "/extensions/EXT_texture_webp/source";
        const std::optional<int> image = wholeNumber<int>(webp->Get("source"));
        if (!image || size_t(*image) >= document_.images.size()) {
            fail(source_, where + ": not the index of an image");
        }
        return *image;
    }
    if (texture.source == -1 && !noted_[size_t(index)]) {
        noted_[size_t(index)] = true;
        const auto* other = std::find_if(std::begin(kOtherImageFormats), std::end(kOtherImageFormats),
                                         [&](const char* name) { return extensionOf(texture.extensions, name); });
        notes_.push_back(at("textures", index) +
                         (other == std::end(kOtherImageFormats)
                              ? ": has no image"
                              : ": its image is in " + std::string(*other) + ", which Patina does not read") +
                         "; the materials that use it take their factors alone");
    }
    return texture.source;
}

TextureSampler MaterialReader::samplerOf(const tinygltf::Texture& texture, int index) const {
    if (texture.sampler == -1) {
        return TextureSampler();   // section 3.8.4.1: repeat, and filtering the reader chooses
    }
    if (texture.sampler < 0 || size_t(texture.sampler) >= document_.samplers.size()) {
        fail(source_, at("textures", index) + "/sampler: sampler " + std::to_string(texture.sampler) + " does not exist");
    }
    return samplerFrom(document_.samplers[size_t(texture.sampler)], at("samplers", texture.sampler), source_);
}

// KHR_texture_transform: offset, rotation (radians), scale, and a texCoord that overrides the
// textureInfo's.
void MaterialReader::transform(const tinygltf::ExtensionMap& extensions, const std::string& where,
                               TextureSlot& slot) const {
    const tinygltf::Value* transform = extensionOf(extensions, "KHR_texture_transform");
    const std::string transformAt = where + "/extensions/KHR_texture_transform";
    if (const std::vector<double> offset = numbersField(transform, "offset", 2, transformAt, source_); !offset.empty()) {
        slot.transform.offset = glm::vec2(float(offset[0]), float(offset[1]));
    }
    if (const std::vector<double> scale = numbersField(transform, "scale", 2, transformAt, source_); !scale.empty()) {
        slot.transform.scale = glm::vec2(float(scale[0]), float(scale[1]));
    }
    slot.transform.rotation = float(numberField(transform, "rotation", 0.0, transformAt, source_));
    slot.texCoord = texCoordFrom(numberField(transform, "texCoord", slot.texCoord, transformAt, source_),
                                 transformAt + "/texCoord", source_);
}

// A textureInfo (section 3.9.2 and 3.8.2): its texture's image and sampler, its UV set and
// transform. An absent one (index -1 in tinygltf) is an empty slot.
template <typename Info>
TextureSlot MaterialReader::slot(const Info& info, const std::string& where) {
    TextureSlot slot;
    if (info.index == -1) {
        return slot;
    }
    slot.image = imageOf(info.index, where);
    slot.sampler = samplerOf(document_.textures[size_t(info.index)], info.index);
    slot.texCoord = texCoordFrom(info.texCoord, where + "/texCoord", source_);
    transform(info.extensions, where, slot);
    return slot;
}

float unit(double value) { return float(std::clamp(value, 0.0, 1.0)); }

// Section 3.9.4: OPAQUE (the default), MASK or BLEND.
AlphaMode alphaModeFrom(const std::string& mode, const std::string& where, const std::string& source) {
    if (mode == "OPAQUE" || mode.empty()) {
        return AlphaMode::Opaque;
    }
    if (mode == "MASK") {
        return AlphaMode::Mask;
    }
    if (mode != "BLEND") {
        fail(source, where + ": \"" + mode + "\" is not OPAQUE, MASK or BLEND");
    }
    return AlphaMode::Blend;
}

// emissiveFactor times KHR_materials_emissive_strength's emissiveStrength (at least 0).
glm::vec3 emissionOf(const tinygltf::Material& material, const std::string& where, const std::string& source) {
    if (material.emissiveFactor.size() != 3) {
        fail(source, where + "/emissiveFactor: must have 3 numbers");
    }
    const std::string strengthAt = where + "/extensions/KHR_materials_emissive_strength";
    const double strength = numberField(extensionOf(material.extensions, "KHR_materials_emissive_strength"),
                                        "emissiveStrength", 1.0, strengthAt, source);
    if (strength < 0.0) {
        fail(source, strengthAt + "/emissiveStrength: " + numberText(strength) + " is below 0");
    }
    const auto& e = material.emissiveFactor;
    return glm::vec3(unit(e[0]), unit(e[1]), unit(e[2])) * float(strength);
}

// A textureInfo inside an extension, where tinygltf leaves it as an untyped value.
tinygltf::TextureInfo textureInfoOf(const tinygltf::Value* object, const char* key, const std::string& where,
                                    const std::string& source) {
    tinygltf::TextureInfo info;
    if (!object || !object->Has(key)) {
        return info;   // index -1: no map
    }
    const tinygltf::Value& value = object->Get(key);
    info.index = int(numberField(&value, "index", -1.0, where + "/" + key, source));
    info.texCoord = int(numberField(&value, "texCoord", 0.0, where + "/" + key, source));
    if (value.Has("extensions") && value.Get("extensions").IsObject()) {
        const tinygltf::Value& extensions = value.Get("extensions");
        for (const std::string& name : extensions.Keys()) {
            info.extensions[name] = extensions.Get(name);
        }
    }
    return info;
}

// Factors of the extension (its README's defaults: white diffuse and specular, glossiness 1),
// the colours linear as the file holds them.
SpecularGlossiness specGlossFactors(const tinygltf::Value* object, const std::string& where, const std::string& source) {
    SpecularGlossiness factors;
    const std::vector<double> diffuse = numbersField(object, "diffuseFactor", 4, where, source);
    if (!diffuse.empty()) {
        factors.diffuse = glm::vec3(unit(diffuse[0]), unit(diffuse[1]), unit(diffuse[2]));
        factors.alpha = unit(diffuse[3]);
    }
    const std::vector<double> specular = numbersField(object, "specularFactor", 3, where, source);
    if (!specular.empty()) {
        factors.specular = glm::vec3(unit(specular[0]), unit(specular[1]), unit(specular[2]));
    }
    factors.glossiness = unit(numberField(object, "glossinessFactor", 1.0, where, source));
    return factors;
}

std::optional<SpecGlossMaterial> MaterialReader::specularGlossiness(int index, ModelMaterial& result) {
    const char* name = "KHR_materials_pbrSpecularGlossiness";
    const tinygltf::Value* object = extensionOf(document_.materials[size_t(index)].extensions, name);
    if (!object) {
        return std::nullopt;
    }
    const std::string where = at("materials", index) + "/extensions/" + name;
    SpecGlossMaterial found;
    found.material = index;
    found.factors = specGlossFactors(object, where, source_);
    // Decoded with the other maps (model_import.cpp), then converted (spec_gloss.h).
    result.baseColor = slot(textureInfoOf(object, "diffuseTexture", where, source_), where + "/diffuseTexture");
    result.metallicRoughness = slot(textureInfoOf(object, "specularGlossinessTexture", where, source_),
                                    where + "/specularGlossinessTexture");
    return found;
}

ModelMaterial MaterialReader::read(int index) {
    const tinygltf::Material& material = document_.materials[size_t(index)];
    const std::string where = at("materials", index), pbrAt = where + "/pbrMetallicRoughness";
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    ModelMaterial result;
    const Material factors = materialFromGltf(material, where, source_, "material " + std::to_string(index));
    result.name = factors.name;
    result.factors = factors;
    if (pbr.baseColorFactor.size() != 4) {
        fail(source_, pbrAt + "/baseColorFactor: must have 4 numbers");
    }
    result.baseAlpha = unit(pbr.baseColorFactor[3]);
    result.baseColor = slot(pbr.baseColorTexture, pbrAt + "/baseColorTexture");
    result.metallicRoughness = slot(pbr.metallicRoughnessTexture, pbrAt + "/metallicRoughnessTexture");
    result.normal = slot(material.normalTexture, where + "/normalTexture");
    result.normalScale = float(material.normalTexture.scale);
    result.occlusion = slot(material.occlusionTexture, where + "/occlusionTexture");
    result.occlusionStrength = unit(material.occlusionTexture.strength);
    result.emissive = slot(material.emissiveTexture, where + "/emissiveTexture");
    result.emissiveFactor = emissionOf(material, where, source_);
    result.alphaMode = alphaModeFrom(material.alphaMode, where + "/alphaMode", source_);
    if (material.alphaCutoff < 0.0) {
        fail(source_, where + "/alphaCutoff: " + numberText(material.alphaCutoff) + " is below 0");
    }
    result.alphaCutoff = float(material.alphaCutoff);
    result.doubleSided = material.doubleSided;
    clearcoatMaps(material, where, result);
    sheenMaps(material, where, result);
    volumeMaps(material, where, result);
    // KHR_materials_anisotropy's anisotropyTexture: kept and exported, not drawn.
    result.anisotropyMap = extensionMap(material, where, "KHR_materials_anisotropy", "anisotropyTexture");
    // KHR_materials_specular's: RGB the tint's (sRGB), A the weight's.
    result.specularColor = extensionMap(material, where, "KHR_materials_specular", "specularColorTexture");
    result.specular = extensionMap(material, where, "KHR_materials_specular", "specularTexture");
    // KHR_materials_iridescence's: R the strength's, G the thickness's.
    result.iridescenceMap = extensionMap(material, where, "KHR_materials_iridescence", "iridescenceTexture");
    result.iridescenceThickness =
        extensionMap(material, where, "KHR_materials_iridescence", "iridescenceThicknessTexture");
    return result;
}

// KHR_materials_clearcoat's three maps (its factors are materialFromGltf's): each a textureInfo
// read as the core maps are, the normal map's scale beside it.
void MaterialReader::clearcoatMaps(const tinygltf::Material& material, const std::string& where,
                                   ModelMaterial& result) {
    const char* name = "KHR_materials_clearcoat";
    const tinygltf::Value* object = extensionOf(material.extensions, name);
    if (!object) {
        return;
    }
    const std::string at = where + "/extensions/" + name;
    result.clearcoat = slot(textureInfoOf(object, "clearcoatTexture", at, source_), at + "/clearcoatTexture");
    result.clearcoatRoughness = slot(textureInfoOf(object, "clearcoatRoughnessTexture", at, source_),
                                     at + "/clearcoatRoughnessTexture");
    result.clearcoatNormal = slot(textureInfoOf(object, "clearcoatNormalTexture", at, source_),
                                  at + "/clearcoatNormalTexture");
    if (object->Has("clearcoatNormalTexture")) {
        const tinygltf::Value& normal = object->Get("clearcoatNormalTexture");
        result.clearcoatNormalScale = float(numberField(&normal, "scale", 1.0, at + "/clearcoatNormalTexture", source_));
    }
}

// KHR_materials_sheen's two maps (its factors are materialFromGltf's), each a textureInfo read
// as the core maps are: the colour's RGB (sRGB), the roughness's A.
void MaterialReader::sheenMaps(const tinygltf::Material& material, const std::string& where, ModelMaterial& result) {
    const char* name = "KHR_materials_sheen";
    const tinygltf::Value* object = extensionOf(material.extensions, name);
    if (!object) {
        return;
    }
    const std::string at = where + "/extensions/" + name;
    result.sheenColor = slot(textureInfoOf(object, "sheenColorTexture", at, source_), at + "/sheenColorTexture");
    result.sheenRoughness =
        slot(textureInfoOf(object, "sheenRoughnessTexture", at, source_), at + "/sheenRoughnessTexture");
}

// KHR_materials_transmission's transmissionTexture and KHR_materials_volume's thicknessTexture
// (their factors are materialFromGltf's), each a textureInfo read as the core maps are.
void MaterialReader::volumeMaps(const tinygltf::Material& material, const std::string& where, ModelMaterial& result) {
    const char* transmissionName = "KHR_materials_transmission";
    if (const tinygltf::Value* object = extensionOf(material.extensions, transmissionName)) {
        const std::string at = where + "/extensions/" + transmissionName;
        result.transmissionMap =
            slot(textureInfoOf(object, "transmissionTexture", at, source_), at + "/transmissionTexture");
    }
    const char* volumeName = "KHR_materials_volume";
    if (const tinygltf::Value* object = extensionOf(material.extensions, volumeName)) {
        const std::string at = where + "/extensions/" + volumeName;
        result.thicknessMap = slot(textureInfoOf(object, "thicknessTexture", at, source_), at + "/thicknessTexture");
    }
}

TextureSlot MaterialReader::extensionMap(const tinygltf::Material& material, const std::string& where,
                                         const char* name, const char* key) {
    const tinygltf::Value* object = extensionOf(material.extensions, name);
    if (!object) {
        return {};
    }
    const std::string at = where + "/extensions/" + name;
    return slot(textureInfoOf(object, key, at, source_), at + "/" + key);
}

}  // namespace

std::vector<ModelMaterial> modelMaterials(const tinygltf::Model& document, const std::string& source,
                                          std::vector<std::string>& notes, std::vector<SpecGlossMaterial>* specGloss) {
    MaterialReader reader(document, source, notes);
    std::vector<ModelMaterial> materials;
    materials.reserve(document.materials.size());
    for (size_t m = 0; m < document.materials.size(); ++m) {
        materials.push_back(reader.read(int(m)));
        if (specGloss) {
            if (std::optional<SpecGlossMaterial> found = reader.specularGlossiness(int(m), materials.back())) {
                specGloss->push_back(*found);
            }
        }
    }
    return materials;
}

}  // namespace patina::gltf
