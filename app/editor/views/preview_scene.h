#pragma once
// The one scene every preset thumbnail is rendered in, whatever is being edited: thumbnails
// compare materials, so they must not follow the current camera and lights.
#include "scene/scene.h"

namespace patina::editor {

// A sphere under the built-in studio environment and one key light, on a mid-grey background,
// PBR Neutral tone mapped: a metal reflects the studio in its own colour, blurred as much as it
// is rough, so gold, copper, silver and chromium tell apart (under analytic lights alone a
// metal was a black ball with dots).
Scene previewScene(const Material& material);

}  // namespace patina::editor
