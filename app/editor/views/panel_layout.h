#pragma once
// Where the panels go in the window: the material panel left, the lights right, the lobe under
// the viewport. The viewport has a minimum size the side panels and the lobe give way to, so a
// small window still shows a usable picture.
#include "state/editor_state.h"

namespace patina::editor {

struct PanelRect {
    float x = 0, y = 0, width = 0, height = 0;
};

struct PanelPlacement {
    PanelRect material, lights, viewport, lobe;
};

// Sizes at UI scale 1; multiplied by the scale.
constexpr float kMinViewportWidth = 400.0f, kMinViewportHeight = 260.0f;
constexpr float kMinSidePanelWidth = 210.0f, kMinLobeHeight = 110.0f;

// The panels in a `width` x `height` area starting at `top` (under the menu bar), each side
// panel as wide as `wanted` asks (sizes at scale 1) unless the viewport needs the room. A
// hidden lobe leaves the centre column to the viewport (the lobe's rectangle is 0 high).
PanelPlacement placePanels(const PanelLayout& wanted, float width, float height, float top, float scale);

}  // namespace patina::editor
