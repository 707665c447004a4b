#pragma once
// The CPU twin of the GPU's texture units (engine/shading/texture.h says the conventions):
// images decoded once to linear texels, then sampled on mip 0 with the sampler's wrap and
// magnification filter, through shaders/shared/texture.glsl's wrap and transform.
#include <cstdint>

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

// KHR_texture_transform applied to a UV (texture.glsl's transformTextureCoordinate).
glm::vec2 transformedUv(const TextureTransform& transform, glm::vec2 uv);

}  // namespace patina
