#include <imgui.h>

#include "file_dialog.h"
#include "menu_actions.h"
#include "panels.h"
#include "ui_scale.h"
#include "widgets.h"

namespace patina::editor {

void drawDialogs(EditorState& state, EditorServices& services) {
    drawPathDialog(state, services);

    // The last session's work, offered before anything else.
    if (state.recoverable && !ImGui::IsPopupOpen("Restore unsaved work?")) {
        ImGui::OpenPopup("Restore unsaved work?");
    }
    if (ImGui::BeginPopupModal("Restore unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (!state.recoverable) {
            ImGui::CloseCurrentPopup();
        } else {
            ImGui::Text("Patina did not close normally last time. Its working scene was kept%s%s.",
                        state.recoverable->savedAt.empty() ? "" : " at ", state.recoverable->savedAt.c_str());
            ImGui::Text("Material \"%s\", %zu light(s).", state.recoverable->scene.material.name.c_str(),
                        state.recoverable->scene.lights.size());
            if (ImGui::Button("Restore")) {
                restoreRecoverable(state);
                ImGui::CloseCurrentPopup();
            }
            recordItem("Restore");
            ImGui::SameLine();
            if (ImGui::Button("Discard")) {
                discardRecoverable(state);
                ImGui::CloseCurrentPopup();
            }
            recordItem("Discard");
        }
        ImGui::EndPopup();
    }

    // Unsaved changes are never dropped without asking. While a Save as started from the
    // prompt is open, the open or quit waits for it, and goes on once nothing is unsaved.
    const bool asking = state.pendingOpen.has_value() || state.pendingNew || state.pendingQuit;
    auto proceed = [&] {
        if (state.pendingOpen) {
            openFile(state, *state.pendingOpen);
        } else if (state.pendingNew) {
            newDocument(state);
        } else {
            state.quitConfirmed = true;
        }
        state.pendingOpen.reset();
        state.pendingNew = false;
        state.pendingQuit = false;
    };
    if (asking && state.pathDialog == EditorState::PathDialog::None && !ImGui::IsPopupOpen("Unsaved changes")) {
        if (!state.dirty()) {
            proceed();
        } else {
            ImGui::OpenPopup("Unsaved changes");
        }
    }
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const std::string parts = unsavedParts(state);
        if (parts.empty()) {
            ImGui::TextUnformatted("Nothing is unsaved.");
        } else {
            ImGui::Text("Unsaved changes to %s.", parts.c_str());
        }
        ImGui::TextDisabled(state.sceneChanged() ? "Save writes the scene, its material inline."
                                                 : "Save writes the material.");
        if (ImGui::Button("Save")) {
            // The whole scene when more than the material changed; a file first if it has none.
            ImGui::CloseCurrentPopup();
            if (state.sceneChanged() || !state.scenePath.empty()) {
                saveSceneDocument(state);
            } else {
                save(state);
            }
            if (!state.dirty()) {
                proceed();
            }
        }
        recordItem("Save changes");
        ImGui::SameLine();
        if (ImGui::Button("Discard changes")) {
            proceed();
            ImGui::CloseCurrentPopup();
        }
        recordItem("Discard changes");
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) {
            state.pendingOpen.reset();
            state.pendingNew = false;
            state.pendingQuit = false;
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }

    if (state.showShortcuts) {
        // Centred and sized to its rows, never larger than the window.
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
        ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(display.x - px(20), display.y - px(20)));
        if (ImGui::Begin("Shortcuts", &state.showShortcuts, ImGuiWindowFlags_AlwaysAutoResize)) {
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
}

}  // namespace patina::editor
