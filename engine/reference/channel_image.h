#pragma once
// The inspector on the CPU twin: a debug channel (scene/channel.h) as an image, and one pixel's
// every channel input, from the surfaces the GPU rasterises (pixel_surfaces.h) through the same
// shared functions shade.frag's PATINA_CHANNEL runs (shading/channel_inputs.h). The GPU's
// channel render is held to it by the tests; `patina inspect` and the editor's read-out use it.
#include <optional>

#include "common/hdr_image.h"
#include "reference/pixel_surfaces.h"
#include "scene/channel.h"
#include "scene/prepared_scene.h"
#include "shading/shading.h"

namespace patina {

// The pixel (x, y)'s channel inputs, rows top first; nullopt where no item is. The environment
// by the split sum along R, as the GPU's channel programs shade it.
std::optional<shader::ChannelInputs> pixelChannelInputs(const PreparedScene& prepared, const PixelSurfaces& surfaces,
                                                        const ChannelLights& lights, int x, int y);

// Sample `i`'s inputs lit by `lights` alone (the enabled ones, packed), without the environment:
// one light's own lobes, for the read-out.
shader::ChannelInputs sampleChannelInputs(const PreparedScene& prepared, const PixelSurfaces& surfaces, size_t i,
                                          const std::vector<Light>& lights);

// The channel at every pixel, 0 where no item is. Throws InputError for a light it cannot find
// (channelLights).
HdrImage channelImage(const PreparedScene& prepared, const PixelSurfaces& surfaces, const ChannelRequest& request);

}  // namespace patina
