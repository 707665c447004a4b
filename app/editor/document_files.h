#pragma once
#include <filesystem>

#include "assets/asset_cache.h"
#include <memory>
#include <vector>

#include "environment/environment.h"
#include "geometry/mesh.h"
#include "scene/scene.h"

namespace patina::editor {

struct EditorState;

// Opening and saving the document. Opening a scene, a material file, a screenshot or a glTF
// model starts a new document, as in every editor: its own path (none for a model: its Save is
// a Save as), its own undo history, and its content as what is saved, which Reset and the
// unsaved mark compare with. Applying a preset, a built-in mesh or an environment is an
// undoable edit of the document that is open.
//
// Makes `scene` the document, saved at `scenePath` (a scene file) or `materialPath` (a material
// file), or neither, with what was loaded for it: `shape`, its glTF file's mesh and model
// (required when it names a file), and `environment` (null: loaded by resolveEnvironmentShown).
// The model's first material is the one edited.
void startDocument(EditorState& state, const Scene& scene, const std::filesystem::path& scenePath,
                   const std::filesystem::path& materialPath, AssetCache::Shape shape = {},
                   std::shared_ptr<const Environment> environment = nullptr);
// File > New: the default scene as a document with no file.
void newDocument(EditorState& state);
// Asks first (state.pendingNew) when anything is unsaved; else starts it.
void requestNew(EditorState& state);
// Opens a material, scene or Patina screenshot (PNG with an embedded scene, its comparison A
// too) or a .gltf/.glb model (shown instead of the sphere, the camera framed on it, the stage
// kept) as a new document, a preset as an undoable edit of the material, or an environment
// image. A file that
// fails to load sets state.error and changes nothing else.
bool openFile(EditorState& state, const std::filesystem::path& path);
// Reads the file first: one that cannot be opened says why and asks nothing. Then, when it
// starts a new document and the one open is unsaved, asks first (state.pendingOpen); else opens.
// A glTF model is a new document too: asked for the same way, then read on a worker
// (startModelLoad).
void requestOpen(EditorState& state, const std::filesystem::path& path);
// The unsaved-changes prompt's answer about state.pendingOpen: `go` (the document was saved, or
// its changes discarded) opens it, a model on a worker or the one read already; else it stays
// closed, and a model read for it is dropped. Clears state.pendingOpen.
void answerOpen(EditorState& state, bool go);
// Opens each in turn (the command line's files): every file's error is kept, one a line, in
// state.error, so a later file does not hide an earlier one's. False when any failed.
bool openFiles(EditorState& state, const std::vector<std::filesystem::path>& paths);
// The command line's files as the window opens: as openFiles, but a glTF model named last is
// read on a worker (startModelLoad), so the window shows at once with its progress and Cancel.
// A model named before other files is read at once: they may act on it (a preset on its part).
void openStartupFiles(EditorState& state, std::vector<std::filesystem::path> paths);
// Writes the material (saveMaterialFile: atomically, the old file kept as .bak); on failure
// sets state.error, stays dirty and leaves the file on disk as it was.
bool saveMaterial(EditorState& state, const std::filesystem::path& path);
// Saves the material as a preset at `path` (".json" added when missing), its folder made if
// need be, the material renamed after the file (one undoable step) so the browser's caption
// and the file agree. Same failure rules as saveMaterial.
bool saveAsPreset(EditorState& state, const std::filesystem::path& path);
// Saves the whole scene, material inline; the scene becomes the document. Same failure rules.
bool saveScene(EditorState& state, const std::filesystem::path& path);
// Opens a glTF model on a worker (state.modelLoad, replacing one under way), applied by
// finishModelLoad as openFile applies it: the window's Open, Recent and dropped files. The
// document as it is now is the one it replaces (state.modelReplaces).
void startModelLoad(EditorState& state, const std::filesystem::path& path);
// Applies the model under way once it is read (with `wait`, waits for it) as a new document;
// its error, if it could not be read, goes to state.error and the document stays. Where the
// document was edited since the model was asked for and is unsaved, asks first
// (state.pendingOpen, answerOpen) and applies nothing. Run once a frame. True when one was
// applied.
bool finishModelLoad(EditorState& state, bool wait = false);
// Stops waiting for the model under way: the mesh shown stays.
void cancelModelLoad(EditorState& state);
// Exports what the viewport shows as glTF 2.0 (".glb" added when the name has neither .glb nor
// .gltf): the model whole, its materials as tuned, with its maps (a .gltf's images beside it);
// or the built-in mesh with the material. An export is no save: the document stays as it is.
// On failure sets state.error and leaves no file behind.
bool exportGltfFile(EditorState& state, std::filesystem::path path);

// Puts the image at `path` (PNG or JPEG) in place of map `key` of the model's material `index`:
// an undoable edit of the material, saved with the scene and kept by an export; the map keeps
// its UV set, sampler and transform. An image that cannot be read changes nothing and says why.
bool replaceMap(EditorState& state, int index, const std::string& key, const std::filesystem::path& path);
// Draws the file's own map there again (an undoable edit).
void restoreMap(EditorState& state, int index, const std::string& key);

}  // namespace patina::editor
