#pragma once
// Animated PNG (APNG: the acTL, fcTL and fdAT chunks of the PNG Specification, Third Edition, W3C,
// first Mozilla's APNG specification): frames encoded one by one as plain PNGs, put together.
#include <cstdint>
#include <vector>

namespace patina {

// The frames' duration, delayNumerator / delayDenominator seconds each (fcTL's delay_num and
// delay_den).
struct FrameDelay {
    uint16_t numerator = 1;
    uint16_t denominator = 30;
};

// One APNG of `framePngs` (each a PNG as encodePng writes it, all of one IHDR), looped for ever:
// signature, IHDR, acTL, then the first frame's fcTL and its IDAT (the default image is the
// first frame), each later frame's fcTL and its image data as fdAT, IEND. Every frame covers
// the whole image, drawn over nothing (dispose none, blend source). Throws
// std::invalid_argument for no frames, a frame that is no PNG, or frames whose headers differ.
std::vector<uint8_t> encodeAnimatedPng(const std::vector<std::vector<uint8_t>>& framePngs, FrameDelay delay = {});

}  // namespace patina
