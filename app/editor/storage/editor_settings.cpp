#include "storage/editor_settings.h"

#include <algorithm>
#include <cstdlib>

#include "image/image.h"
#include "io/json_writer.h"
#include "io/scene_file.h"
#include "files/file_bytes.h"
#include "storage/save_errors.h"

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

void loadSettings(Document& document, Preferences& preferences, Prompts& prompts, WindowGeometry& window,
                  const std::filesystem::path& file) {
    if (!std::filesystem::exists(file)) {
        return;
    }
    try {
        const Json json = readJsonFile(file);
        std::vector<std::string> warnings;
        JsonObjectReader reader(json, "", file.string());
        window.width = reader.integer("windowWidth", window.width, {320, 16384});
        window.height = reader.integer("windowHeight", window.height, {240, 16384});
        preferences.layout.leftWidth = reader.number("leftPanelWidth", preferences.layout.leftWidth, {100, 4000});
        preferences.layout.rightWidth = reader.number("rightPanelWidth", preferences.layout.rightWidth, {100, 4000});
        preferences.layout.lobeHeight = reader.number("lobePanelHeight", preferences.layout.lobeHeight, {60, 4000});
        preferences.layout.showLobe = reader.boolean("showLobe", preferences.layout.showLobe);
        preferences.uiScaleSetting = reader.number("uiScale", preferences.uiScaleSetting, {0.5, 3.0});
        preferences.showGizmos = reader.boolean("showLightGizmos", preferences.showGizmos);
        preferences.showAdvanced = reader.boolean("showAdvanced", preferences.showAdvanced);
        preferences.screenshotFolder = reader.string("screenshotFolder", preferences.screenshotFolder.string());
        preferences.screenshotWidth =
            reader.integer("screenshotWidth", preferences.screenshotWidth, {0, kLargestScreenshot});
        preferences.screenshotHeight =
            reader.integer("screenshotHeight", preferences.screenshotHeight, {0, kLargestScreenshot});
        if (const Json* recent = reader.child("recentFiles"); recent && recent->is_array()) {
            preferences.recentFiles.clear();
            for (const Json& entry : *recent) {
                if (entry.is_string()) {
                    preferences.recentFiles.emplace_back(entry.get<std::string>());
                }
            }
        }
        if (const Json* material = reader.child("lastMaterial")) {
            document.scene.material = materialFromJson(*material, "/lastMaterial", file.string(), true, warnings);
            document.savedMaterial = document.scene.material;
            document.committed = document.snapshot();
        }
        if (reader.has("lastMaterialPath")) {
            document.materialPath = reader.string("lastMaterialPath", "");
        }
    } catch (const std::exception& error) {
        prompts.error = "Settings ignored: " + std::string(error.what());
    }
}

namespace {
// The preferences: what a change of writes the file at once.
Json preferencesJson(const Preferences& preferences, const WindowGeometry& window) {
    Json recent = Json::array();
    for (const std::filesystem::path& path : preferences.recentFiles) {
        recent.push_back(path.string());
    }
    return Json{{"windowWidth", window.width},
                {"windowHeight", window.height},
                {"leftPanelWidth", preferences.layout.leftWidth},
                {"rightPanelWidth", preferences.layout.rightWidth},
                {"lobePanelHeight", preferences.layout.lobeHeight},
                {"showLobe", preferences.layout.showLobe},
                {"uiScale", preferences.uiScaleSetting},
                {"showLightGizmos", preferences.showGizmos},
                {"showAdvanced", preferences.showAdvanced},
                {"screenshotFolder", preferences.screenshotFolder.string()},
                {"screenshotWidth", preferences.screenshotWidth},
                {"screenshotHeight", preferences.screenshotHeight},
                {"recentFiles", recent}};
}

// The preferences and the material a new session resumes with, atomically: a crash while
// writing leaves the old file.
void writeSettings(const Document& document, const Preferences& preferences, const WindowGeometry& window,
                   const std::filesystem::path& file) {
    Json json = preferencesJson(preferences, window);
    // The material as it is now (saved or not), and where it was saved, so a new session
    // resumes; "dirty" is not restored: the file on disk decides.
    json["lastMaterial"] = materialToJson(document.scene.material);
    json["lastMaterialPath"] = document.materialPath.string();
    std::filesystem::create_directories(file.parent_path());
    const std::string text = prettyJson(json);
    writeFileAtomic(file, std::vector<uint8_t>(text.begin(), text.end()));
}
}  // namespace

bool saveSettings(const Document& document, const Preferences& preferences, Prompts& prompts,
                  const WindowGeometry& window, const std::filesystem::path& file) {
    try {
        writeSettings(document, preferences, window, file);
        return true;
    } catch (const std::exception& error) {
        prompts.error = couldNotSave(file, error);
        return false;
    }
}

SettingsWriter::SettingsWriter(const Preferences& preferences, const WindowGeometry& window, std::filesystem::path file)
    : file_(std::move(file)), written_(preferencesJson(preferences, window).dump()) {}

std::optional<std::chrono::milliseconds> SettingsWriter::update(const Document& document,
                                                                const Preferences& preferences, Prompts& prompts,
                                                                const WindowGeometry& window, Clock::time_point now) {
    std::string text = preferencesJson(preferences, window).dump();
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
        writeSettings(document, preferences, window, file_);
        failed_ = false;
    } catch (const std::exception& error) {
        if (!failed_) {   // said once: a folder that cannot be written is not news at each change
            prompts.error = couldNotSave(file_, error);
        }
        failed_ = true;
    }
    written_ = std::move(pending_);
    pending_.clear();
    return std::nullopt;
}

}  // namespace patina::editor
