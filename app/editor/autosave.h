#pragma once
// Crash recovery: the working scene (material, lights, camera, display, mesh) written
// atomically a few seconds after it last changed, and offered back at the next start when the
// editor did not close normally. A clean quit removes the file.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace patina::editor {

struct EditorState;

using AutosaveClock = std::chrono::steady_clock;
// How long the scene must hold still before it is written: a slider drag writes once, after.
inline constexpr std::chrono::milliseconds kAutosaveDelay{2000};

struct Autosave {
    std::filesystem::path file;   // empty: no autosave (tests, or no config folder)
    std::string written;          // the text the file holds, or the state's at start
    std::string pending;          // a change not yet written
    AutosaveClock::time_point changedAt{};
    bool failed = false;          // the last write failed (said once in EditorState::error)
};

// What the last session left, offered until restored or discarded.
struct Recoverable {
    Scene scene;                          // its mesh resolved when it has a file
    std::filesystem::path materialPath;   // where its material was saved, if anywhere
    std::filesystem::path scenePath;      // the scene file it was, if any
    std::string savedAt;                  // local time, for the prompt
};

// The autosave document: {"format": "patina-autosave", "version": 1, "savedAt", "materialPath",
// "scenePath", "scene": a scene file's object}.
std::string autosaveText(const EditorState& state);

// At start, before any edit: remembers the state as it is (nothing to write yet) and, when the
// file holds another session's work, offers it (EditorState::recoverable). A file that cannot be
// read is reported in EditorState::error and left for the user.
void startAutosave(EditorState& state, const std::filesystem::path& file);
// Once a frame: notes a change and writes it when it has held still kAutosaveDelay. Returns how
// long until that write, or nothing when none waits (for the event loop's timeout). Writes
// nothing while a recoverable session is offered: the file still holds it.
std::optional<std::chrono::milliseconds> updateAutosave(EditorState& state, AutosaveClock::time_point now);
// The offered session becomes the edited one (one undo step back to what was there), or is
// dropped; either way the file then follows this session.
void restoreRecoverable(EditorState& state);
void discardRecoverable(EditorState& state);
// A clean quit: nothing is left to recover.
void removeAutosave(EditorState& state);

}  // namespace patina::editor
