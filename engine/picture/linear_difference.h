#pragma once
// Two renderers' linear images of one view compared as a user sees them (`patina difference`,
// scripts/compare_cycles.sh, docs/LIGHTING.md "Side by side with Cycles"): both shrunk alike,
// both through the same exposure, tone curve and sRGB encoding (shaders/shared/display.glsl's
// displayTransform), then the mean |difference| in sRGB levels (0-255) over the pixels that show
// the model in both, its edges left out (each renderer filters them its own way).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/hdr_image.h"
#include "image/image.h"
#include "scene/scene.h"

namespace patina {

// Each pixel the mean of a factor x factor block of `image`: what a renderer shows at that
// size when it renders `factor` times larger (a box filter over the larger image's pixels).
// Throws std::invalid_argument when factor < 1 or a side is not a multiple of it.
HdrImage downsampleBox(const HdrImage& image, int factor);

// The pixels (1) of an image `factor` times smaller than `coverage` that show the model, from a
// channel image that is 0 (all three components) where no item is (`render --channel
// geometry-normal --reference`): a pixel counts when every pixel of its block is covered and so
// is every pixel within `erode` of it (its (2 erode + 1)^2 neighbourhood at the smaller size), so
// that silhouettes are left out. Throws std::invalid_argument as downsampleBox does, or for
// erode < 0.
std::vector<uint8_t> coverageMask(const HdrImage& coverage, int factor, int erode);

// Over the pixels `mask` keeps and their R, G and B, with `display`'s exposure and tone map and
// the sRGB encoding applied to both (unrounded, clamped to [0, 1]) and scaled to 0-255:
// mean |b - a| and mean (b - a) (positive: b is brighter).
struct MaskedDifference {
    double meanAbsolute = 0.0;
    double meanSigned = 0.0;
    size_t pixels = 0;
};
// Throws std::invalid_argument when the two images or the mask differ in size.
MaskedDifference maskedDifference(const HdrImage& a, const HdrImage& b, const std::vector<uint8_t>& mask,
                                  const DisplaySettings& display);

// |b - a| per pixel as displayed (the largest over R, G, B) times `gain`, through heatColour;
// the pixels the mask leaves out grey, so that what was not compared shows as such.
LdrImage maskedHeatMap(const HdrImage& a, const HdrImage& b, const std::vector<uint8_t>& mask,
                       const DisplaySettings& display, float gain);

}  // namespace patina
