#pragma once
// Texture lookups on the CPU, the twin of the GPU's texture units: the same wrap modes and the
// same transform (shaders/shared/texture.glsl), the same mip levels and level of detail, on
// linear texels. glTF 2.0
// section 3.8 (samplers) and KHR_texture_transform; docs/FORMATS.md says the conventions.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace patina {

// glTF's wrapS / wrapT: 10497 REPEAT (the default), 33071 CLAMP_TO_EDGE, 33648 MIRRORED_REPEAT.
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// How a texture is sampled (glTF's sampler). Absent filters mean linear with trilinear mipmaps.
struct TextureSampler {
    TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;
    bool nearestMagnification = false;   // magFilter 9728 NEAREST
    bool nearestMinification = false;    // minFilter 9728 / 9984 / 9986
    bool mipmaps = true;                 // minFilter with a MIPMAP mode, or absent
    bool operator==(const TextureSampler&) const = default;
};

// KHR_texture_transform: uv' = offset + R(rotation) * (scale * uv).
struct TextureTransform {
    glm::vec2 offset{0.0f}, scale{1.0f};
    float rotation = 0.0f;   // radians, counter-clockwise in UV space as the extension says
    bool operator==(const TextureTransform&) const = default;
};

// An image as the CPU samples it: RGBA texels in linear light (an sRGB image decoded once,
// texel by texel, as the GPU's sRGB formats decode before they filter), rows in file order:
// (0, 0) is the top-left texel.
struct LinearTexture {
    int width = 0, height = 0;
    std::vector<glm::vec4> texels;
};

}  // namespace patina
