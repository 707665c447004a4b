#include "editor_settings.h"

#include <algorithm>
#include <cstdlib>

#include "image/image.h"
#include "io/json_writer.h"
#include "io/scene_file.h"
#include "files/file_bytes.h"
#include "save_errors.h"

namespace patina::editor {

std::filesystem::path configFolder() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) {
        return std::filesystem::path(xdg) / "patina";
    }
    const char* home = std::getenv("HOME");
    return std::filesystem::path(home && *home ? home : ".") / ".config" / "patina";
}

WindowGeometry windowSizeFor(const WindowGeometry& saved, int workWidth, int workHeight, float contentScale) {
    const float scale = contentScale > 0.0f ? contentScale : 1.0f;
    WindowGeometry size = saved;
    if (size.width <= 0 || size.height <= 0) {
        size = {int(1280 * scale), int(720 * scale)};
    }
    // Room for the window's title bar and borders inside the work area.
    const int roomWidth = workWidth > 0 ? workWidth - 16 : size.width;
    const int roomHeight = workHeight > 0 ? workHeight - 48 : size.height;
    return {std::max(std::min(size.width, roomWidth), 640), std::max(std::min(size.height, roomHeight), 400)};
}

void loadSettings(EditorState& state, WindowGeometry& window, const std::filesystem::path& file) {
    if (!std::filesystem::exists(file)) {
        return;
    }
    try {
        const Json json = readJsonFile(file);
        std::vector<std::string> warnings;
        JsonObjectReader reader(json, "", file.string());
        window.width = reader.integer("windowWidth", window.width, {320, 16384});
        window.height = reader.integer("windowHeight", window.height, {240, 16384});
        state.layout.leftWidth = reader.number("leftPanelWidth", state.layout.leftWidth, {100, 4000});
        state.layout.rightWidth = reader.number("rightPanelWidth", state.layout.rightWidth, {100, 4000});
        state.layout.lobeHeight = reader.number("lobePanelHeight", state.layout.lobeHeight, {60, 4000});
        state.layout.showLobe = reader.boolean("showLobe", state.layout.showLobe);
        state.uiScaleSetting = reader.number("uiScale", state.uiScaleSetting, {0.5, 3.0});
        state.showGizmos = reader.boolean("showLightGizmos", state.showGizmos);
        state.showAdvanced = reader.boolean("showAdvanced", state.showAdvanced);
        state.screenshotFolder = reader.string("screenshotFolder", state.screenshotFolder.string());
        state.screenshotWidth = reader.integer("screenshotWidth", state.screenshotWidth, {0, kLargestScreenshot});
        state.screenshotHeight = reader.integer("screenshotHeight", state.screenshotHeight, {0, kLargestScreenshot});
        if (const Json* recent = reader.child("recentFiles"); recent && recent->is_array()) {
            state.recentFiles.clear();
            for (const Json& entry : *recent) {
                if (entry.is_string()) {
                    state.recentFiles.emplace_back(entry.get<std::string>());
                }
            }
        }
        if (const Json* material = reader.child("lastMaterial")) {
            state.scene.material = materialFromJson(*material, "/lastMaterial", file.string(), true, warnings);
            state.savedMaterial = state.scene.material;
            state.committed = state.snapshot();
        }
        if (reader.has("lastMaterialPath")) {
            state.materialPath = reader.string("lastMaterialPath", "");
        }
    } catch (const std::exception& error) {
        state.error = "Settings ignored: " + std::string(error.what());
    }
}

namespace {
// The preferences (what a change of writes the file at once) and, with `session`, the material
// a new session resumes with.
Json settingsJson(const EditorState& state, const WindowGeometry& window, bool session) {
    Json recent = Json::array();
    for (const std::filesystem::path& path : state.recentFiles) {
        recent.push_back(path.string());
    }
    Json json{{"windowWidth", window.width},
              {"windowHeight", window.height},
              {"leftPanelWidth", state.layout.leftWidth},
              {"rightPanelWidth", state.layout.rightWidth},
              {"lobePanelHeight", state.layout.lobeHeight},
              {"showLobe", state.layout.showLobe},
              {"uiScale", state.uiScaleSetting},
              {"showLightGizmos", state.showGizmos},
              {"showAdvanced", state.showAdvanced},
              {"screenshotFolder", state.screenshotFolder.string()},
              {"screenshotWidth", state.screenshotWidth},
              {"screenshotHeight", state.screenshotHeight},
              {"recentFiles", recent}};
    if (session) {
        // The material as it is now (saved or not), and where it was saved, so a new session
        // resumes; "dirty" is not restored: the file on disk decides.
        json["lastMaterial"] = materialToJson(state.scene.material);
        json["lastMaterialPath"] = state.materialPath.string();
    }
    return json;
}

// Atomically: a crash while writing leaves the old file.

void writeSettings(const EditorState& state, const WindowGeometry& window, const std::filesystem::path& file) {
    std::filesystem::create_directories(file.parent_path());
    const std::string text = prettyJson(settingsJson(state, window, true));
    writeFileAtomic(file, std::vector<uint8_t>(text.begin(), text.end()));
}
}  // namespace

bool saveSettings(EditorState& state, const WindowGeometry& window, const std::filesystem::path& file) {
    try {
        writeSettings(state, window, file);
        return true;
    } catch (const std::exception& error) {
        state.error = couldNotSave(file, error);
        return false;
    }
}

SettingsWriter::SettingsWriter(const EditorState& state, const WindowGeometry& window, std::filesystem::path file)
    : file_(std::move(file)), written_(settingsJson(state, window, false).dump()) {}

std::optional<std::chrono::milliseconds> SettingsWriter::update(EditorState& state, const WindowGeometry& window,
                                                                Clock::time_point now) {
    std::string text = settingsJson(state, window, false).dump();
    if (text == written_) {
        pending_.clear();
        return std::nullopt;
    }
    if (text != pending_) {
        pending_ = std::move(text);
        changedAt_ = now;
    }
    if (now < changedAt_ + kSettingsDelay) {
        return std::chrono::ceil<std::chrono::milliseconds>(changedAt_ + kSettingsDelay - now);
    }
    try {
        writeSettings(state, window, file_);
        failed_ = false;
    } catch (const std::exception& error) {
        if (!failed_) {   // said once: a folder that cannot be written is not news at each change
            state.error = couldNotSave(file_, error);
        }
        failed_ = true;
    }
    written_ = std::move(pending_);
    pending_.clear();
    return std::nullopt;
}

}  // namespace patina::editor
