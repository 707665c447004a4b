#pragma once
// View > Turntable: the camera turns about its target, about the vertical axis (engine
// scene/camera_control.h turntableCamera), at a set speed while on; any edit pauses it. Part of
// the interaction: not saved, not undone.
#include <filesystem>

#include "scene/scene.h"
#include "state/undo_history.h"

namespace patina::editor {

struct Document;
struct Prompts;

struct Turntable {
    bool on = false;
    float degreesPerSecond = 20.0f;   // the View menu's speed; negative turns the other way
    // Where this turn started and how far it has gone: the camera is turntableCamera(start,
    // degrees), never a sum of small turns that drifts.
    Camera start;
    double degrees = 0.0;
    // What it last saw, to tell an edit from its own turn: the camera it set, the document's
    // undoable state and the files it was opened from.
    Camera shown;
    EditSnapshot seen;
    std::filesystem::path scenePath, materialPath;
};

// Starts turning from the camera as it is now.
void startTurntable(Turntable& turntable, const Document& document);
// Turns the camera `seconds` further; first pauses instead (on = false, the status says so)
// where anything changed the document since the last turn: an edit (a slider held, an undo, a
// preset), a file opened, or the camera moved by anything else. The editor calls it once a
// frame while on.
void advanceTurntable(Turntable& turntable, Document& document, Prompts& prompts, double seconds);

}  // namespace patina::editor
