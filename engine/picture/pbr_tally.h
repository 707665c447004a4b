#pragma once
// The pbr-validation channel's picture counted (channels.glsl's pbrValidationValue): what the
// editor's status line and `render --channel pbr-validation` report.
#include "image/image.h"
#include "model/pbr_validation.h"

namespace patina {

// The verdict of one pixel of the channel's display image: a flag colour (exact in 8 bits, sRGB
// or not) or Ok for anything else.
PbrVerdict pbrVerdictOfShown(const uint8_t* rgba);

// The pixels of `shown` by verdict; `texels` counts the surfaces' pixels (the background is 0,
// which no surface shows: lightness 0 is always flagged).
PbrTally tallyPbrChannel(const LdrImage& shown);

}  // namespace patina
