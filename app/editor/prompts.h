#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace patina::editor {

struct EditorState;

// Prompts: what the editor says to the user and what it waits on them for: the error and the
// status, and the dialogs and questions pending an answer.
struct Prompts {
    std::string error;                       // shown until dismissed
    std::string status;                      // last completed action
    std::filesystem::path lastScreenshot;    // its folder can be opened from the status
    std::optional<std::filesystem::path> pendingOpen;   // waits for "discard changes?"
    bool pendingNew = false;                            // File > New, waiting likewise
    bool pendingQuit = false;
    bool quitConfirmed = false;
    bool showShortcuts = false;
    // The preset browser: its search box, and the preset a Rename or Delete prompt is about.
    struct PresetBrowser {
        std::string filter;
        std::filesystem::path renaming, deleting;   // empty: no such prompt
        std::string newName;                        // typed in the Rename prompt
        std::string problem;                        // why the last try failed, said in its prompt
    } presets;
    enum class PathDialog {
        None, Open, SaveAs, SaveSceneAs, SavePreset, ExportComparison, ExportGltf, ReplaceMap
    } pathDialog = PathDialog::None;
    std::string pathDialogText;
    // Whether the path field has had the keys since the dialog opened, and whether keys typed
    // before it did were taken into pathDialogText (file_dialog.cpp takeEarlyKeys).
    bool pathFieldTaken = false, pathTypedEarly = false;
    // What ReplaceMap replaces: the model's material and the map's key (model/model.h mapsOf).
    int replacedMaterial = -1;
    std::string replacedMap;
};

// Whether a prompt is up (restore, unsaved changes, a path): nothing edits the document behind
// it, neither a shortcut nor a dropped file.
bool promptOpen(const EditorState& state);
// Warnings one a line, for the status.
std::string joinLines(const std::vector<std::string>& lines);

}  // namespace patina::editor
