#include "state/turntable.h"

#include <cmath>

#include "scene/camera_control.h"
#include "state/document.h"
#include "state/prompts.h"

namespace patina::editor {

namespace {
void remember(Turntable& turntable, const Document& document) {
    turntable.shown = document.scene.camera;
    turntable.seen = document.snapshot();
    turntable.scenePath = document.scenePath;
    turntable.materialPath = document.materialPath;
}

// Whether anything but the turntable changed the document since it last turned. The snapshot's
// shape compares the shape and not its camera, which the turn moves.
bool editedSince(const Turntable& turntable, const Document& document) {
    return document.scene.camera != turntable.shown || !(document.snapshot() == turntable.seen) ||
           document.scenePath != turntable.scenePath || document.materialPath != turntable.materialPath;
}
}  // namespace

void startTurntable(Turntable& turntable, const Document& document) {
    turntable.on = true;
    turntable.start = document.scene.camera;
    turntable.degrees = 0.0;
    remember(turntable, document);
}

void advanceTurntable(Turntable& turntable, Document& document, Prompts& prompts, double seconds) {
    if (!turntable.on) {
        return;
    }
    if (editedSince(turntable, document)) {
        turntable.on = false;
        prompts.status = "Turntable paused by an edit (View > Turntable turns on again)";
        return;
    }
    // Kept within one turn: a double counts seconds for ever, but the angle stays small.
    turntable.degrees = std::fmod(turntable.degrees + double(turntable.degreesPerSecond) * seconds, 360.0);
    document.scene.camera = turntableCamera(turntable.start, float(turntable.degrees));
    remember(turntable, document);
}

}  // namespace patina::editor
