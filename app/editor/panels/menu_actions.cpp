#include "panels/menu_actions.h"

#include <algorithm>

#include "panels/file_dialog.h"
#include "storage/open_folder.h"

namespace patina::editor {

void saveAs(const Document& document, Prompts& prompts) {
    startPathDialog(prompts, Prompts::PathDialog::SaveAs,
                    document.materialPath.empty() ? std::filesystem::path(document.scene.material.name + ".json")
                                                  : document.materialPath);
}

void saveSceneAs(const Document& document, Prompts& prompts) {
    // A scene never saved is named for what it shows: the model opened, or the material.
    const std::string shown = document.scene.meshFile.empty()
                                  ? document.scene.material.name
                                  : std::filesystem::path(document.scene.meshFile).stem().string();
    startPathDialog(prompts, Prompts::PathDialog::SaveSceneAs,
                    document.scenePath.empty() ? std::filesystem::path(shown + "-scene.json") : document.scenePath);
}

void saveSceneDocument(Document& document, Preferences& preferences, Prompts& prompts) {
    if (document.scenePath.empty()) {
        saveSceneAs(document, prompts);
    } else {
        saveScene(document, preferences, prompts, document.scenePath);
    }
}

void save(Document& document, Preferences& preferences, Prompts& prompts) {
    if (!document.scenePath.empty()) {
        saveScene(document, preferences, prompts, document.scenePath);
    } else if (!document.materialPath.empty()) {
        saveMaterial(document, preferences, prompts, document.materialPath);
    } else if (!document.scene.meshFile.empty()) {
        saveSceneAs(document, prompts);   // a model's document: its tuning is kept in a scene
    } else {
        saveAs(document, prompts);
    }
}

void screenshot(const Preferences& preferences, Jobs& jobs, Prompts& prompts, const EditorServices& services) {
    const int width =
        std::max(preferences.screenshotWidth > 0 ? preferences.screenshotWidth : services.viewportWidth, 1);
    const int height =
        std::max(preferences.screenshotHeight > 0 ? preferences.screenshotHeight : services.viewportHeight, 1);
    jobs.screenshotRequested = {width, height};
    prompts.status = "Rendering the " + std::to_string(width) + " x " + std::to_string(height) + " screenshot...";
}

void takeRequestedScreenshot(EditorState& state, EditorServices& services) {
    if (const auto size = state.screenshotRequested) {
        state.screenshotRequested.reset();   // once, even when it fails
        resolveAmbientOcclusion(state, state, state, true);   // a screenshot shows what the scene says
        services.screenshot(state, state, state, state, size->first, size->second);
    }
}

void openScreenshotFolder(const Preferences& preferences, Jobs& jobs, Prompts& prompts) {
    if (const std::string failed =
            showFolder(preferences.screenshotFolder, preferences.folderOpener, jobs.folderOpeners);
        !failed.empty()) {
        prompts.error = failed;
    }
}

void saveAsPresetDialog(const Document& document, const Interaction& interaction, const Preferences& preferences,
                        Prompts& prompts) {
    const std::string edited = editedMaterial(document, interaction).name;
    std::string name = edited.empty() ? "material" : edited;
    std::replace(name.begin(), name.end(), '/', '_');
    startPathDialog(prompts, Prompts::PathDialog::SavePreset, preferences.userPresetFolder / (name + ".json"));
}

void openDialog(const Document& document, Prompts& prompts) {
    startPathDialog(prompts, Prompts::PathDialog::Open, document.materialPath.parent_path() / "");
}

}  // namespace patina::editor
