#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace patina::editor {

// The largest screenshot side the View menu takes: what `patina render --width` takes.
constexpr int kLargestScreenshot = 16384;

// Sizes the user can drag, and whether the lobe panel shows (View menu), persisted between
// sessions.
struct PanelLayout {
    float leftWidth = 330.0f;
    float rightWidth = 340.0f;
    float lobeHeight = 260.0f;
    bool showLobe = true;
};

// Preferences: how the user set up the editor, which outlives a document. What
// editor_settings.cpp keeps between sessions, and the folders the editor was started with.
struct Preferences {
    bool showGizmos = true;                  // light dots and arrows over the viewport
    // Research controls (BRDF model, render path, timings, derived values, accuracy): shown
    // under Advanced, closed by default so an artist sees the material's own parameters.
    bool showAdvanced = false;
    float uiScaleSetting = 1.0f;             // times the monitor's content scale (ui_scale.h)
    PanelLayout layout;
    std::vector<std::filesystem::path> recentFiles;
    std::vector<std::filesystem::path> presetFolders;   // built-in first, then the user's
    std::filesystem::path userPresetFolder;             // where Save as preset writes
    std::filesystem::path screenshotFolder = ".";
    std::filesystem::path benchFolder = ".";            // where `patina bench` wrote its chart
    int screenshotWidth = 0, screenshotHeight = 0;      // 0: the viewport's size; kept
    std::string folderOpener = "xdg-open";              // what shows a folder (open_folder.h)
};

void rememberRecent(Preferences& preferences, const std::filesystem::path& path);
// Whether `path` is a file of one of the preset folders: opened, it is a template (Save writes
// the document, never the preset's file).
bool isPreset(const Preferences& preferences, const std::filesystem::path& path);

}  // namespace patina::editor
