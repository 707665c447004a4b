#include "model/pbr_validation.h"

#include <algorithm>
#include <cmath>

#include "shading/shading.h"

namespace patina {

PbrCheck checkBaseColor(glm::vec3 linearBaseColor, float metallic, float transmission, const PbrRanges& ranges) {
    // The channel's own functions (channels.glsl), so the batch check and the picture agree.
    PbrCheck check;
    check.metal = metallic >= 0.5f;
    const float lightness = shader::pbrLightness(linearBaseColor);
    const float reflected = shader::pbrLightness((1.0f - transmission) * linearBaseColor);
    check.value = int(lightness);
    check.reflected = int(reflected);
    switch (shader::pbrVerdict(lightness, reflected, check.metal, ranges.asVector())) {
        case shader::PBR_DIELECTRIC_TOO_DARK: check.verdict = PbrVerdict::DielectricTooDark; break;
        case shader::PBR_DIELECTRIC_TOO_BRIGHT: check.verdict = PbrVerdict::DielectricTooBright; break;
        case shader::PBR_METAL_TOO_DARK: check.verdict = PbrVerdict::MetalTooDark; break;
        default: check.verdict = PbrVerdict::Ok;
    }
    return check;
}

namespace {
const ModelImage* imageOf(const Model& model, const TextureSlot& slot) {
    if (!slot.present() || size_t(slot.image) >= model.images.size()) {
        return nullptr;
    }
    const ModelImage& image = model.images[size_t(slot.image)];
    const bool whole = image.width > 0 && image.height > 0 &&
                       image.rgba.size() >= size_t(image.width) * size_t(image.height) * 4;
    return whole ? &image : nullptr;
}

// The texel of `image` at the place of texel (x, y) of an image of width x height, nearest.
const uint8_t* texelAt(const ModelImage& image, int x, int y, int width, int height) {
    const int tx = std::min(image.width - 1, int((x + 0.5) * image.width / width));
    const int ty = std::min(image.height - 1, int((y + 0.5) * image.height / height));
    return &image.rgba[(size_t(ty) * size_t(image.width) + size_t(tx)) * 4];
}
}  // namespace

PbrTally checkBaseColorTexels(const Model& model, const ModelMaterial& material, const PbrRanges& ranges) {
    PbrTally tally;
    const ModelImage* base = imageOf(model, material.baseColor);
    if (!base) {
        return tally;
    }
    const ModelImage* metallicRoughness = imageOf(model, material.metallicRoughness);
    const ModelImage* transmissionMap = imageOf(model, material.transmissionMap);
    for (int y = 0; y < base->height; ++y) {
        for (int x = 0; x < base->width; ++x) {
            const uint8_t* texel = texelAt(*base, x, y, base->width, base->height);
            const glm::vec3 decoded{shader::srgbDecode(texel[0] / 255.0f), shader::srgbDecode(texel[1] / 255.0f),
                                    shader::srgbDecode(texel[2] / 255.0f)};
            const float metallic =
                material.factors.metallic *
                (metallicRoughness ? texelAt(*metallicRoughness, x, y, base->width, base->height)[2] / 255.0f : 1.0f);
            const float transmission =
                material.factors.transmission *
                (transmissionMap ? texelAt(*transmissionMap, x, y, base->width, base->height)[0] / 255.0f : 1.0f);
            const PbrVerdict verdict =
                checkBaseColor(material.factors.baseColor * decoded, metallic, transmission, ranges).verdict;
            ++tally.texels;
            tally.dielectricDark += verdict == PbrVerdict::DielectricTooDark;
            tally.dielectricBright += verdict == PbrVerdict::DielectricTooBright;
            tally.metalDark += verdict == PbrVerdict::MetalTooDark;
        }
    }
    return tally;
}

}  // namespace patina
