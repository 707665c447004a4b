#include "shading/texture_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "shading/shading.h"

namespace patina {

namespace {

// TextureWrap's order is texture.glsl's TEXTURE_WRAP_* constants.
static_assert(int(TextureWrap::Repeat) == shader::TEXTURE_WRAP_REPEAT);
static_assert(int(TextureWrap::ClampToEdge) == shader::TEXTURE_WRAP_CLAMP_TO_EDGE);
static_assert(int(TextureWrap::MirroredRepeat) == shader::TEXTURE_WRAP_MIRRORED_REPEAT);

int wrapMode(TextureWrap wrap) {
    return int(wrap);
}

// floor(x) as a texel index. Beyond 2^24 a float has no fraction and no texel left to tell
// apart, so the range is bounded there (an int cannot hold every float); NaN reads texel 0.
int texelIndex(float x) {
    constexpr float limit = 16777216.0f;
    if (!(std::abs(x) < limit)) {
        return std::isnan(x) ? 0 : (x < 0.0f ? -int(limit) : int(limit));
    }
    return int(std::floor(x));
}

glm::vec4 texelAt(const LinearTexture& texture, const TextureSampler& sampler, int x, int y) {
    const int column = shader::wrapTexel(x, texture.width, wrapMode(sampler.wrapS));
    const int row = shader::wrapTexel(y, texture.height, wrapMode(sampler.wrapT));
    return texture.texels[size_t(row) * size_t(texture.width) + size_t(column)];
}

// `texture` at `uv` with the nearest texel or bilinear between four (GL's NEAREST and LINEAR).
glm::vec4 filtered(const LinearTexture& texture, const TextureSampler& sampler, glm::vec2 uv, bool nearest) {
    const glm::vec2 size(float(texture.width), float(texture.height));
    if (nearest) {
        const glm::vec2 p = uv * size;
        return texelAt(texture, sampler, texelIndex(p.x), texelIndex(p.y));
    }
    // GL's convention: texel i covers [i, i + 1) / size, so its centre is at i + 1/2.
    const glm::vec2 p = uv * size - glm::vec2(0.5f);
    const int x0 = texelIndex(p.x), y0 = texelIndex(p.y);
    const glm::vec2 f = p - glm::floor(p);
    const glm::vec4 top = glm::mix(texelAt(texture, sampler, x0, y0), texelAt(texture, sampler, x0 + 1, y0), f.x);
    const glm::vec4 bottom =
        glm::mix(texelAt(texture, sampler, x0, y0 + 1), texelAt(texture, sampler, x0 + 1, y0 + 1), f.x);
    return glm::mix(top, bottom, f.y);
}

// One channel's mean of four 8-bit values, in linear light when `srgb`, rounded to 8 bits.
uint8_t meanOf(const uint8_t* const values[4], int channel, bool srgb) {
    // srgbDecode of each 8-bit value, made once: a 4K map's levels decode 64 million values.
    static const std::array<float, 256> decoded = [] {
        std::array<float, 256> table{};
        for (int v = 0; v < 256; ++v) {
            table[size_t(v)] = shader::srgbDecode(float(v) / 255.0f);
        }
        return table;
    }();
    float sum = 0.0f;
    for (int i = 0; i < 4; ++i) {
        const uint8_t v = values[i][channel];
        sum += srgb ? decoded[v] : float(v) / 255.0f;
    }
    const float mean = sum / 4.0f;
    return uint8_t(std::lround(255.0f * (srgb ? shader::srgbEncode(mean) : mean)));
}

}  // namespace

glm::vec4 sampleTexture(const LinearTexture& texture, const TextureSampler& sampler, glm::vec2 uv) {
    return filtered(texture, sampler, uv, sampler.nearestMagnification);
}

std::vector<ImageLevel> mipLevels(const uint8_t* rgba, int width, int height, bool srgb) {
    std::vector<ImageLevel> levels;
    const uint8_t* above = rgba;
    int aboveWidth = width, aboveHeight = height;
    while (aboveWidth > 1 || aboveHeight > 1) {
        ImageLevel level{std::max(1, aboveWidth / 2), std::max(1, aboveHeight / 2), {}};
        level.rgba.resize(size_t(level.width) * size_t(level.height) * 4);
        for (int y = 0; y < level.height; ++y) {
            const int y0 = std::min(2 * y, aboveHeight - 1), y1 = std::min(2 * y + 1, aboveHeight - 1);
            for (int x = 0; x < level.width; ++x) {
                const int x0 = std::min(2 * x, aboveWidth - 1), x1 = std::min(2 * x + 1, aboveWidth - 1);
                auto at = [&](int tx, int ty) { return above + (size_t(ty) * size_t(aboveWidth) + size_t(tx)) * 4; };
                const uint8_t* const corners[4] = {at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1)};
                uint8_t* out = &level.rgba[(size_t(y) * size_t(level.width) + size_t(x)) * 4];
                for (int c = 0; c < 4; ++c) {
                    out[c] = meanOf(corners, c, srgb && c < 3);
                }
            }
        }
        levels.push_back(std::move(level));
        above = levels.back().rgba.data();
        aboveWidth = levels.back().width;
        aboveHeight = levels.back().height;
    }
    return levels;
}

glm::vec4 sampleTextureLod(const std::vector<LinearTexture>& levels, const TextureSampler& sampler, glm::vec2 uv,
                           float lod) {
    const float c = !sampler.nearestMagnification && sampler.nearestMinification && sampler.mipmaps ? 0.5f : 0.0f;
    if (!(lod > c)) {   // NaN too: level 0, magnified
        return filtered(levels.front(), sampler, uv, sampler.nearestMagnification);
    }
    if (!sampler.mipmaps || levels.size() == 1) {
        return filtered(levels.front(), sampler, uv, sampler.nearestMinification);
    }
    const float last = float(levels.size() - 1);
    const float level = std::min(lod, last);
    const size_t lower = size_t(std::floor(level)), upper = std::min(lower + 1, levels.size() - 1);
    const float fraction = level - std::floor(level);
    const glm::vec4 a = filtered(levels[lower], sampler, uv, sampler.nearestMinification);
    return fraction > 0.0f ? glm::mix(a, filtered(levels[upper], sampler, uv, sampler.nearestMinification), fraction)
                           : a;
}

LinearTexture linearTexture(const uint8_t* rgba, int width, int height, bool srgb) {
    LinearTexture texture;
    texture.width = width;
    texture.height = height;
    texture.texels.resize(size_t(width) * size_t(height));
    const auto unorm = [](uint8_t v) { return float(v) / 255.0f; };
    const auto colour = [&](uint8_t v) { return srgb ? shader::srgbDecode(unorm(v)) : unorm(v); };
    for (size_t i = 0; i < texture.texels.size(); ++i) {
        const uint8_t* p = rgba + 4 * i;
        texture.texels[i] = glm::vec4(colour(p[0]), colour(p[1]), colour(p[2]), unorm(p[3]));
    }
    return texture;
}

glm::vec2 transformedUv(const TextureTransform& transform, glm::vec2 uv) {
    return shader::transformTextureCoordinate(uv, transform.offset, transform.scale, transform.rotation);
}

}  // namespace patina
