#pragma once
#include <cstddef>

#include <glm/vec3.hpp>

#include "common/hdr_image.h"
#include "environment/cube_map.h"

namespace patina {

// Equirect (latitude-longitude) images, +Y up, row 0 the zenith, the centre along -Z
// (shaders/shared/ibl.glsl's directionToEquirect; docs/FORMATS.md).

// Bilinear, wrapping around in longitude and clamped at the poles; a unit direction.
glm::vec3 sampleEquirect(const HdrImage& image, glm::vec3 direction);

// The image resampled onto a cube of `faceSize` texels a side (2x2 samples per texel).
CubeLevel equirectToCube(const HdrImage& image, int faceSize);
// The cube face size for an equirect `width` texels around: a texel about as wide as the
// image's, a power of two in [16, 512].
int cubeFaceSizeFor(int width);

// NaN, infinite and negative values (real HDRIs hold some) set to 0; how many pixels had one.
size_t replaceInvalidPixels(HdrImage& image);

// Largest environment images read: 16384 texels a side, 256 MiB of float RGB decoded.
constexpr int kMaxEnvironmentSide = 16384;
constexpr size_t kMaxEnvironmentBytes = size_t(256) << 20;
// Empty when width x height may be decoded, else why not (for the readers' messages).
const char* environmentSizeProblem(long long width, long long height);

}  // namespace patina
