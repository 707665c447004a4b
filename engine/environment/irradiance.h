#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "common/hdr_image.h"
#include "environment/cube_map.h"

namespace patina {

// The environment's diffuse light: the irradiance E(n) = integral over the sphere of
// Env(l) max(n.l, 0) dl (the cosine convolution; Ramamoorthi and Hanrahan 2001, eq. 1), the
// Lambert radiance being c_diff / pi E(n). Kept as a cube map whose every texel holds E at the
// direction through its centre, read with the seamless bilinear filter (cube_map.h on the CPU,
// GL_TEXTURE_CUBE_MAP_SEAMLESS on the GPU); docs/LIGHTING.md L2 and its measurements.
//
// How each texel is made, exactly but for the horizon: the source's pixels are gathered into
// cells (the texels of a cube of kIrradianceCellSize texels a side, each pixel into the cell its
// centre falls in), and each cell keeps, per colour channel, its first moment
// M = sum over its pixels of L_p integral over the pixel of l dl (closed form for an equirect
// pixel, pixelMoment). For a cell wholly above the horizon of n its share of E is n.M, exactly,
// however its radiance lies within it: a one-pixel sun counts at its own direction, not at the
// cell's centre. A cell cut by the horizon counts max(n.M, 0), which is short of the truth by at
// most the part of it below the horizon (measured: docs/LIGHTING.md).
constexpr int kIrradianceFaceSize = 32;   // the map: 2.8 degrees a texel
constexpr int kIrradianceCellSize = 16;   // the cells: 1536 of them

// Integral over the equirect pixel (x, y) of a width x height image of the direction l dl
// (shaders/shared/ibl.glsl's convention: l = (sin t sin p, cos t, -sin t cos p) with
// t = pi v and p = 2 pi (u - 1/2)). Its length is a little under the pixel's solid angle.
glm::dvec3 pixelMoment(int width, int height, int x, int y);

// E at the texel centres of a cube of `faceSize` texels from an equirect image, as above.
CubeLevel irradianceCube(const HdrImage& equirect, int faceSize = kIrradianceFaceSize,
                         int cellSize = kIrradianceCellSize);

}  // namespace patina
