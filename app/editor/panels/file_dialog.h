#pragma once
// The path dialog of Open, Save material as, Save scene as, Save as preset and Export
// comparison: a title and prompt per action, a path field, and the folder it points into
// listed below it, filtered to the action's file types (and, to open, to what is typed).
#include <filesystem>
#include <string>
#include <vector>

#include "editor_services.h"
#include "editor_state.h"

namespace patina::editor {

struct PathDialogKind {
    const char* title;                     // the dialog's title
    const char* prompt;                    // what it asks for
    const char* verb;                      // its button
    std::vector<std::string> extensions;   // the files it lists
    // Whether the name typed filters the list: to find a file to open, yes; a save's new name
    // matches nothing, and the folder it goes into stays listed.
    bool filterByName = false;
};
const PathDialogKind& pathDialogKind(EditorState::PathDialog dialog);

struct ListedEntry {
    std::filesystem::path path;
    bool folder = false;
};
// Where a relative path typed in `dialog` is: the user's presets folder for Save as preset (a
// name alone goes there, as saveAsPreset takes it), else the working folder (empty).
std::filesystem::path relativeBase(const EditorState& state, EditorState::PathDialog dialog);
// The folder `typed` points into (the text up to its last '/', a relative one inside `base`).
std::filesystem::path typedFolder(const std::string& typed, const std::filesystem::path& base = {});
// That folder's entries, folders first then files of `dialog`'s types; for Open, each whose
// name contains what is typed after that '/' (any case).
std::vector<ListedEntry> listForDialog(const std::string& typed, EditorState::PathDialog dialog,
                                       const std::filesystem::path& base = {});

// Enter in the path field: a folder (a relative one inside `base`) is entered (the text becomes
// "folder/", and true is returned); anything else is to be confirmed (false).
bool enterFolder(std::string* typed, const std::filesystem::path& base = {});

void startPathDialog(EditorState& state, EditorState::PathDialog kind, const std::filesystem::path& initial);
// The dialog itself, while state.pathDialog is not None.
void drawPathDialog(EditorState& state, EditorServices& services);

}  // namespace patina::editor
