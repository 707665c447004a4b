#pragma once
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "assets/asset_cache.h"
#include "storage/autosave.h"
#include "storage/environment_load.h"
#include "storage/model_load.h"
#include "storage/occlusion_bake.h"
#include "storage/open_folder.h"

namespace patina::editor {

struct Document;
struct Interaction;
struct Prompts;

// Jobs: the work the editor does beside the user's, over many frames: an environment or a model
// being made ready, the autosave, the last session's work offered back, the screenshot asked
// for, and the file managers it started.
struct Jobs {
    // The cache of loaded files the editor owns; the environment's worker shares it.
    std::shared_ptr<AssetCache> assets = std::make_shared<AssetCache>();
    // Where an environment made on the UI thread (a scene opened, a built-in chosen) prefilters:
    // the CPU, or the GPU's pass once the window's context is current there (runEditor). The
    // environment's worker has no context: it prefilters on the CPU.
    PrefilterFunction uiPrefilter = prefilterCube;
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
    // The shown shape's ambient occlusion being baked on a worker (resolveAmbientOcclusion), and
    // the bakes no longer wanted, kept until their workers end.
    std::shared_ptr<OcclusionBake> occlusionBake;
    std::vector<std::shared_ptr<OcclusionBake>> droppedOcclusionBakes;
    // F12's size, taken at the start of the next frame: the frame asking shows "Rendering..."
    // first, as a large screenshot keeps the window waiting for seconds.
    std::optional<std::pair<int, int>> screenshotRequested;
    // File managers opened on the screenshots' folder that were still running after their
    // moment, reaped by the next opening (open_folder.h).
    RunningOpeners folderOpeners;
};

// Makes `source` ("builtin:NAME", an .hdr or .exr path) the scene's environment, adding one if
// there is none: loaded (and prefiltered) first, so a file that cannot be read leaves the
// previous environment as it was and says why in prompts.error. Undoable; the light is selected.
// A built-in is applied at once; a file is made ready on a worker (jobs.environmentLoad,
// replacing one under way) and applied by finishEnvironmentLoad. False when it failed at once.
bool setEnvironmentSource(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts,
                          const std::string& source);
// Applies the environment load once it is done (with `wait`, waits for it): run once a frame.
// True when one was applied.
bool finishEnvironmentLoad(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts,
                           bool wait = false);
// Makes the document's environment the one the environment light names, whatever changed the
// light (open, undo, autosave restore): loaded through the assets cache when it does not match
// (a built-in too: read back from the disk cache once). Run once a frame, before drawing.
void resolveEnvironmentShown(Document& document, Jobs& jobs, Prompts& prompts);
// The shape's ambient occlusion while the display has it on (Document::occlusion): the cache's
// for the shape shown and its ground, looked up. One not baked yet is baked on a worker
// (jobs.occlusionBake: about a second for 2CylinderEngine, a built-in mesh's in milliseconds),
// and drawn from the frame after it ends; with `wait` (a screenshot), waited for. A bake that
// fails says why and turns the occlusion off. Run once a frame, before drawing.
void resolveAmbientOcclusion(Document& document, Jobs& jobs, Prompts& prompts, bool wait = false);

}  // namespace patina::editor
