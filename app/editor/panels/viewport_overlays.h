#pragma once
// What the viewport draws over its picture: the comparison's side labels, the edited part's
// outline, the environment being prepared, the channel shown, and the render's cost (Advanced).

#include <imgui.h>

namespace patina {
struct Scene;
}

namespace patina::editor {

struct Document;
struct Interaction;
struct Jobs;
struct Preferences;
class EditorServices;

// The viewport's picture on screen: where it starts, its size, in whole pixels too.
struct ViewArea {
    ImVec2 origin, size;
    int width, height;
};

// Which material each part of the view shows, named.
void drawSideLabels(const Document& document, const Interaction& interaction, ImVec2 origin, ImVec2 size);
// The edited part of a model of several parts, outlined over the picture as the camera sees it.
void drawPartOutline(const Document& document, Interaction& interaction, const Preferences& preferences,
                     const ViewArea& area);
// An environment file being prepared: the picture keeps the one it had until then.
void drawEnvironmentProgress(const Jobs& jobs, const ViewArea& area);
// Which channel the viewport shows instead of the picture, at its top left.
void drawChannelLabel(const Interaction& interaction, const ViewArea& area);
// Overlay (Advanced): cost of the last render and what was drawn.
void drawRenderOverlay(const Interaction& interaction, EditorServices& services, const Scene& b, const ViewArea& area);

}  // namespace patina::editor
