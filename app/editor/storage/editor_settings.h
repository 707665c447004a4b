#pragma once
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "state/document.h"
#include "state/preferences.h"
#include "state/prompts.h"

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

// Missing or unreadable settings leave the defaults (a bad file is reported in prompts.error,
// never fatal). The material the last session ended with becomes the document's.
void loadSettings(Document& document, Preferences& preferences, Prompts& prompts, WindowGeometry& window,
                  const std::filesystem::path& file);
// The preferences and the document's material, for the next session. Returns false (and sets
// prompts.error) when the file cannot be written. Atomic.
bool saveSettings(const Document& document, const Preferences& preferences, Prompts& prompts,
                  const WindowGeometry& window, const std::filesystem::path& file);

// How long a preference must hold still before it is written: a window resize writes once.
inline constexpr std::chrono::milliseconds kSettingsDelay{500};

// Writes the settings whenever a preference changes (window size, panels, recent files, ...),
// not only at a clean quit, so a crash keeps them. The material a session resumes with goes
// along but is no reason to write: crash recovery (autosave.h) keeps the work.
class SettingsWriter {
public:
    using Clock = std::chrono::steady_clock;
    // `preferences` and `window` as loaded: nothing to write yet.
    SettingsWriter(const Preferences& preferences, const WindowGeometry& window, std::filesystem::path file);
    // Once a frame; how long until a waiting write, or nothing (for the event loop's timeout).
    // A failed write is said once in prompts.error.
    std::optional<std::chrono::milliseconds> update(const Document& document, const Preferences& preferences,
                                                    Prompts& prompts, const WindowGeometry& window,
                                                    Clock::time_point now);

private:
    std::filesystem::path file_;
    std::string written_, pending_;
    Clock::time_point changedAt_{};
    bool failed_ = false;
};

}  // namespace patina::editor
