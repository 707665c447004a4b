#include "gltf/spec_gloss.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "gltf/material.h"
#include "shading/shading.h"

namespace patina::gltf {

namespace {

constexpr float kDielectricF0 = 0.04f;   // the example's dielectricSpecular
constexpr float kEpsilon = 1e-6f;        // the example's guard against 0 / 0

float maxComponent(glm::vec3 c) { return std::max({c.r, c.g, c.b}); }

// Texel (x, y) of a `width` x `height` output read from `image` at the same place (nearest).
const uint8_t* texelAt(const ModelImage& image, int x, int y, int width, int height) {
    const int ix = std::min(image.width - 1, x * image.width / width);
    const int iy = std::min(image.height - 1, y * image.height / height);
    return &image.rgba[(size_t(iy) * size_t(image.width) + size_t(ix)) * 4];
}

uint8_t unorm8(float value) { return uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); }
float decoded(uint8_t texel) { return float(shader::srgbDecode(texel / 255.0f)); }
glm::vec3 decodedRgb(const uint8_t* texel) { return {decoded(texel[0]), decoded(texel[1]), decoded(texel[2])}; }

// The conversion of every texel into a base colour image and a metallic-roughness image.
void bakeMaps(Model& model, const SpecGlossMaterial& source, ModelMaterial& material) {
    const TextureSlot diffuseSlot = material.baseColor, specularSlot = material.metallicRoughness;
    const ModelImage* diffuse = diffuseSlot.present() ? &model.images[size_t(diffuseSlot.image)] : nullptr;
    const ModelImage* specular = specularSlot.present() ? &model.images[size_t(specularSlot.image)] : nullptr;
    const int width = std::max(diffuse ? diffuse->width : 0, specular ? specular->width : 0);
    const int height = std::max(diffuse ? diffuse->height : 0, specular ? specular->height : 0);
    ModelImage base{material.name + " base colour (from specular-glossiness)", width, height, {}};
    ModelImage metalRough{material.name + " metallic-roughness (from specular-glossiness)", width, height, {}};
    base.rgba.resize(size_t(width) * size_t(height) * 4);
    metalRough.rgba.resize(base.rgba.size());
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            SpecularGlossiness texel = source.factors;
            if (diffuse) {
                const uint8_t* d = texelAt(*diffuse, x, y, width, height);
                texel.diffuse *= decodedRgb(d);
                texel.alpha *= d[3] / 255.0f;
            }
            if (specular) {
                const uint8_t* s = texelAt(*specular, x, y, width, height);
                texel.specular *= decodedRgb(s);
                texel.glossiness *= s[3] / 255.0f;
            }
            const MetallicRoughness converted = metallicRoughnessFrom(texel);
            uint8_t* b = &base.rgba[(size_t(y) * size_t(width) + size_t(x)) * 4];
            const glm::vec3 encoded = shader::srgbColor(converted.baseColor);
            b[0] = unorm8(encoded.r), b[1] = unorm8(encoded.g), b[2] = unorm8(encoded.b), b[3] = unorm8(converted.alpha);
            uint8_t* m = &metalRough.rgba[(size_t(y) * size_t(width) + size_t(x)) * 4];
            m[0] = 0, m[1] = unorm8(converted.roughness), m[2] = unorm8(converted.metallic), m[3] = 255;
        }
    }
    // The maps keep the sampling of the one they came from (the diffuse's first).
    const TextureSlot& sampling = diffuse ? diffuseSlot : specularSlot;
    material.baseColor = sampling;
    material.baseColor.image = int(model.images.size());
    material.metallicRoughness = sampling;
    material.metallicRoughness.image = int(model.images.size()) + 1;
    model.images.push_back(std::move(base));
    model.images.push_back(std::move(metalRough));
    material.factors.baseColor = glm::vec3(1.0f);
    material.baseAlpha = 1.0f;
    material.factors.metallic = 1.0f;
    material.factors.roughness = 1.0f;
}

// Whether two more images of the baked size (bakeMaps) keep the model's decoded images within
// the budget docs/FORMATS.md sets (a hostile file's maps are bounded; what they bake must be).
bool fitsBudget(const Model& model, const ModelMaterial& material, uint64_t budget) {
    uint64_t used = 0, width = 0, height = 0;
    for (const ModelImage& image : model.images) {
        used += image.rgba.size();
    }
    for (const TextureSlot* slot : {&material.baseColor, &material.metallicRoughness}) {
        if (slot->present()) {
            const ModelImage& image = model.images[size_t(slot->image)];
            width = std::max(width, uint64_t(image.width));
            height = std::max(height, uint64_t(image.height));
        }
    }
    return used + 2 * width * height * 4 <= budget;
}

}  // namespace

float perceivedBrightness(glm::vec3 c) { return std::sqrt(0.299f * c.r * c.r + 0.587f * c.g * c.g + 0.114f * c.b * c.b); }

float solveMetallic(float diffuse, float specular, float oneMinusSpecularStrength) {
    if (specular < kDielectricF0) {
        return 0.0f;   // darker than any dielectric: no metal explains it
    }
    const float a = kDielectricF0;
    const float b = diffuse * oneMinusSpecularStrength / (1.0f - kDielectricF0) + specular - 2.0f * kDielectricF0;
    const float c = kDielectricF0 - specular;
    const float discriminant = std::max(b * b - 4.0f * a * c, 0.0f);
    return std::clamp((-b + std::sqrt(discriminant)) / (2.0f * a), 0.0f, 1.0f);
}

MetallicRoughness metallicRoughnessFrom(const SpecularGlossiness& material) {
    const float oneMinusSpecularStrength = 1.0f - maxComponent(material.specular);
    const float metallic = solveMetallic(perceivedBrightness(material.diffuse), perceivedBrightness(material.specular),
                                         oneMinusSpecularStrength);
    const glm::vec3 fromDiffuse =
        material.diffuse * (oneMinusSpecularStrength / (1.0f - kDielectricF0) / std::max(1.0f - metallic, kEpsilon));
    const glm::vec3 fromSpecular =
        (material.specular - glm::vec3(kDielectricF0 * (1.0f - metallic))) / std::max(metallic, kEpsilon);
    MetallicRoughness result;
    result.baseColor = glm::clamp(glm::mix(fromDiffuse, fromSpecular, metallic * metallic), 0.0f, 1.0f);
    result.alpha = material.alpha;
    result.metallic = metallic;
    result.roughness = 1.0f - material.glossiness;
    return result;
}

void convertSpecularGlossiness(Model& model, const std::vector<SpecGlossMaterial>& materials, uint64_t budget) {
    for (const SpecGlossMaterial& source : materials) {
        ModelMaterial& material = model.materials[size_t(source.material)];
        std::string how = "its factors";
        const bool mapped = material.baseColor.present() || material.metallicRoughness.present();
        if (mapped && fitsBudget(model, material, budget)) {
            bakeMaps(model, source, material);
            how = "its maps texel by texel into a base colour and a metallic-roughness map";
        } else {
            if (mapped) {   // the maps would take the model past its decoded images' budget
                how = "its factors alone: its maps, baked, would pass the " +
                      std::to_string(budget) + " bytes a model's decoded images may take";
            }
            const MetallicRoughness converted = metallicRoughnessFrom(source.factors);
            material.factors.baseColor = converted.baseColor;
            material.baseAlpha = converted.alpha;
            material.factors.metallic = converted.metallic;
            material.factors.roughness = converted.roughness;
            material.baseColor = {};
            material.metallicRoughness = {};
        }
        material.factors.specular = float(kDielectricF0 / double(shader::F0_PER_SPECULAR));   // the conversion's dielectric F0
        model.notes.push_back("material \"" + material.name +
                              "\": specular-glossiness (KHR_materials_pbrSpecularGlossiness) converted to "
                              "metallic-roughness by the Khronos conversion, " + how);
    }
}

}  // namespace patina::gltf
