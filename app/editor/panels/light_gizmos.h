#pragma once
// The lights drawn over the viewport's picture, each at its size, with handles to drag.

#include <imgui.h>

namespace patina::editor {

struct Document;
struct Interaction;

// Point lights as a marker, sphere lights as their outline, tube lights as a capsule with a
// handle at each end and one in the middle, directional lights as an arrow from the centre of
// the view; all can be dragged. `origin` and `size`: the picture on screen. `pressed`: the
// viewport's button was clicked this frame. True while a gizmo is hovered or dragged.
bool drawLightGizmos(Document& document, Interaction& interaction, ImVec2 origin, ImVec2 size, bool pressed);

}  // namespace patina::editor
