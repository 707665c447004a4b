#include "storage/autosave.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <system_error>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "state/editor_state.h"
#include "files/file_bytes.h"
#include "io/json_reader.h"
#include "io/scene_file.h"
#include "storage/save_errors.h"

namespace patina::editor {

std::string recoverableSummary(const Scene& scene) {
    const std::string lights = std::to_string(scene.lights.size()) + " light(s).";
    if (scene.meshFile.empty()) {
        return "Material \"" + scene.material.name + "\", " + lights;
    }
    return "Model " + std::filesystem::path(scene.meshFile).filename().string() + ", " +
           std::to_string(scene.modelMaterials.size()) + " of its materials tuned, " + lights;
}

namespace {
constexpr const char* kFormat = "patina-autosave";
constexpr int kVersion = 1;

// The state's scene and where its material lives, without the time: equal text, no change.
Json autosaveJson(const Document& document) {
    return Json{{"format", kFormat},
                {"version", kVersion},
                {"materialPath", document.materialPath.string()},
                {"scenePath", document.scenePath.string()},
                {"scene", sceneToJson(document.scene)}};
}

std::string localTime() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
    return text;
}

void write(Autosave& autosave, Prompts& prompts, const std::string& text) {
    Json json = Json::parse(text);
    json["savedAt"] = localTime();
    const std::string stamped = json.dump(2);
    try {
        std::filesystem::create_directories(autosave.file.parent_path());
        writeFileAtomic(autosave.file, std::vector<uint8_t>(stamped.begin(), stamped.end()));
        autosave.failed = false;
    } catch (const std::exception& error) {
        if (!autosave.failed) {   // once, not every few seconds
            prompts.error = "Autosave failed (your work is not being kept for crash recovery): " +
                          std::string(error.what());
        }
        autosave.failed = true;
    }
    autosave.written = text;
}
}  // namespace

std::shared_ptr<FileLock> FileLock::tryLock(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
        throw std::runtime_error(couldNotSave(path, std::system_error(errno, std::generic_category())));
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        ::close(fd);
        return nullptr;
    }
    return std::shared_ptr<FileLock>(new FileLock(path, fd));
}

FileLock::~FileLock() {
    ::close(fd_);   // lets the lock go
}

std::string autosaveText(const Document& document) {
    return autosaveJson(document).dump();
}

namespace {
std::filesystem::path lockFileOf(const std::filesystem::path& file) {
    return std::filesystem::path(file).replace_extension(".lock");
}

// Removes an autosave whose lock this editor holds, lock file and all.
void removeLocked(const std::filesystem::path& file, std::shared_ptr<FileLock>& lock) {
    std::error_code ignored;
    std::filesystem::remove(file, ignored);
    std::filesystem::remove(lockFileOf(file), ignored);
    lock.reset();
}

Recoverable readRecoverable(const std::filesystem::path& file, AssetCache& assets) {
    const Json json = readJsonFile(file);
    JsonObjectReader reader(json, "", file.string());
    reader.checkFormatAndVersion(kFormat, kVersion);
    Recoverable found;
    found.file = file;
    found.savedAt = reader.string("savedAt", "");
    found.materialPath = reader.string("materialPath", "");
    found.scenePath = reader.string("scenePath", "");
    const Json& scene = reader.required("scene");
    std::vector<std::string> warnings;
    found.scene = sceneFromJson(scene, file.string() + " (scene)", file.parent_path(), warnings);
    if (!found.scene.meshFile.empty()) {
        try {
            found.shape = assets.shape(found.scene);
        } catch (const std::exception&) {
            found.scene.meshFile.clear();   // the mesh file went away: the rest is still the work
        }
    }
    return found;
}

// The files in `folder` whose editor is gone, each under its lock, oldest first; errors go to
// state.error and the file stays where it is.
std::vector<Recoverable> findLeftBehind(const Jobs& jobs, Prompts& prompts, const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        if (entry.path().extension() == ".json" && entry.path() != jobs.autosave.file) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    std::vector<Recoverable> found;
    for (const std::filesystem::path& file : files) {
        try {
            std::shared_ptr<FileLock> lock = FileLock::tryLock(lockFileOf(file));
            if (!lock) {
                continue;   // its editor is running: its work is its own
            }
            Recoverable recoverable = readRecoverable(file, *jobs.assets);
            recoverable.lock = std::move(lock);
            found.push_back(std::move(recoverable));
        } catch (const std::exception& error) {
            prompts.error += (prompts.error.empty() ? "" : "\n") +
                           ("An autosave left by an earlier session could not be read; it is kept as " +
                            file.string() + ": " + error.what());
        }
    }
    return found;
}

// Lock files of editors that ended before they wrote anything (a crash at start): removed, so
// the folder does not fill up with them.
void removeStrayLocks(const std::filesystem::path& folder) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        const std::filesystem::path json = std::filesystem::path(entry.path()).replace_extension(".json");
        if (entry.path().extension() != ".lock" || std::filesystem::exists(json, error)) {
            continue;
        }
        try {
            if (std::shared_ptr<FileLock> lock = FileLock::tryLock(entry.path())) {
                removeLocked(json, lock);
            }
        } catch (const std::exception&) {
            // not ours to tidy
        }
    }
}

void offerNext(Jobs& jobs) {
    std::vector<Recoverable>& waiting = jobs.autosave.waiting;
    jobs.recoverable.reset();
    if (!waiting.empty()) {
        jobs.recoverable = std::move(waiting.front());
        waiting.erase(waiting.begin());
    }
}

// "editor-PID-MILLISECONDS.json": a name no other editor, running or gone, has used.
std::filesystem::path ownFile(const std::filesystem::path& folder) {
    const auto now = std::chrono::system_clock::now().time_since_epoch();
    const long long ms = std::chrono::duration_cast<std::chrono::milliseconds>(now).count();
    std::filesystem::path file = folder / ("editor-" + std::to_string(::getpid()) + "-" + std::to_string(ms) + ".json");
    for (int n = 2; std::filesystem::exists(file) || std::filesystem::exists(lockFileOf(file)); ++n) {
        file = folder / ("editor-" + std::to_string(::getpid()) + "-" + std::to_string(ms) + "-" + std::to_string(n) + ".json");
    }
    return file;
}
}  // namespace

void startAutosave(const Document& document, Jobs& jobs, Prompts& prompts, const std::filesystem::path& folder) {
    jobs.autosave = Autosave{};
    jobs.recoverable.reset();
    try {
        std::filesystem::create_directories(folder);
        jobs.autosave.file = ownFile(folder);
        jobs.autosave.lock = FileLock::tryLock(lockFileOf(jobs.autosave.file));
        if (!jobs.autosave.lock) {
            throw std::runtime_error(jobs.autosave.file.string() + " is locked by another editor");
        }
        // The one file that editors before per-editor files shared: offered like any other.
        std::error_code ignored;
        const std::filesystem::path shared = folder.parent_path() / "autosave.json";
        if (std::filesystem::exists(shared, ignored) && !std::filesystem::exists(folder / "editor-shared.json", ignored)) {
            std::filesystem::rename(shared, folder / "editor-shared.json", ignored);
        }
    } catch (const std::exception& error) {
        jobs.autosave.file.clear();
        prompts.error += (prompts.error.empty() ? "" : "\n") +
                       ("Autosave is off (your work is not being kept for crash recovery): " + std::string(error.what()));
    }
    jobs.autosave.written = autosaveText(document);
    removeStrayLocks(folder);
    jobs.autosave.waiting = findLeftBehind(jobs, prompts, folder);
    offerNext(jobs);
}

std::optional<std::chrono::milliseconds> updateAutosave(const Document& document, Autosave& autosave,
                                                        Prompts& prompts, AutosaveClock::time_point now) {
    if (autosave.file.empty()) {
        return std::nullopt;
    }
    std::string text = autosaveText(document);
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
    write(autosave, prompts, autosave.pending);
    autosave.pending.clear();
    return std::nullopt;
}

namespace {
// What is on disk of the restored work's files, against which it is unsaved; a new document's
// scene where it had none.
void compareWithItsFiles(Document& document, const Recoverable& found) {
    std::vector<std::string> warnings;
    document.savedScene = defaultScene();
    if (!found.scenePath.empty()) {
        try {
            document.savedScene = loadSceneFile(found.scenePath, warnings);
        } catch (const std::exception&) {
        }
    }
    document.savedMaterial = document.savedScene.material;
    if (!found.materialPath.empty()) {
        try {
            document.savedMaterial = loadMaterialFile(found.materialPath, warnings);
        } catch (const std::exception&) {
        }
    }
}
}  // namespace

void restoreRecoverable(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts) {
    if (!jobs.recoverable) {
        return;
    }
    Recoverable found = std::move(*jobs.recoverable);
    startDocument(document, interaction, jobs, found.scene, found.scenePath, found.materialPath, found.shape);
    compareWithItsFiles(document, found);
    prompts.status = "Restored the work autosaved " + found.savedAt;
    // Kept in this editor's own file before the old one goes, so a crash now loses nothing.
    if (!jobs.autosave.file.empty()) {
        write(jobs.autosave, prompts, autosaveText(document));
        jobs.autosave.pending.clear();
    }
    if (!jobs.autosave.failed) {
        removeLocked(found.file, found.lock);
    }
    offerNext(jobs);
}

void discardRecoverable(Jobs& jobs) {
    if (jobs.recoverable) {
        removeLocked(jobs.recoverable->file, jobs.recoverable->lock);
    }
    offerNext(jobs);
}

void removeAutosave(Autosave& autosave) {
    if (!autosave.file.empty()) {
        removeLocked(autosave.file, autosave.lock);
    }
}

}  // namespace patina::editor
