#include <imgui.h>

#include "panels/file_dialog.h"
#include "panels/menu_actions.h"
#include "panels/panels.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
// The last session's work, offered before anything else.
void drawRestorePrompt(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts) {
    if (jobs.recoverable && !ImGui::IsPopupOpen("Restore unsaved work?")) {
        ImGui::OpenPopup("Restore unsaved work?");
    }
    if (ImGui::BeginPopupModal("Restore unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (!jobs.recoverable) {
            ImGui::CloseCurrentPopup();
        } else {
            ImGui::Text("Patina did not close normally last time. Its working scene was kept%s%s.",
                        jobs.recoverable->savedAt.empty() ? "" : " at ", jobs.recoverable->savedAt.c_str());
            ImGui::TextUnformatted(recoverableSummary(jobs.recoverable->scene).c_str());
            if (ImGui::Button("Restore")) {
                restoreRecoverable(document, interaction, jobs, prompts);
                ImGui::CloseCurrentPopup();
            }
            recordItem("Restore");
            ImGui::SameLine();
            if (ImGui::Button("Discard")) {
                discardRecoverable(jobs);
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
        newDocument(state, state, state, state);
    } else {
        state.quitConfirmed = true;
    }
    state.pendingNew = false;
    state.pendingQuit = false;
}

// Whether the prompt's Save writes the scene: when more than the material changed, a scene file
// is open, or a model's document has no file yet (Ctrl+S's rule, menu_actions.h save).
bool promptSavesScene(const Document& document) {
    return document.sceneChanged() || !document.scenePath.empty() ||
           (document.materialPath.empty() && !document.scene.meshFile.empty());
}

// The prompt's Save: the scene or the material; a file first if it has none.
void saveForPrompt(Document& document, Preferences& preferences, Prompts& prompts) {
    if (promptSavesScene(document)) {
        saveSceneDocument(document, preferences, prompts);
    } else {
        save(document, preferences, prompts);
    }
}

// Unsaved changes are never dropped without asking. While a Save as started from the prompt is
// open, the open or quit waits for it, and goes on once nothing is unsaved.
void drawUnsavedPrompt(EditorState& state) {
    const bool asking = state.pendingOpen.has_value() || state.pendingNew || state.pendingQuit;
    if (asking && state.pathDialog == Prompts::PathDialog::None && !ImGui::IsPopupOpen("Unsaved changes")) {
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
        saveForPrompt(state, state, state);
        if (!state.dirty()) {
            proceed(state);
        }
    }
    recordItem("Save changes");
    ImGui::SameLine();
    if (ImGui::Button("Discard changes")) {
        discardChanges(state, *state.assets);
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
    drawRestorePrompt(state, state, state, state);
    drawUnsavedPrompt(state);
    drawShortcutsWindow(state);
}

}  // namespace patina::editor
