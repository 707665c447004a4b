#pragma once
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "editor_state.h"

namespace patina::editor {

// What persists between sessions, in $XDG_CONFIG_HOME/patina/settings.json
// (~/.config/patina/ without XDG_CONFIG_HOME): window size, panel sizes, UI scale, gizmos, the
// lobe and Advanced shown or not, recent files, screenshot folder and the last session's material.
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
// Returns false (and sets state.error) when the file cannot be written. Atomic.
bool saveSettings(EditorState& state, const WindowGeometry& window, const std::filesystem::path& file);

// How long a preference must hold still before it is written: a window resize writes once.
inline constexpr std::chrono::milliseconds kSettingsDelay{500};

// Writes the settings whenever a preference changes (window size, panels, recent files, ...),
// not only at a clean quit, so a crash keeps them. The material a session resumes with goes
// along but is no reason to write: crash recovery (autosave.h) keeps the work.
class SettingsWriter {
public:
    using Clock = std::chrono::steady_clock;
    // `state` and `window` as loaded: nothing to write yet.
    SettingsWriter(const EditorState& state, const WindowGeometry& window, std::filesystem::path file);
    // Once a frame; how long until a waiting write, or nothing (for the event loop's timeout).
    // A failed write is said once in state.error.
    std::optional<std::chrono::milliseconds> update(EditorState& state, const WindowGeometry& window,
                                                    Clock::time_point now);

private:
    std::filesystem::path file_;
    std::string written_, pending_;
    Clock::time_point changedAt_{};
    bool failed_ = false;
};

}  // namespace patina::editor
