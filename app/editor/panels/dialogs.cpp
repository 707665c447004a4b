#include <imgui.h>

#include "file_dialog.h"
#include "menu_actions.h"
#include "panels.h"
#include "ui_scale.h"
#include "widgets.h"

namespace patina::editor {

namespace {
// The last session's work, offered before anything else.
void drawRestorePrompt(EditorState& state) {
    if (state.recoverable && !ImGui::IsPopupOpen("Restore unsaved work?")) {
        ImGui::OpenPopup("Restore unsaved work?");
    }
    if (ImGui::BeginPopupModal("Restore unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (!state.recoverable) {
            ImGui::CloseCurrentPopup();
        } else {
            ImGui::Text("Patina did not close normally last time. Its working scene was kept%s%s.",
                        state.recoverable->savedAt.empty() ? "" : " at ", state.recoverable->savedAt.c_str());
            ImGui::TextUnformatted(recoverableSummary(state.recoverable->scene).c_str());
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
}

// What was waiting on the prompt goes on: the open, the new document or the quit.
void proceed(EditorState& state) {
    if (state.pendingOpen) {
        answerOpen(state, true);
    } else if (state.pendingNew) {
        newDocument(state);
    } else {
        state.quitConfirmed = true;
    }
    state.pendingNew = false;
    state.pendingQuit = false;
}

// Whether the prompt's Save writes the scene: when more than the material changed, a scene file
// is open, or a model's document has no file yet (Ctrl+S's rule, menu_actions.h save).
bool promptSavesScene(const EditorState& state) {
    return state.sceneChanged() || !state.scenePath.empty() ||
           (state.materialPath.empty() && !state.scene.meshFile.empty());
}

// The prompt's Save: the scene or the material; a file first if it has none.
void saveForPrompt(EditorState& state) {
    if (promptSavesScene(state)) {
        saveSceneDocument(state);
    } else {
        save(state);
    }
}

// Unsaved changes are never dropped without asking. While a Save as started from the prompt is
// open, the open or quit waits for it, and goes on once nothing is unsaved.
void drawUnsavedPrompt(EditorState& state) {
    const bool asking = state.pendingOpen.has_value() || state.pendingNew || state.pendingQuit;
    if (asking && state.pathDialog == EditorState::PathDialog::None && !ImGui::IsPopupOpen("Unsaved changes")) {
        if (!state.dirty()) {
            proceed(state);
        } else {
            ImGui::OpenPopup("Unsaved changes");
        }
    }
    if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        return;
    }
    const std::string parts = unsavedParts(state);
    if (parts.empty()) {
        ImGui::TextUnformatted("Nothing is unsaved.");
    } else {
        ImGui::Text("Unsaved changes to %s.", parts.c_str());
    }
    if (state.pendingOpen) {
        ImGui::Text("%s opens as a new document.", state.pendingOpen->filename().string().c_str());
    }
    ImGui::TextDisabled(promptSavesScene(state) ? "Save writes the scene, its material inline."
                                             : "Save writes the material.");
    if (ImGui::Button("Save")) {
        ImGui::CloseCurrentPopup();
        saveForPrompt(state);
        if (!state.dirty()) {
            proceed(state);
        }
    }
    recordItem("Save changes");
    ImGui::SameLine();
    if (ImGui::Button("Discard changes")) {
        proceed(state);
        ImGui::CloseCurrentPopup();
    }
    recordItem("Discard changes");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
        answerOpen(state, false);
        state.pendingNew = false;
        state.pendingQuit = false;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}
}  // namespace

void drawDialogs(EditorState& state, EditorServices& services) {
    drawPathDialog(state, services);
    drawRestorePrompt(state);
    drawUnsavedPrompt(state);
    drawShortcutsWindow(state);
}

}  // namespace patina::editor
