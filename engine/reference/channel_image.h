#pragma once
// The inspector on the CPU twin: a debug channel (scene/channel.h) as an image, and the pieces
// one pixel's inputs are gathered from (pixel_story.h), from the surfaces the GPU rasterises (pixel_surfaces.h) through the same
// shared functions shade.frag's PATINA_CHANNEL runs (shading/channel_inputs.h). The GPU's
// channel render is held to it by the tests; `patina inspect` and the editor's read-out use it.
#include <optional>

#include "common/hdr_image.h"
#include "reference/pixel_surfaces.h"
#include "scene/channel.h"
#include "scene/prepared_scene.h"
#include "shading/channel_inputs.h"
#include "shading/shading.h"

namespace patina {

// What shade.frag reads at surface sample `i`; `draws` are sceneDraws of the prepared scene the
// surfaces are of.
ChannelPoint channelPoint(const PixelSurfaces& surfaces, const std::vector<SceneDraw>& draws, size_t i);
// The enabled environment light as the channel programs read it; nullopt without one.
std::optional<ChannelEnvironment> channelEnvironment(const PreparedScene& prepared);

// The channel at every pixel, 0 where no item is. Throws InputError for a light it cannot find
// (channelLights).
HdrImage channelImage(const PreparedScene& prepared, const PixelSurfaces& surfaces, const ChannelRequest& request);

}  // namespace patina
