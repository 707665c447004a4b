#include "autosave.h"

#include <ctime>
#include <system_error>

#include "editor_state.h"
#include "gltf/scene_mesh.h"
#include "io/file_bytes.h"
#include "io/json_reader.h"
#include "io/scene_file.h"

namespace patina::editor {

namespace {
constexpr const char* kFormat = "patina-autosave";
constexpr int kVersion = 1;

// The state's scene and where its material lives, without the time: equal text, no change.
Json autosaveJson(const EditorState& state) {
    return Json{{"format", kFormat},
                {"version", kVersion},
                {"materialPath", state.materialPath.string()},
                {"scenePath", state.scenePath.string()},
                {"scene", sceneToJson(state.scene)}};
}

std::string localTime() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
    return text;
}

void write(EditorState& state, const std::string& text) {
    Json json = Json::parse(text);
    json["savedAt"] = localTime();
    const std::string stamped = json.dump(2);
    try {
        std::filesystem::create_directories(state.autosave.file.parent_path());
        writeFileAtomic(state.autosave.file, std::vector<uint8_t>(stamped.begin(), stamped.end()));
        state.autosave.failed = false;
    } catch (const std::exception& error) {
        if (!state.autosave.failed) {   // once, not every few seconds
            state.error = "Autosave failed (your work is not being kept for crash recovery): " +
                          std::string(error.what());
        }
        state.autosave.failed = true;
    }
    state.autosave.written = text;
}
}  // namespace

std::string autosaveText(const EditorState& state) {
    return autosaveJson(state).dump();
}

void startAutosave(EditorState& state, const std::filesystem::path& file) {
    state.autosave = Autosave{};
    state.autosave.file = file;
    state.autosave.written = autosaveText(state);
    std::error_code missing;
    if (!std::filesystem::exists(file, missing)) {
        return;
    }
    try {
        const Json json = readJsonFile(file);
        JsonObjectReader reader(json, "", file.string());
        reader.checkFormatAndVersion(kFormat, kVersion);
        Recoverable found;
        found.savedAt = reader.string("savedAt", "");
        found.materialPath = reader.string("materialPath", "");
        found.scenePath = reader.string("scenePath", "");
        const Json& scene = reader.required("scene");
        std::vector<std::string> warnings;
        found.scene = sceneFromJson(scene, file.string() + " (scene)", file.parent_path(), warnings);
        if (!found.scene.meshFile.empty()) {
            try {
                resolveMesh(found.scene);
            } catch (const std::exception&) {
                found.scene.meshFile.clear();   // the mesh file went away: the rest is still the work
            }
        }
        state.recoverable = std::move(found);
    } catch (const std::exception& error) {
        state.error = "The last session's autosave could not be read; it is kept as " + file.string() +
                      ": " + error.what();
    }
}

std::optional<std::chrono::milliseconds> updateAutosave(EditorState& state, AutosaveClock::time_point now) {
    Autosave& autosave = state.autosave;
    if (autosave.file.empty() || state.recoverable) {
        return std::nullopt;
    }
    std::string text = autosaveText(state);
    if (text == autosave.written) {
        autosave.pending.clear();
        return std::nullopt;
    }
    if (text != autosave.pending) {
        autosave.pending = std::move(text);
        autosave.changedAt = now;
    }
    const auto due = autosave.changedAt + kAutosaveDelay;
    if (now < due) {
        return std::chrono::ceil<std::chrono::milliseconds>(due - now);
    }
    write(state, autosave.pending);
    autosave.pending.clear();
    return std::nullopt;
}

void restoreRecoverable(EditorState& state) {
    if (!state.recoverable) {
        return;
    }
    const Recoverable found = std::move(*state.recoverable);
    state.recoverable.reset();
    applyScene(state, found.scene);
    commitEdits(state);   // one undo step back to what was there before
    state.materialPath = found.materialPath;
    state.scenePath = found.scenePath;
    // As for the material below: the scene file on disk, if there is one, is what is saved.
    if (!found.scenePath.empty()) {
        try {
            std::vector<std::string> warnings;
            state.savedScene = loadSceneFile(found.scenePath, warnings);
        } catch (const std::exception&) {
        }
    }
    // The file on disk decides whether the restored material is saved; without one, it is
    // compared with what the editor started with, as always.
    if (!found.materialPath.empty()) {
        try {
            std::vector<std::string> warnings;
            state.savedMaterial = loadMaterialFile(found.materialPath, warnings);
        } catch (const std::exception&) {
        }
    }
    state.status = "Restored the work autosaved " + found.savedAt;
}

void discardRecoverable(EditorState& state) {
    state.recoverable.reset();
    removeAutosave(state);
    state.autosave.written = autosaveText(state);
}

void removeAutosave(EditorState& state) {
    if (!state.autosave.file.empty()) {
        std::error_code ignored;
        std::filesystem::remove(state.autosave.file, ignored);
    }
}

}  // namespace patina::editor
