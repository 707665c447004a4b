#pragma once
// The CPU twin of the GPU's texture units (engine/shading/texture.h says the conventions):
// images decoded once to linear texels, their mip levels made once (and uploaded as they are
// to the GPU), then sampled with the sampler's wrap and filters at the level of detail
// texture.glsl computes, through its wrap and transform.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "shading/texture.h"

namespace patina {

// `width` x `height` 8-bit RGBA texels, rows top first, as linear floats. srgb: RGB through the
// exact sRGB decode (base colour and emissive maps, as GL_SRGB8_ALPHA8 does); alpha, and every
// channel of a data map, is v / 255.
LinearTexture linearTexture(const uint8_t* rgba, int width, int height, bool srgb);

// The texture at `uv` (no flip: v = 0 is the first row). Bilinear between the four texels
// around x = u width - 1/2, y = v height - 1/2, or the texel under (u width, v height) when the
// sampler magnifies with NEAREST; each neighbour wrapped by the sampler's mode. Mip 0 only:
// the ground truth a GPU's filtered lookups are measured against. The texture must not be empty.
glm::vec4 sampleTexture(const LinearTexture& texture, const TextureSampler& sampler, glm::vec2 uv);

// An 8-bit RGBA image of a mip level, rows top first.
struct ImageLevel {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

// The mip levels below level 0 (`rgba`, width x height), down to 1 x 1: each half the size of
// the one above (rounded down, at least 1), each texel the mean of the 2 x 2 texels it covers
// (the last row or column of an odd size left out, a size of 1 read twice), taken in linear
// light for the RGB of an sRGB image (decoded, averaged, encoded and rounded again) and as
// stored for alpha and data. What the GPU uploads (gl/model_textures.cpp) and the CPU twin
// samples: one definition, not the driver's glGenerateMipmap.
std::vector<ImageLevel> mipLevels(const uint8_t* rgba, int width, int height, bool srgb);

// The texture at `uv` through its levels (level 0 first, as linearTexture makes each) at level
// of detail `lod` (texture.glsl's textureLevelOfDetail), as OpenGL 4.6 core 8.14-8.15 says for
// textureLod with the minification filters gl/model_textures.cpp sets: at or below c (0.5 for
// a LINEAR magnification with a NEAREST_MIPMAP minification, else 0) level 0 with the
// magnification filter; above it, without mipmaps level 0 with the minification filter, with
// them the two levels around min(lod, last level) blended by its fraction (MIPMAP_LINEAR),
// each with the minification filter.
glm::vec4 sampleTextureLod(const std::vector<LinearTexture>& levels, const TextureSampler& sampler, glm::vec2 uv,
                           float lod);

// KHR_texture_transform applied to a UV (texture.glsl's transformTextureCoordinate).
glm::vec2 transformedUv(const TextureTransform& transform, glm::vec2 uv);

}  // namespace patina
