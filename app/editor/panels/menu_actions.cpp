#include "menu_actions.h"

#include <algorithm>

#include "file_dialog.h"
#include "open_folder.h"

namespace patina::editor {

void saveAs(EditorState& state) {
    startPathDialog(state, EditorState::PathDialog::SaveAs,
                    state.materialPath.empty() ? std::filesystem::path(state.scene.material.name + ".json")
                                               : state.materialPath);
}

void saveSceneAs(EditorState& state) {
    // A scene never saved is named for what it shows: the model opened, or the material.
    const std::string shown = state.scene.meshFile.empty() ? state.scene.material.name
                                                           : std::filesystem::path(state.scene.meshFile).stem().string();
    startPathDialog(state, EditorState::PathDialog::SaveSceneAs,
                    state.scenePath.empty() ? std::filesystem::path(shown + "-scene.json") : state.scenePath);
}

void saveSceneDocument(EditorState& state) {
    if (state.scenePath.empty()) {
        saveSceneAs(state);
    } else {
        saveScene(state, state.scenePath);
    }
}

void save(EditorState& state) {
    if (!state.scenePath.empty()) {
        saveScene(state, state.scenePath);
    } else if (!state.materialPath.empty()) {
        saveMaterial(state, state.materialPath);
    } else if (!state.scene.meshFile.empty()) {
        saveSceneAs(state);   // a model's document: its tuning is kept in a scene
    } else {
        saveAs(state);
    }
}

void screenshot(EditorState& state, const EditorServices& services) {
    const int width = std::max(state.screenshotWidth > 0 ? state.screenshotWidth : services.viewportWidth, 1);
    const int height = std::max(state.screenshotHeight > 0 ? state.screenshotHeight : services.viewportHeight, 1);
    state.screenshotRequested = {width, height};
    state.status = "Rendering the " + std::to_string(width) + " x " + std::to_string(height) + " screenshot...";
}

void takeRequestedScreenshot(EditorState& state, EditorServices& services) {
    if (const auto size = state.screenshotRequested) {
        state.screenshotRequested.reset();   // once, even when it fails
        services.screenshot(state, size->first, size->second);
    }
}

void openScreenshotFolder(EditorState& state) {
    if (const std::string failed = showFolder(state.screenshotFolder, state.folderOpener); !failed.empty()) {
        state.error = failed;
    }
}

void saveAsPresetDialog(EditorState& state) {
    const std::string edited = editedMaterial(state).name;
    std::string name = edited.empty() ? "material" : edited;
    std::replace(name.begin(), name.end(), '/', '_');
    startPathDialog(state, EditorState::PathDialog::SavePreset, state.userPresetFolder / (name + ".json"));
}

void openDialog(EditorState& state) {
    startPathDialog(state, EditorState::PathDialog::Open, state.materialPath.parent_path() / "");
}

}  // namespace patina::editor
