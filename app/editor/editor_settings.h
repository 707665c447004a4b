#pragma once
#include <filesystem>

#include "editor_state.h"

namespace patina::editor {

// What persists between sessions, in $XDG_CONFIG_HOME/patina/settings.json
// (~/.config/patina/ without XDG_CONFIG_HOME): window size, panel sizes, UI scale, gizmos and
// Advanced shown or not, recent files, screenshot folder and the last session's material.
struct WindowGeometry {
    int width = 0;    // 0: not saved yet, windowSizeFor chooses
    int height = 0;
};

// The window's size on a monitor whose work area (the screen less panels and docks) is
// `workWidth` x `workHeight`: the saved size, or 1280 x 720 times the content scale, either
// kept inside the work area (a 1366 x 768 laptop included). Never under 640 x 400.
WindowGeometry windowSizeFor(const WindowGeometry& saved, int workWidth, int workHeight, float contentScale);

std::filesystem::path configFolder();

// Missing or unreadable settings leave the defaults (a bad file is reported in state.error,
// never fatal).
void loadSettings(EditorState& state, WindowGeometry& window, const std::filesystem::path& file);
// Returns false (and sets state.error) when the file cannot be written.
bool saveSettings(EditorState& state, const WindowGeometry& window, const std::filesystem::path& file);

}  // namespace patina::editor
