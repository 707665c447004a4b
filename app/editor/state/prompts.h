#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace patina::editor {

struct Jobs;

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
    // How many times the dialog has opened: each opening's path field is a new widget (ImGui
    // keeps a field's cursor by its ID, and the last opening's, inside the new text, took what
    // was typed there). And whether the field's cursor goes to the end of its text when it next
    // has the keys (after early keys, or Enter on a folder).
    int pathDialogOpenings = 0;
    bool pathCursorToEnd = false;
    // What ReplaceMap replaces: the model's material and the map's key (model/model.h mapsOf).
    int replacedMaterial = -1;
    std::string replacedMap;
};

// Whether a prompt is up (restore, unsaved changes, a path): nothing edits the document behind
// it, neither a shortcut nor a dropped file. The restore prompt is up while Jobs offers work.
bool promptOpen(const Jobs& jobs, const Prompts& prompts);
// Warnings one a line, for the status.
std::string joinLines(const std::vector<std::string>& lines);

}  // namespace patina::editor
