#pragma once
// Crash recovery: the working scene (material, lights, camera, display, mesh) written
// atomically a few seconds after it last changed, and offered back at the next start when the
// editor that wrote it did not close normally. Each running editor writes its own file in the
// autosave folder and holds a lock beside it while it runs: a file whose lock is free was left
// by an editor that is gone, and only such a file is offered, or ever deleted, by another. A
// clean quit removes its own file.
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assets/asset_cache.h"
#include "scene/scene.h"

namespace patina::editor {

struct Document;
struct Interaction;
struct Jobs;
struct Prompts;

using AutosaveClock = std::chrono::steady_clock;
// How long the scene must hold still before it is written: a slider drag writes once, after.
inline constexpr std::chrono::milliseconds kAutosaveDelay{2000};

// An exclusive flock(2) on a file, held until the last copy goes; the kernel lets it go when
// the process ends in any way, SIGKILL included.
class FileLock {
public:
    // The lock on `path` (created when missing), or null when another process holds it.
    // Throws std::runtime_error when the file cannot be opened.
    static std::shared_ptr<FileLock> tryLock(const std::filesystem::path& path);
    ~FileLock();
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    FileLock(std::filesystem::path path, int fd) : path_(std::move(path)), fd_(fd) {}
    std::filesystem::path path_;
    int fd_;
};

// What an editor that is gone left, offered until restored or discarded.
struct Recoverable {
    Scene scene;
    AssetCache::Shape shape;              // its glTF file's, loaded; empty for a built-in
    std::filesystem::path materialPath;   // where its material was saved, if anywhere
    std::filesystem::path scenePath;      // the scene file it was, if any
    std::string savedAt;                  // local time, for the prompt
    std::filesystem::path file;           // the autosave it was read from
    std::shared_ptr<FileLock> lock;       // held while offered: no other editor offers it too
};

// What the restore prompt says the work is: 'Material "gold", 4 light(s).', or for a model
// 'Model engine.glb, 2 of its materials tuned, 4 light(s).'
std::string recoverableSummary(const Scene& scene);

struct Autosave {
    std::filesystem::path file;   // this editor's own; empty: no autosave (no config folder)
    std::shared_ptr<FileLock> lock;
    std::string written;          // the text the file holds, or the state's at start
    std::string pending;          // a change not yet written
    AutosaveClock::time_point changedAt{};
    bool failed = false;          // the last write failed (said once in Prompts::error)
    std::vector<Recoverable> waiting;   // found at start, offered after Jobs::recoverable
};

// The autosave document: {"format": "patina-autosave", "version": 1, "savedAt", "materialPath",
// "scenePath", "scene": a scene file's object}.
std::string autosaveText(const Document& document);

// At start, before any edit: takes a file of its own in `folder` (made when missing) under its
// lock (Jobs::autosave), remembers the document as it is (nothing to write yet) and offers each
// file there whose editor is gone (Jobs::recoverable, one at a time). A file that cannot be read
// is reported in Prompts::error and left for the user; a file of a running editor is left alone.
void startAutosave(const Document& document, Jobs& jobs, Prompts& prompts, const std::filesystem::path& folder);
// Once a frame: notes a change of the document and writes it when it has held still
// kAutosaveDelay (a failed write said once in prompts.error). Returns how long until that
// write, or nothing when none waits (for the event loop's timeout).
std::optional<std::chrono::milliseconds> updateAutosave(const Document& document, Autosave& autosave,
                                                        Prompts& prompts, AutosaveClock::time_point now);
// The offered work becomes the edited document (its own paths and history), kept at once in
// this editor's file; its old file is then deleted. Discard deletes that file. Either way the
// next file found is offered.
void restoreRecoverable(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts);
void discardRecoverable(Jobs& jobs);
// A clean quit: this editor's file and lock are removed; nothing is left to recover.
void removeAutosave(Autosave& autosave);

}  // namespace patina::editor
