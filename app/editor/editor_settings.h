#pragma once
#include <filesystem>

#include "editor_state.h"

namespace patina::editor {

// What persists between sessions, in $XDG_CONFIG_HOME/patina/settings.json
// (~/.config/patina/ without XDG_CONFIG_HOME): window size, panel sizes, recent files,
// screenshot folder and the last session's material.
struct WindowGeometry {
    int width = 1400;
    int height = 860;
};

std::filesystem::path configFolder();

// Missing or unreadable settings leave the defaults (a bad file is reported in state.error,
// never fatal).
void loadSettings(EditorState& state, WindowGeometry& window, const std::filesystem::path& file);
// Returns false (and sets state.error) when the file cannot be written.
bool saveSettings(EditorState& state, const WindowGeometry& window, const std::filesystem::path& file);

}  // namespace patina::editor
