#include "shading/texture_sampling.h"

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

}  // namespace

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

glm::vec4 sampleTexture(const LinearTexture& texture, const TextureSampler& sampler, glm::vec2 uv) {
    const glm::vec2 size(float(texture.width), float(texture.height));
    if (sampler.nearestMagnification) {
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

glm::vec2 transformedUv(const TextureTransform& transform, glm::vec2 uv) {
    return shader::transformTextureCoordinate(uv, transform.offset, transform.scale, transform.rotation);
}

}  // namespace patina
