#pragma once
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "assets/asset_cache.h"
#include "autosave.h"
#include "environment_load.h"
#include "model_load.h"

namespace patina::editor {

struct EditorState;

// Jobs: the work the editor does beside the user's, over many frames: an environment being
// made ready, the autosave, and the last session's work offered back.
struct Jobs {
    // The cache of loaded files the editor owns; the environment's worker shares it.
    std::shared_ptr<AssetCache> assets = std::make_shared<AssetCache>();
    Autosave autosave;                       // crash recovery (autosave.h)
    std::optional<Recoverable> recoverable;  // the last session's work, offered at start
    // An environment file that could not be loaded for the light naming it (its error shown
    // once, not every frame); cleared when a load succeeds.
    std::string environmentFailed;
    // An environment file being made ready on a worker (setEnvironmentSource), applied by
    // finishEnvironmentLoad when done; the viewport shows its progress.
    std::shared_ptr<EnvironmentLoad> environmentLoad;
    // A glTF model being read on a worker (startModelLoad), applied by finishModelLoad; and the
    // cancelled ones, kept until their workers end so that dropping them never waits.
    std::shared_ptr<ModelLoad> modelLoad;
    // The document that model replaces, as it was when it was asked for: edited since and
    // unsaved, it is not replaced without asking again.
    Scene modelReplaces;
    std::vector<std::shared_ptr<ModelLoad>> droppedModelLoads;
    // F12's size, taken at the start of the next frame: the frame asking shows "Rendering..."
    // first, as a large screenshot keeps the window waiting for seconds.
    std::optional<std::pair<int, int>> screenshotRequested;
};

// Makes `source` ("builtin:NAME", an .hdr or .exr path) the scene's environment, adding one if
// there is none: loaded (and prefiltered) first, so a file that cannot be read leaves the
// previous environment as it was and says why in state.error. Undoable. A built-in is applied
// at once; a file is made ready on a worker (state.environmentLoad, replacing one under way)
// and applied by finishEnvironmentLoad. False when it failed at once.
bool setEnvironmentSource(EditorState& state, const std::string& source);
// Applies the environment load once it is done (with `wait`, waits for it): run once a frame.
// True when one was applied.
bool finishEnvironmentLoad(EditorState& state, bool wait = false);
// Makes the document's environment the one the environment light names, whatever changed the
// light (open, undo, autosave restore): loaded through the assets cache when it does not match
// (a built-in too: read back from the disk cache once). Run once a frame, before drawing.
void resolveEnvironmentShown(EditorState& state);

}  // namespace patina::editor
