#include <algorithm>
#include <cmath>
#include <system_error>

#include <imgui.h>

#include "file_dialog.h"
#include "keys.h"
#include "open_folder.h"
#include "panels.h"
#include "ui_scale.h"
#include "widgets.h"

namespace patina::editor {

namespace {
constexpr int kLargestScreenshot = 16384;

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

void screenshot(EditorState& state, const EditorServices& services) {
    const int width = std::max(state.screenshotWidth > 0 ? state.screenshotWidth : services.viewportWidth, 1);
    const int height = std::max(state.screenshotHeight > 0 ? state.screenshotHeight : services.viewportHeight, 1);
    state.screenshotRequested = {width, height};
    state.status = "Rendering the " + std::to_string(width) + " x " + std::to_string(height) + " screenshot...";
}

void openScreenshotFolder(EditorState& state) {
    if (const std::string failed = showFolder(state.screenshotFolder, state.folderOpener); !failed.empty()) {
        state.error = failed;
    }
}

// The user's presets folder, the material's name as the file's.
void saveAsPresetDialog(EditorState& state) {
    std::string name = state.scene.material.name.empty() ? "material" : state.scene.material.name;
    std::replace(name.begin(), name.end(), '/', '_');
    startPathDialog(state, EditorState::PathDialog::SavePreset, state.userPresetFolder / (name + ".json"));
}

}  // namespace

void takeRequestedScreenshot(EditorState& state, EditorServices& services) {
    if (const auto size = state.screenshotRequested) {
        state.screenshotRequested.reset();   // once, even when it fails
        services.screenshot(state, size->first, size->second);
    }
}

void drawMenuBar(EditorState& state, EditorServices& services) {
    if (!ImGui::BeginMainMenuBar()) {
        return;
    }
    const bool fileMenu = ImGui::BeginMenu("File");
    if (!fileMenu) {
        recordItem("menu:File");   // while open, the last item is the menu's window
    }
    if (fileMenu) {
        if (ImGui::MenuItem("New", "Ctrl+N")) {
            requestNew(state);
        }
        recordItem("New", "A new scene: the default sphere, lights and material, saved nowhere yet");
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
        if (ImGui::MenuItem("Save as preset...", nullptr, false, !state.userPresetFolder.empty())) {
            saveAsPresetDialog(state);
        }
        recordItem("Save as preset", "Save the material into your presets folder; it shows in the preset browser");
        ImGui::Separator();
        if (ImGui::MenuItem("Screenshot", "F12")) {
            screenshot(state, services);
        }
        if (ImGui::MenuItem("Open screenshot folder")) {
            openScreenshotFolder(state);
        }
        recordItem("Open screenshot folder", "Show the folder screenshots go to in the file manager");
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
        recordItem("Frame mesh", "Aim the camera at the whole mesh");
        ImGui::MenuItem("Light gizmos", nullptr, &state.showGizmos);
        recordItem("Light gizmos", "Show the lights' dots and arrows over the viewport");
        ImGui::MenuItem("Lobe panel", nullptr, &state.layout.showLobe);
        recordItem("Lobe panel", "Show the BRDF lobe under the viewport; hidden, the viewport takes its room");
        ImGui::MenuItem("Advanced controls", nullptr, &state.showAdvanced);
        recordItem("Advanced controls", "The BRDF model, render path, timings, derived values and the Accuracy tab");
        // Steps, not a slider: the menu would grow under the mouse while it is dragged.
        const bool sizes = ImGui::BeginMenu("UI size");
        if (!sizes) {   // while open, the last item is the menu's window
            recordItem("UI size", "Text and controls larger or smaller, on top of the screen's own scale");
        }
        if (sizes) {
            for (int percent : {75, 100, 125, 150, 175, 200, 250, 300}) {
                const std::string label = std::to_string(percent) + "%";
                if (ImGui::MenuItem(label.c_str(), nullptr, std::lround(state.uiScaleSetting * 100.0f) == percent)) {
                    state.uiScaleSetting = float(percent) / 100.0f;
                }
                recordItem("UI size " + label);
            }
            ImGui::EndMenu();
        }
        ImGui::Separator();
        ImGui::SetNextItemWidth(px(90));
        ImGui::InputInt("Screenshot width (0: viewport)", &state.screenshotWidth);
        recordItem("Screenshot width", "Screenshots this many pixels wide; 0: as wide as the viewport");
        ImGui::SetNextItemWidth(px(90));
        ImGui::InputInt("Screenshot height (0: viewport)", &state.screenshotHeight);
        recordItem("Screenshot height", "Screenshots this many pixels high; 0: as high as the viewport");
        // What `patina render` takes: the renderer says at once when the GL cannot.
        state.screenshotWidth = std::clamp(state.screenshotWidth, 0, kLargestScreenshot);
        state.screenshotHeight = std::clamp(state.screenshotHeight, 0, kLargestScreenshot);
        std::string folder = state.screenshotFolder.string();
        if (inputString("Screenshot folder", &folder)) {
            state.screenshotFolder = folder;
        }
        recordItem("Screenshot folder", "Where F12 writes screenshots (made when missing)");
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        if (ImGui::MenuItem("Shortcuts", "F1")) {
            state.showShortcuts = true;
        }
        ImGui::EndMenu();
    }
    // The last completed action, on one line where it moves nothing; after a screenshot, a
    // button to its folder.
    const std::string status = state.status.substr(0, state.status.find('\n'));
    ImGui::SameLine(0.0f, px(24));
    ImGui::TextDisabled("%s", status.c_str());
    if (!state.lastScreenshot.empty() && status.find(state.lastScreenshot.string()) != std::string::npos) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Open folder")) {
            openScreenshotFolder(state);
        }
        recordItem("Open folder", "Show the screenshot's folder in the file manager");
    }
    ImGui::EndMainMenuBar();
}

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
    if (promptOpen(state)) {
        // Nothing edits the document behind a prompt: Ctrl+Z or Ctrl+O there once undid or
        // replaced what the prompt was asking about.
        return;
    }
    if (pressed(keys, kKeyN, true)) {
        requestNew(state);
    }
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
}

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
