#pragma once
// One function per panel: each reads EditorState, draws its widgets and writes the state back.
#include "editor_services.h"
#include "editor_state.h"

namespace patina::editor {

void drawMaterialPanel(EditorState& state, EditorServices& services);
void drawLightsPanel(EditorState& state, EditorServices& services);
void drawViewportPanel(EditorState& state, EditorServices& services);
void drawLobePanel(EditorState& state);
void drawAccuracyPanel(EditorState& state, EditorServices& services);
void drawPresetsPanel(EditorState& state, EditorServices& services);
// View > Pixel read-out over the picture of `shown` (origin, size on screen): the hovered
// pixel's story, Ctrl+click pins, and the Pinned pixels window.
void drawPixelReadOut(EditorState& state, EditorServices& services, const PreparedScene& shown, ImVec2 origin,
                      ImVec2 size, bool hovered);
void drawMenuBar(EditorState& state, EditorServices& services);
// Writes the screenshot F12 asked for in the frame before (EditorState::screenshotRequested).
void takeRequestedScreenshot(EditorState& state, EditorServices& services);
void drawDialogs(EditorState& state, EditorServices& services);
void handleShortcuts(EditorState& state, EditorServices& services);
// F1's list of the keys, while state.showShortcuts.
void drawShortcutsWindow(EditorState& state);

// The whole editor for one frame: menu, panels around the viewport, dialogs, shortcuts, and
// the undo commit once no widget is active.
void drawEditorFrame(EditorState& state, EditorServices& services);

}  // namespace patina::editor
