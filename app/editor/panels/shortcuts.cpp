#include <imgui.h>

#include "window/keys.h"
#include "panels/menu_actions.h"
#include "panels/panels.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

void handleShortcuts(EditorState& state, EditorServices& services) {
    if (ImGui::GetIO().WantTextInput) {
        return;   // typing a name or a path: keys are text
    }
    const KeyPresses& keys = services.keyPresses;
    // F1 shows the shortcuts and Escape closes them, as any help window, behind a prompt too.
    if (pressed(keys, kKeyF1)) {
        state.showShortcuts = !state.showShortcuts;
    } else if (pressed(keys, kKeyEscape)) {
        state.showShortcuts = false;
    }
    if (promptOpen(state, state)) {
        // Nothing edits the document behind a prompt: Ctrl+Z or Ctrl+O there once undid or
        // replaced what the prompt was asking about.
        return;
    }
    if (pressed(keys, kKeyN, true)) {
        requestNew(state, state, state, state);
    }
    if (pressed(keys, kKeyZ, true)) {
        undo(state, state, state);
    }
    if (pressed(keys, kKeyZ, true, true) || pressed(keys, kKeyY, true)) {
        redo(state, state, state);
    }
    if (pressed(keys, kKeyS, true)) {
        save(state, state, state);
    }
    if (pressed(keys, kKeyS, true, true)) {
        saveAs(state, state);
    }
    if (pressed(keys, kKeyS, true, false, true)) {
        saveSceneDocument(state, state, state);
    }
    if (pressed(keys, kKeyO, true)) {
        openDialog(state, state);
    }
    if (pressed(keys, kKeyQ, true)) {
        state.pendingQuit = true;
    }
    if (pressed(keys, kKeyF12)) {
        screenshot(state, state, state, services);
    }
    if (pressed(keys, kKeyDelete)) {
        deleteLight(state, state, state.selectedLight);   // one undo step, as the Delete button
    }
}

// F1's list of keys: centred and sized to its rows, never larger than the window.
void drawShortcutsWindow(Prompts& prompts) {
    if (!prompts.showShortcuts) {
        return;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(display.x - px(20), display.y - px(20)));
    if (ImGui::Begin("Shortcuts", &prompts.showShortcuts, ImGuiWindowFlags_AlwaysAutoResize)) {
        const char* rows[][2] = {
            {"Ctrl+N", "new scene"}, {"Ctrl+O", "open a material, scene, screenshot, glTF or environment"},
            {"Ctrl+S", "save (the scene, if one is open; else the material)"},
            {"Ctrl+Shift+S", "save the material as"}, {"Ctrl+Alt+S", "save the scene"}, {"Ctrl+Z", "undo"},
            {"Ctrl+Shift+Z, Ctrl+Y", "redo"}, {"F12", "screenshot of the viewport"},
            {"Delete", "delete the selected light"}, {"F", "frame the mesh (viewport)"},
            {"Left drag", "orbit; on a light: move it"}, {"Middle or Shift+left drag", "pan"}, {"Right drag", "turn the environment (lighting and background)"},
            {"Wheel", "zoom"}, {"Ctrl+click a slider", "type a value"},
            {"Right-click Reset", "back to the default"}, {"F1", "this list (Escape closes it)"},
            {"Ctrl+Q", "quit"}};
        if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_SizingFixedFit)) {
            for (const auto& row : rows) {
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(row[0]);
                ImGui::TableNextColumn();
                ImGui::TextDisabled("%s", row[1]);
            }
            ImGui::EndTable();
        }
        recordItem("shortcuts");
    }
    ImGui::End();
}

}  // namespace patina::editor
