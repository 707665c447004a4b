#pragma once
#include <cstdint>
#include <span>

#include "common/hdr_image.h"
#include "image/image.h"
#include "scene/scene.h"

namespace patina {

// The display image of linear radiance on the CPU: exposure, tone map and sRGB by the shaders'
// own displayTransform (shaders/shared/display.glsl), rounded to bytes as the GPU's RGBA8 target
// stores them. For images made without the GPU (the ground-truth render).
// Pixels marked in `backdrop` (empty: none) are the flat background, shown as its swatch
// (srgbColor: no exposure, no tone map), as the renderer shows it.
LdrImage displayImage(const HdrImage& linear, const DisplaySettings& display, std::span<const uint8_t> backdrop = {});

// A debug channel's image (scene/channel.h) as the shared shownChannel shows it (data: no
// exposure or tone map), rounded to bytes as the GPU's display image stores them.
LdrImage channelDisplayImage(const HdrImage& channel, int channelId, bool srgb);

// An equirect environment image shrunk to width x height for a thumbnail: each pixel the mean of
// a few bilinear reads across it, through the PBR Neutral tone map (an HDRI's sun would clip
// everything else to white without one).
LdrImage equirectPreview(const HdrImage& equirect, int width, int height);

}  // namespace patina
