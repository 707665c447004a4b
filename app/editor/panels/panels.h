#pragma once
#include <vector>

#include <imgui.h>
// One function per panel: each reads EditorState (the whole, or the parts it draws), draws its
// widgets and writes the state back.
#include "window/editor_services.h"
#include "state/editor_state.h"

namespace patina::editor {

void drawMaterialPanel(EditorState& state, EditorServices& services);
void drawLightsPanel(EditorState& state, EditorServices& services);
void drawViewportPanel(EditorState& state, EditorServices& services);
void drawLobePanel(const Document& document, Interaction& interaction, EditorServices& services);
void drawAccuracyPanel(const Document& document, const Interaction& interaction, const Preferences& preferences,
                       EditorServices& services);
void drawPresetsPanel(EditorState& state, EditorServices& services);
// One picture the viewport shows, for the read-out: its scene, where the whole picture is on
// screen (origin, size), the part of it that shows (hoverMin to hoverMax: Split shows A's left
// part) and which side it is ("A", "B"; "" alone).
struct ReadOutPicture {
    const PreparedScene* scene;
    ImVec2 origin, size, hoverMin, hoverMax;
    const char* side;
};
// View > Pixel read-out over the viewport's pictures, B's last: the hovered pixel's story, told
// by the picture under the mouse; a click pins a place (fractions of the picture, so a pin
// marks the same place in each picture of a comparison); the Pinned pixels window tells B's
// story at each pin.
void drawPixelReadOut(Interaction& interaction, Prompts& prompts, EditorServices& services,
                      const std::vector<ReadOutPicture>& pictures, bool hovered);
void drawMenuBar(EditorState& state, EditorServices& services);
// Writes the screenshot F12 asked for in the frame before (Jobs::screenshotRequested).
void takeRequestedScreenshot(EditorState& state, EditorServices& services);
void drawDialogs(EditorState& state, EditorServices& services);
void handleShortcuts(EditorState& state, EditorServices& services);
// F1's list of the keys, while prompts.showShortcuts.
void drawShortcutsWindow(Prompts& prompts);

// The whole editor for one frame: menu, panels around the viewport, dialogs, shortcuts, and
// the undo commit once no widget is active.
void drawEditorFrame(EditorState& state, EditorServices& services);

}  // namespace patina::editor
