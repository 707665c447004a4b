#include "views/panel_layout.h"

#include <algorithm>

namespace patina::editor {

namespace {
// `wanted` side sizes scaled down together until `total` fits in `room`, none below `minimum`.
void giveWay(float& a, float& b, float room, float minimum) {
    a = std::max(a, minimum);
    b = std::max(b, minimum);
    if (a + b <= room) {
        return;
    }
    const float spare = std::max(room - 2.0f * minimum, 0.0f);
    const float over = (a - minimum) + (b - minimum);
    if (over <= 0.0f) {
        return;   // both at their minimum already: the viewport gets what is left
    }
    a = minimum + (a - minimum) * spare / over;
    b = minimum + (b - minimum) * spare / over;
}

// The lobe's height in a centre column `height` high: as wanted, down to its minimum while the
// viewport keeps its own; a window too short for both: the viewport first, the lobe with what
// is left.
float lobeHeight(float wanted, float height, float scale) {
    float lobe = std::max(wanted, kMinLobeHeight * scale);
    lobe = std::min(lobe, std::max(height - kMinViewportHeight * scale, kMinLobeHeight * scale));
    return std::min(lobe, std::max(height - kMinViewportHeight * scale, height * 0.25f));
}
}  // namespace

PanelPlacement placePanels(const PanelLayout& wanted, float width, float height, float top, float scale) {
    float left = wanted.leftWidth * scale, right = wanted.rightWidth * scale;
    giveWay(left, right, width - kMinViewportWidth * scale, kMinSidePanelWidth * scale);
    const float centre = std::max(width - left - right, 1.0f);

    const float lobe = wanted.showLobe ? lobeHeight(wanted.lobeHeight * scale, height, scale) : 0.0f;
    const float viewport = std::max(height - lobe, 1.0f);

    PanelPlacement placement;
    placement.material = {0.0f, top, left, height};
    placement.lights = {width - right, top, right, height};
    placement.viewport = {left, top, centre, viewport};
    placement.lobe = {left, top + viewport, centre, lobe};
    return placement;
}

}  // namespace patina::editor
