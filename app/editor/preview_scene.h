#pragma once
// The one scene every preset thumbnail is rendered in, whatever is being edited: thumbnails
// compare materials, so they must not follow the current camera and lights.
#include "scene/scene.h"

namespace patina::editor {

// A sphere under a soft sky and a soft box in front of it, above: 16 white directional lights
// on three rows, on a mid-grey background, PBR Neutral tone mapped. Without an environment a
// metal shows nothing but its highlights, so one or two lights leave every metal a black ball
// with dots; sixteen make a lit patch in the metal's own colour, spread as wide as it is rough,
// so gold, copper, silver and chromium tell apart. (Environments will replace the box.)
Scene previewScene(const Material& material);

}  // namespace patina::editor
