#include <algorithm>
#include <system_error>

#include <imgui.h>

#include "keys.h"
#include "panels.h"
#include "widgets.h"

namespace patina::editor {

namespace {
void startPathDialog(EditorState& state, EditorState::PathDialog kind, std::filesystem::path initial) {
    state.pathDialog = kind;
    state.pathDialogText = initial.string();
}

void saveAs(EditorState& state) {
    startPathDialog(state, EditorState::PathDialog::SaveAs,
                    state.materialPath.empty() ? std::filesystem::path(state.scene.material.name + ".json")
                                               : state.materialPath);
}

void saveSceneAs(EditorState& state) {
    startPathDialog(state, EditorState::PathDialog::SaveSceneAs,
                    state.scenePath.empty() ? std::filesystem::path(state.scene.material.name + "-scene.json")
                                            : state.scenePath);
}

void saveSceneDocument(EditorState& state) {
    if (state.scenePath.empty()) {
        saveSceneAs(state);
    } else {
        saveScene(state, state.scenePath);
    }
}

// Ctrl+S: the document: the scene when one is open, else the material.
void save(EditorState& state) {
    if (!state.scenePath.empty()) {
        saveScene(state, state.scenePath);
    } else if (state.materialPath.empty()) {
        saveAs(state);
    } else {
        saveMaterial(state, state.materialPath);
    }
}

void screenshot(EditorState& state, EditorServices& services) {
    const int width = state.screenshotWidth > 0 ? state.screenshotWidth : services.viewportWidth;
    const int height = state.screenshotHeight > 0 ? state.screenshotHeight : services.viewportHeight;
    services.screenshot(state, std::max(width, 1), std::max(height, 1));
}

// Entries of the folder the typed path points into, for picking with the mouse.
void drawFolderListing(EditorState& state) {
    std::filesystem::path typed(state.pathDialogText);
    std::filesystem::path folder = std::filesystem::is_directory(typed) ? typed : typed.parent_path();
    if (folder.empty()) {
        folder = ".";
    }
    std::vector<std::filesystem::directory_entry> entries;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        const std::string extension = entry.path().extension().string();
        if (entry.is_directory(error) || extension == ".json" || extension == ".png") {
            entries.push_back(entry);
        }
    }
    std::sort(entries.begin(), entries.end());
    ImGui::BeginChild("listing", ImVec2(520, 220), true);
    if (ImGui::Selectable("..")) {
        state.pathDialogText = (std::filesystem::absolute(folder, error).parent_path() / "").string();
    }
    for (const auto& entry : entries) {
        const bool directory = entry.is_directory(error);
        const std::string label = entry.path().filename().string() + (directory ? "/" : "");
        if (ImGui::Selectable(label.c_str())) {
            state.pathDialogText = (entry.path() / (directory ? "" : "")).string();
        }
    }
    ImGui::EndChild();
}
}  // namespace

void drawMenuBar(EditorState& state, EditorServices& services) {
    if (!ImGui::BeginMainMenuBar()) {
        return;
    }
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open...", "Ctrl+O")) {
            startPathDialog(state, EditorState::PathDialog::Open, state.materialPath.parent_path() / "");
        }
        if (ImGui::BeginMenu("Open recent", !state.recentFiles.empty())) {
            for (const std::filesystem::path& recent : state.recentFiles) {
                if (ImGui::MenuItem(recent.string().c_str())) {
                    requestOpen(state, recent);
                }
            }
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Save", "Ctrl+S")) {
            save(state);
        }
        if (ImGui::MenuItem("Save material as...", "Ctrl+Shift+S")) {
            saveAs(state);
        }
        if (ImGui::MenuItem("Save scene", "Ctrl+Alt+S")) {
            saveSceneDocument(state);
        }
        recordItem("Save scene");
        if (ImGui::MenuItem("Save scene as...")) {
            saveSceneAs(state);
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Screenshot", "F12")) {
            screenshot(state, services);
        }
        if (ImGui::MenuItem("Export comparison...", nullptr, false, state.compareA.has_value())) {
            startPathDialog(state, EditorState::PathDialog::ExportComparison, "comparison.png");
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) {
            state.pendingQuit = true;
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        if (ImGui::MenuItem("Undo", "Ctrl+Z", false, state.history.canUndo() || state.snapshot() != state.committed)) {
            undo(state);
        }
        if (ImGui::MenuItem("Redo", "Ctrl+Shift+Z / Ctrl+Y", false, state.history.canRedo())) {
            redo(state);
        }
        ImGui::EndMenu();
    }
    const bool viewMenu = ImGui::BeginMenu("View");
    if (!viewMenu) {
        recordItem("menu:View");   // while open, the last item is the menu's window
    }
    if (viewMenu) {
        if (ImGui::MenuItem("Frame mesh", "F")) {
            frameMesh(state);
        }
        recordItem("Frame mesh");
        ImGui::SetNextItemWidth(90);
        ImGui::InputInt("Screenshot width (0: viewport)", &state.screenshotWidth);
        recordItem("Screenshot width");
        ImGui::SetNextItemWidth(90);
        ImGui::InputInt("Screenshot height (0: viewport)", &state.screenshotHeight);
        recordItem("Screenshot height");
        state.screenshotWidth = std::clamp(state.screenshotWidth, 0, 8192);
        state.screenshotHeight = std::clamp(state.screenshotHeight, 0, 8192);
        std::string folder = state.screenshotFolder.string();
        if (inputString("Screenshot folder", &folder)) {
            state.screenshotFolder = folder;
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        if (ImGui::MenuItem("Shortcuts", "F1")) {
            state.showShortcuts = true;
        }
        ImGui::EndMenu();
    }
    // The last completed action, on one line where it moves nothing.
    const std::string status = state.status.substr(0, state.status.find('\n'));
    ImGui::SameLine(0.0f, 24.0f);
    ImGui::TextDisabled("%s", status.c_str());
    ImGui::EndMainMenuBar();
}

void handleShortcuts(EditorState& state, EditorServices& services) {
    if (ImGui::GetIO().WantTextInput) {
        return;   // typing a name or a path: keys are text
    }
    const KeyPresses& keys = services.keyPresses;
    if (pressed(keys, kKeyZ, true)) {
        undo(state);
    }
    if (pressed(keys, kKeyZ, true, true) || pressed(keys, kKeyY, true)) {
        redo(state);
    }
    if (pressed(keys, kKeyS, true)) {
        save(state);
    }
    if (pressed(keys, kKeyS, true, true)) {
        saveAs(state);
    }
    if (pressed(keys, kKeyS, true, false, true)) {
        saveSceneDocument(state);
    }
    if (pressed(keys, kKeyO, true)) {
        startPathDialog(state, EditorState::PathDialog::Open, state.materialPath.parent_path() / "");
    }
    if (pressed(keys, kKeyQ, true)) {
        state.pendingQuit = true;
    }
    if (pressed(keys, kKeyF12)) {
        screenshot(state, services);
    }
    if (pressed(keys, kKeyDelete)) {
        deleteLight(state, state.selectedLight);   // one undo step, as the Delete button
    }
    if (pressed(keys, kKeyF1)) {
        state.showShortcuts = !state.showShortcuts;
    }
}

void drawDialogs(EditorState& state, EditorServices& services) {
    // Path dialog: Open, Save as, Export comparison.
    if (state.pathDialog != EditorState::PathDialog::None && !ImGui::IsPopupOpen("Path")) {
        ImGui::OpenPopup("Path");
    }
    if (ImGui::BeginPopupModal("Path", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const EditorState::PathDialog kind = state.pathDialog;
        const char* verb = kind == EditorState::PathDialog::Open ? "Open"
                           : kind == EditorState::PathDialog::SaveAs || kind == EditorState::PathDialog::SaveSceneAs
                               ? "Save"
                               : "Export";
        ImGui::Text("%s: a material (.json), scene (.json) or Patina screenshot (.png)", verb);
        ImGui::SetNextItemWidth(520);
        const bool entered = inputString("##path", &state.pathDialogText, ImGuiInputTextFlags_EnterReturnsTrue);
        drawFolderListing(state);
        const bool confirmed = ImGui::Button(verb);
        recordItem("path:confirm");
        if (confirmed || entered) {
            const std::filesystem::path path = state.pathDialogText;
            if (state.pathDialog == EditorState::PathDialog::Open) {
                requestOpen(state, path);
            } else if (state.pathDialog == EditorState::PathDialog::SaveAs) {
                saveMaterial(state, path);
            } else if (state.pathDialog == EditorState::PathDialog::SaveSceneAs) {
                saveScene(state, path);
            } else {
                services.exportComparison(state, path);
            }
            state.pathDialog = EditorState::PathDialog::None;
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
            state.pathDialog = EditorState::PathDialog::None;
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }

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
    const bool asking = state.pendingOpen.has_value() || state.pendingQuit;
    auto proceed = [&] {
        if (state.pendingOpen) {
            openFile(state, *state.pendingOpen);
        } else {
            state.quitConfirmed = true;
        }
        state.pendingOpen.reset();
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
        ImGui::Text("%s%s not saved.", parts.empty() ? "Nothing is" : "", parts.c_str());
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
            state.pendingQuit = false;
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }

    if (state.showShortcuts) {
        ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_Appearing);
        if (ImGui::Begin("Shortcuts", &state.showShortcuts)) {
            const char* rows[][2] = {
                {"Ctrl+O", "open a material, scene or screenshot"},
                {"Ctrl+S", "save (the scene, if one is open; else the material)"},
                {"Ctrl+Shift+S", "save the material as"}, {"Ctrl+Alt+S", "save the scene"}, {"Ctrl+Z", "undo"}, {"Ctrl+Shift+Z, Ctrl+Y", "redo"},
                {"F12", "screenshot of the viewport"}, {"Delete", "delete the selected light"}, {"F", "frame the mesh (viewport)"},
                {"Left drag", "orbit; on a light: move it"}, {"Middle or Shift+left drag", "pan"},
                {"Wheel", "zoom"}, {"Ctrl+click a slider", "type a value"}, {"F1", "this list"},
                {"Ctrl+Q", "quit"}};
            for (const auto& row : rows) {
                ImGui::Text("%-24s %s", row[0], row[1]);
            }
        }
        ImGui::End();
    }
}

}  // namespace patina::editor
