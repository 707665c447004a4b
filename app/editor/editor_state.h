#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "assets/asset_cache.h"
#include "gl/renderer.h"
#include "geometry/mesh.h"
#include "scene/prepared_scene.h"
#include "scene/scene.h"
#include "environment_load.h"
#include "autosave.h"
#include "undo_history.h"

namespace patina::editor {

enum class CompareView { Single, Split, SideBySide };
// What a viewport drag holds of a light: a point's or a sphere's position (a tube's middle,
// moving both ends), or one end of a tube.
enum class LightHandle { Position, TubeStart, TubeEnd };

struct LobeSettings {
    float thetaInDegrees = 45.0f;
    bool followFirstDirectional = false;
    bool luminance = false;       // else per channel
    bool logScale = false;
    bool multiplyByCosine = false;
};

// Sizes the user can drag, and whether the lobe panel shows (View menu), persisted between
// sessions.
struct PanelLayout {
    float leftWidth = 330.0f;
    float rightWidth = 340.0f;
    float lobeHeight = 260.0f;
    bool showLobe = true;
};

// Everything the editor shows is a function of this state; panels read it, draw widgets and
// write it back. No ImGui or GL types here, so it is tested without a window.
struct EditorState {
    // The default scene under a tone map that keeps highlights (a file's own choice replaces it).
    Scene scene = defaultScene();
    // What the scene names, loaded (assets/), through a cache the editor owns and the
    // environment's worker shares: its glTF file's mesh (null: the built-in kind's), and its
    // environment light's environment (kept while the light is off, for the checkbox).
    std::shared_ptr<AssetCache> assets = std::make_shared<AssetCache>();
    std::shared_ptr<const Mesh> mesh;
    std::shared_ptr<const Environment> environment;
    std::filesystem::path materialPath;      // where Save writes the material; empty: never saved
    Material savedMaterial = scene.material; // what is on disk at materialPath
    // The scene as a document: where it was opened from or saved to (empty: none), and the
    // scene as it was then (or at start), against which lights, camera, display and mesh are
    // unsaved changes.
    std::filesystem::path scenePath;
    Scene savedScene = scene;
    UndoHistory history;
    EditSnapshot committed = snapshot();     // the state history knows; edits since are pending

    int selectedLight = 0;
    int soloLight = -1;                      // -1: all enabled lights
    bool showGizmos = true;                  // light dots and arrows over the viewport
    // Research controls (BRDF model, render path, timings, derived values, accuracy): shown
    // under Advanced, closed by default so an artist sees the material's own parameters.
    bool showAdvanced = false;
    float uiScaleSetting = 1.0f;             // times the monitor's content scale (ui_scale.h)
    RenderPath renderPath = RenderPath::Single;

    std::optional<Material> compareA;        // "Set A"; B is the current material
    CompareView compareView = CompareView::Single;
    float splitPosition = 0.5f;              // split wipe divider, fraction of the width
    // The viewport's drags in progress: the light whose gizmo is held (-1: none), the divider.
    int draggedLight = -1;
    LightHandle draggedHandle = LightHandle::Position;   // which part of it
    bool draggingDivider = false;

    // How the environment is shaded in the viewport and screenshots (Advanced; not saved).
    EnvironmentShading environmentShading;
    LobeSettings lobe;
    PanelLayout layout;
    std::vector<std::filesystem::path> recentFiles;
    std::vector<std::filesystem::path> presetFolders;   // built-in first, then the user's
    std::filesystem::path userPresetFolder;             // where Save as preset writes
    std::filesystem::path screenshotFolder = ".";
    std::filesystem::path benchFolder = ".";            // where `patina bench` wrote its chart
    int screenshotWidth = 0, screenshotHeight = 0;      // 0: the viewport's size
    std::filesystem::path lastScreenshot;               // its folder can be opened from the status
    // F12's size, taken at the start of the next frame: the frame asking shows "Rendering..."
    // first, as a large screenshot keeps the window waiting for seconds.
    std::optional<std::pair<int, int>> screenshotRequested;
    std::string folderOpener = "xdg-open";              // what shows a folder (open_folder.h)

    Autosave autosave;                       // crash recovery (autosave.h)
    std::optional<Recoverable> recoverable;  // the last session's work, offered at start

    std::string error;                       // shown until dismissed
    std::string status;                      // last completed action
    std::optional<std::filesystem::path> pendingOpen;   // waits for "discard changes?"
    bool pendingNew = false;                            // File > New, waiting likewise
    // An environment file that could not be loaded for the light naming it (its error shown
    // once, not every frame); cleared when a load succeeds.
    std::string environmentFailed;
    // An environment file being made ready on a worker (setEnvironmentSource), applied by
    // finishEnvironmentLoad when done; the viewport shows its progress.
    std::shared_ptr<EnvironmentLoad> environmentLoad;
    bool pendingQuit = false;
    bool quitConfirmed = false;
    bool showShortcuts = false;
    // The preset browser: its search box, and the preset a Rename or Delete prompt is about.
    struct PresetBrowser {
        std::string filter;
        std::filesystem::path renaming, deleting;   // empty: no such prompt
        std::string newName;                        // typed in the Rename prompt
        std::string problem;                        // why the last try failed, said in its prompt
    } presets;
    enum class PathDialog { None, Open, SaveAs, SaveSceneAs, SavePreset, ExportComparison } pathDialog = PathDialog::None;
    std::string pathDialogText;

    // What differs from the files: the material from its own (or the scene's), the rest of the
    // scene from the scene as opened, saved or started with.
    bool materialChanged() const { return scene.material != savedMaterial; }
    bool sceneChanged() const;
    bool dirty() const { return materialChanged() || sceneChanged(); }
    EditSnapshot snapshot() const { return {scene.material, scene.lights, scene.display}; }
};

// The window title: the document's file name (the scene's, else the material's, else the
// material's name), a '*' while anything is unsaved.
std::string windowTitle(const EditorState& state);
// "the material", "the lights and the camera", ...: what is unsaved, for the prompt.
std::string unsavedParts(const EditorState& state);

// --- Undoable edits ---------------------------------------------------------------------
// Widgets write straight into state.scene. Whatever changed since the last commit becomes
// one undo step when commitEdits runs, which the editor does once no widget is active: a
// slider drag over many frames is one step, whatever widget made it.
void commitEdits(EditorState& state);
// A discrete edit (a button): its own step, apart from anything pending.
template <typename Apply>
void applyEdit(EditorState& state, Apply&& apply) {
    commitEdits(state);
    apply(state);
    commitEdits(state);
}
void undo(EditorState& state);
void redo(EditorState& state);

// --- Light list --------------------------------------------------------------------------
void addLight(EditorState& state, LightType type);
// Makes `source` ("builtin:NAME", an .hdr or .exr path) the scene's environment, adding one if
// there is none: loaded (and prefiltered) first, so a file that cannot be read leaves the
// previous environment as it was and says why in state.error. Undoable. A built-in is applied
// at once; a file is made ready on a worker (state.environmentLoad, replacing one under way)
// and applied by finishEnvironmentLoad. False when it failed at once.
bool setEnvironmentSource(EditorState& state, const std::string& source);
// Applies the environment load once it is done (with `wait`, waits for it): run once a frame.
// True when one was applied.
bool finishEnvironmentLoad(EditorState& state, bool wait = false);
// Makes state.environment the one the environment light names, whatever changed the light
// (open, undo, autosave restore): loaded through state.assets when it does not match (a
// built-in too: read back from the disk cache once). Run once a frame, before drawing.
void resolveEnvironmentShown(EditorState& state);
// The scene's environment light, or null.
Light* editedEnvironment(EditorState& state);
// "studio" for builtin:studio, a file's stem.
std::string environmentName(const std::string& source);
void duplicateLight(EditorState& state, int index);
void deleteLight(EditorState& state, int index);
void moveLight(EditorState& state, int index, int delta);
void toggleSolo(EditorState& state, int index);
// Whether solo leaves this light out of the picture (the list and the gizmos grey it out).
bool soloedOut(const EditorState& state, int index);

// The scene as rendered: solo applied.
Scene renderedScene(const EditorState& state);
// `shown` (renderedScene, withMaterial) with the document's loaded mesh and environment: what
// the renderer draws. Refers to `shown`, which must outlive it.
PreparedScene preparedScene(const EditorState& state, const Scene& shown);
// Aims the camera at the whole mesh (F, View > Frame mesh).
void frameMesh(EditorState& state);
Scene withMaterial(const EditorState& state, const Material& material);

// --- The document ------------------------------------------------------------------------
// Opening a scene, a material file or a screenshot starts a new document, as in every editor:
// its own path, its own undo history, and its content as what is saved, which Reset and the
// unsaved mark compare with. Applying a preset, a mesh or an environment is an undoable edit of
// the document that is open.
//
// Makes `scene` the document, saved at `scenePath` (a scene file) or `materialPath` (a material
// file), or neither, with what was loaded for it: `mesh` (required when it names a file) and
// `environment` (null: loaded by resolveEnvironmentShown).
void startDocument(EditorState& state, const Scene& scene, const std::filesystem::path& scenePath,
                   const std::filesystem::path& materialPath, std::shared_ptr<const Mesh> mesh = nullptr,
                   std::shared_ptr<const Environment> environment = nullptr);
// File > New: the default scene as a document with no file.
void newDocument(EditorState& state);
// Asks first (state.pendingNew) when anything is unsaved; else starts it.
void requestNew(EditorState& state);
// Opens a material, scene or Patina screenshot (PNG with an embedded scene, its comparison A
// too) as a new document, a preset as an undoable edit of the material, or a .gltf/.glb mesh
// (shown instead of the sphere, the camera framed on it) or an environment image. A file that
// fails to load sets state.error and changes nothing else.
bool openFile(EditorState& state, const std::filesystem::path& path);
// Reads the file first: one that cannot be opened says why and asks nothing. Then, when it
// starts a new document and the one open is unsaved, asks first (state.pendingOpen); else opens.
void requestOpen(EditorState& state, const std::filesystem::path& path);
// Whether a prompt is up (restore, unsaved changes, a path): nothing edits the document behind
// it, neither a shortcut nor a dropped file.
bool promptOpen(const EditorState& state);
// Whether `path` is a file of one of the preset folders: opened, it is a template (Save writes
// the document, never the preset's file).
bool isPreset(const EditorState& state, const std::filesystem::path& path);
// Opens each in turn (the command line's files): every file's error is kept, one a line, in
// state.error, so a later file does not hide an earlier one's. False when any failed.
bool openFiles(EditorState& state, const std::vector<std::filesystem::path>& paths);
// Writes the material (saveMaterialFile: atomically, the old file kept as .bak); on failure
// sets state.error, stays dirty and leaves the file on disk as it was.
bool saveMaterial(EditorState& state, const std::filesystem::path& path);
// Saves the material as a preset at `path` (".json" added when missing), its folder made if
// need be, the material renamed after the file (one undoable step) so the browser's caption
// and the file agree. Same failure rules as saveMaterial.
bool saveAsPreset(EditorState& state, const std::filesystem::path& path);
// Saves the whole scene, material inline; the scene becomes the document. Same failure rules.
bool saveScene(EditorState& state, const std::filesystem::path& path);
void rememberRecent(EditorState& state, const std::filesystem::path& path);

}  // namespace patina::editor
