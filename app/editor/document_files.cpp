#include "document_files.h"

#include <optional>
#include <utility>

#include "camera_choice.h"
#include "editor_state.h"
#include "assets/prepare_scene.h"
#include "gltf/import.h"
#include "gltf/model_export.h"
#include "image/png_text.h"
#include "io/file_kinds.h"
#include "files/input_error.h"
#include "files/regular_file.h"
#include "io/scene_file.h"
#include "scene/light_rig.h"
#include "save_errors.h"
#include "screenshot_comparison.h"
#include "shown_path.h"

namespace patina::editor {

namespace {
// ": 3 materials (\"Texture\" edited), 2 textures" and any notes of what was left out.
std::string modelSummary(const Model& model) {
    const size_t materials = model.materials.size(), images = model.images.size();
    std::string text = ": " + std::to_string(materials) + " material" + (materials == 1 ? "" : "s");
    if (materials == 1) {
        text += " (\"" + model.materials[0].name + "\", in the Material panel)";
    } else if (materials > 1) {
        text += " (the Material panel shows \"" + model.materials[0].name +
                "\"; pick another in Parts or click a part)";
    }
    if (images > 0) {
        text += ", " + std::to_string(images) + " texture image" + (images == 1 ? "" : "s");
    }
    for (const std::string& note : model.notes) {
        text += "\n" + note;
    }
    return text;
}

// The loaded model becomes a new document, as a scene file does: named for the model, with its
// own Save scene as and its own history, so that no Save writes it into the file of the scene
// open before it (an engine's scene file once took the box opened after it, without a word).
// The stage stays, as a material file keeps it: the lights (following the model's size and
// place: a model of hundreds of units used to swallow every point light), the display and the
// environment; the camera frames the model. Its materials start as its file says (the scene's
// material stays the built-in meshes').
void applyMesh(EditorState& state, const std::filesystem::path& path, const ModelLoad::Result& loaded) {
    const std::shared_ptr<const GltfImport>& imported = loaded.imported;
    const std::shared_ptr<const Mesh> mesh(imported, &imported->mesh);
    Scene scene = state.scene;
    scene.meshFile = std::filesystem::absolute(path).lexically_normal().string();
    scene.modelMaterials.clear();
    scene.modelBrdf.reset();   // shaded as its file says (glTF's BRDF), whatever the last one chose
    fitSceneTo(scene, meshBounds(state), shapeBounds(scene, mesh.get()));   // as `render --mesh` fits it
    startDocument(state, scene, {}, {}, {mesh, loaded.model}, state.environment);
    rememberCamera(state, kFrontCamera);
    state.error.clear();
    state.status = "Opened " + path.filename().string() + modelSummary(*loaded.model);
    rememberRecent(state, path);
}

bool openMesh(EditorState& state, const std::filesystem::path& path) {
    try {
        // Before anything changes: a bad file changes nothing.
        applyMesh(state, path, {state.assets->model(path), state.assets->drawnModel(path)});
        return true;
    } catch (const std::exception& error) {
        state.error = error.what();   // the previous mesh stays
        return false;
    }
}
}  // namespace

void startModelLoad(EditorState& state, const std::filesystem::path& path) {
    cancelModelLoad(state);   // a newer choice replaces one under way
    state.modelLoad = std::make_shared<ModelLoad>(path, state.assets);
    state.modelReplaces = state.scene;
    state.status = "Loading " + path.filename().string() + "...";
}

bool finishModelLoad(EditorState& state, bool wait) {
    std::erase_if(state.droppedModelLoads, [](const std::shared_ptr<ModelLoad>& load) { return load->ready(); });
    if (!state.modelLoad || (!wait && !state.modelLoad->ready())) {
        return false;
    }
    // Edited while the model was read: those edits are not dropped without asking. The load
    // waits for the answer (answerOpen).
    if (state.dirty() && state.scene != state.modelReplaces) {
        state.pendingOpen = state.modelLoad->path();
        return false;
    }
    const std::shared_ptr<ModelLoad> load = std::move(state.modelLoad);
    try {
        applyMesh(state, load->path(), load->take());
        return true;
    } catch (const std::exception& error) {
        // The previous mesh stays. An error shown already (another file's of the command line)
        // stays too: this one arrives later and would hide it.
        state.error = state.error.empty() ? error.what() : state.error + "\n" + error.what();
        state.status.clear();
        return false;
    }
}

namespace {
// The model under way, no longer wanted. Its worker is told to stop at the next image decoded
// and ends on its own, its result unused, while the editor goes on (a future waits for its
// worker when destroyed, so the load is kept until then). False when none was under way.
bool dropModelLoad(EditorState& state) {
    if (!state.modelLoad) {
        return false;
    }
    state.modelLoad->cancel();   // its worker stops at the next image
    state.droppedModelLoads.push_back(std::move(state.modelLoad));
    return true;
}
}  // namespace

void cancelModelLoad(EditorState& state) {
    if (dropModelLoad(state)) {
        state.status = "Mesh left as it was";
    }
}

void startDocument(EditorState& state, const Scene& scene, const std::filesystem::path& scenePath,
                   const std::filesystem::path& materialPath, AssetCache::Shape shape,
                   std::shared_ptr<const Environment> environment) {
    state.scene = scene;
    state.mesh = std::move(shape.mesh);
    state.model = std::move(shape.model);
    state.selectedModelMaterial = 0;
    state.partFilter.clear();
    state.partPresets.clear();
    state.environment = std::move(environment);
    state.scenePath = scenePath;
    state.materialPath = materialPath;
    state.savedScene = scene;
    state.savedMaterial = scene.material;
    state.history = UndoHistory();   // the last document's steps would restore its content under this path
    state.committed = state.snapshot();
    state.selectedLight = scene.lights.empty() ? -1 : 0;
    state.soloLight = -1;
    state.draggedLight = -1;
    // An environment still being prepared was chosen for the last document.
    state.environmentLoad.reset();
    dropModelLoad(state);   // the last document's model does not land in this one
    state.environmentFailed.clear();
}

void newDocument(EditorState& state) {
    startDocument(state, defaultScene(), {}, {});
    state.error.clear();
    state.status = "New scene";
}

void requestNew(EditorState& state) {
    if (state.dirty()) {
        state.pendingNew = true;
    } else {
        newDocument(state);
    }
}

namespace {
// A scene, material or screenshot file, read and checked before anything changes.
struct DocumentFile {
    std::optional<Scene> scene;          // a scene file or a screenshot
    // What the scene names, loaded: its glTF file's mesh and model, and its enabled environment.
    AssetCache::Shape shape;
    std::shared_ptr<const Environment> environment;
    std::optional<Material> material;    // a material file
    std::optional<ScreenshotComparison> comparison;   // a screenshot's A and view
    std::vector<std::string> warnings;
};

DocumentFile readDocumentFile(AssetCache& assets, const std::filesystem::path& path) {
    std::error_code kind;
    if (std::filesystem::is_directory(path, kind)) {
        throw InputError(path.string() +
                         " is a folder: open a material, scene, screenshot (.png) or glTF (.gltf, .glb) file");
    }
    DocumentFile file;
    if (path.extension() == ".png") {
        file.scene = screenshotScene(path, file.warnings);
        file.comparison = comparisonFromPng(path);
    } else {
        Json json;
        try {
            json = readJsonFile(path);
        } catch (const InputError&) {
            if (path.extension() == ".json") {
                throw;   // a JSON file that is wrong: where and how
            }
            throw InputError(path.string() + ": Patina opens materials and scenes (.json), its screenshots (.png), "
                                             "glTF models (.gltf, .glb) and environment images (.hdr, .exr)");
        }
        if (json.is_object() && json.value("format", Json()) == "patina-scene") {
            file.scene = sceneFromJson(json, path.string(), path.parent_path(), file.warnings);
        } else {
            file.material = materialFromJson(json, "", path.string(), true, file.warnings);
        }
    }
    // A scene's glTF and environment are read now, so a missing or bad one fails the open
    // instead of every later frame.
    if (file.scene) {
        const PreparedScene prepared = prepareScene(*file.scene, assets, file.warnings);
        if (!file.scene->meshFile.empty()) {
            file.shape = {prepared.mesh, prepared.model};
        }
        file.environment = prepared.environment;
    }
    return file;
}

// Whether opening `path` starts a new document (a scene, a screenshot, a material file, a glTF
// model) rather than editing the open one (a preset, an environment image).
bool startsADocument(const EditorState& state, const std::filesystem::path& path) {
    const bool environment = path.extension() == ".hdr" || path.extension() == ".exr";
    return !environment && !isPreset(state, path);
}

void applyDocumentFile(EditorState& state, const std::filesystem::path& path, DocumentFile file) {
    if (file.scene) {
        // A scene file is the document; a screenshot's scene is not a file to save into.
        startDocument(state, *file.scene, path.extension() == ".png" ? std::filesystem::path() : path, {}, file.shape,
                      file.environment);
        // A screenshot reopens as what it shows: a comparison with its A, view and split, or
        // a single view.
        if (path.extension() == ".png") {
            state.compareView = CompareView::Single;
        }
        if (file.comparison) {
            state.compareA = file.comparison->a;
            state.compareView = file.comparison->view;
            state.splitPosition = file.comparison->split;
        }
    } else if (isPreset(state, path)) {
        // A preset is a template: an undoable edit of the material; Save never writes into it
        // (Save as preset does, when asked to).
        // On a model, onto the material the panel edits: its factors, the part keeping its BRDF
        // model (a preset's is for the built-in meshes; a glTF part stays glTF's).
        Material preset = *file.material;
        if (modelMaterialCount(state) > 0) {
            preset.model = editedMaterial(state).model;
        }
        applyEdit(state, [&](Document& d) { setEditedMaterial(state, d.scene, preset); });
        if (modelMaterialCount(state) > 0) {   // the part keeps its name: the labels say which preset
            state.partPresets[state.selectedModelMaterial] = {file.material->name, editedMaterial(state)};
        }
    } else {
        Scene scene = state.scene;   // the stage stays: lights, camera, display and mesh
        scene.material = *file.material;
        startDocument(state, scene, {}, path);
    }
    state.error.clear();
    const bool preset = !file.scene && isPreset(state, path);
    state.status = (preset ? "Preset " + file.material->name + " applied" +
                                 (modelMaterialCount(state) > 0 ? " to " + editedMaterial(state).name : "") +
                                 " (Ctrl+Z undoes it)"
                           : "Opened " + path.filename().string()) +
                   (file.warnings.empty() ? "" : "\n" + joinLines(file.warnings));
    rememberRecent(state, path);
}
}  // namespace

bool openFile(EditorState& state, const std::filesystem::path& path) {
    if (!gltfExtension(path).empty()) {
        return openMesh(state, path);
    }
    if (path.extension() == ".hdr" || path.extension() == ".exr") {
        return setEnvironmentSource(state, std::filesystem::absolute(path).lexically_normal().string());
    }
    try {
        applyDocumentFile(state, path, readDocumentFile(*state.assets, path));
        return true;
    } catch (const std::exception& error) {
        state.error = error.what();
        return false;
    }
}

bool openFiles(EditorState& state, const std::vector<std::filesystem::path>& paths) {
    std::string errors;
    for (const std::filesystem::path& path : paths) {
        // An environment image is prepared on a worker; here it is waited for, so that its error
        // joins the others instead of replacing them when it arrives.
        if (!openFile(state, path) || (state.environmentLoad && !finishEnvironmentLoad(state, true))) {
            errors += (errors.empty() ? "" : "\n") + state.error;
        }
    }
    state.error = errors;
    return errors.empty();
}

void openStartupFiles(EditorState& state, std::vector<std::filesystem::path> paths) {
    std::optional<std::filesystem::path> model;
    if (!paths.empty() && !gltfExtension(paths.back()).empty()) {
        model = paths.back();
        paths.pop_back();
    }
    openFiles(state, paths);
    if (model) {
        startModelLoad(state, *model);   // its error, if any, joins the others once it is read
    }
}

void requestOpen(EditorState& state, const std::filesystem::path& path) {
    if (!startsADocument(state, path)) {
        openFile(state, path);   // undoable: nothing can be lost
        return;
    }
    // The file is checked before anything is asked: a missing or broken one says so at once. A
    // model, that it can be opened: the rest once it is read, on a worker.
    const bool model = !gltfExtension(path).empty();
    DocumentFile file;
    try {
        if (model) {
            RegularFile(path, 0, path.string());
        } else {
            file = readDocumentFile(*state.assets, path);
        }
    } catch (const std::exception& error) {
        state.error = error.what();
        return;
    }
    if (state.dirty()) {
        state.pendingOpen = path;
    } else if (model) {
        startModelLoad(state, path);   // read and decoded on a worker: the window keeps drawing
    } else {
        applyDocumentFile(state, path, std::move(file));
    }
}

void answerOpen(EditorState& state, bool go) {
    const std::optional<std::filesystem::path> path = std::exchange(state.pendingOpen, std::nullopt);
    if (!path) {
        return;
    }
    const bool modelRead = state.modelLoad && state.modelLoad->path() == *path;
    if (!go) {
        if (modelRead) {
            cancelModelLoad(state);
        }
    } else if (modelRead) {
        state.modelReplaces = state.scene;   // what was answered for: applied in the next frame
    } else if (!gltfExtension(*path).empty()) {
        startModelLoad(state, *path);
    } else {
        openFile(state, *path);
    }
}

bool saveScene(EditorState& state, const std::filesystem::path& path) {
    commitEdits(state);
    try {
        saveSceneFile(path, state.scene);
    } catch (const std::exception& error) {
        state.error = couldNotSave(path, error);
        return false;
    }
    state.scenePath = path;
    state.savedScene = state.scene;
    state.savedMaterial = state.scene.material;   // inline in the scene file
    state.error.clear();
    state.status = "Saved " + path.filename().string();
    rememberRecent(state, path);
    return true;
}

bool exportGltfFile(EditorState& state, std::filesystem::path path) {
    if (gltfExtension(path).empty()) {
        path += ".glb";
    }
    try {
        if (state.scene.meshFile.empty()) {
            exportGltf(path, *builtinMesh(state.scene.mesh), state.scene.material);
        } else if (state.model) {
            exportGltfModel(path, tunedModel(*state.model, state.scene));
        } else {
            throw std::runtime_error("the model is still loading");
        }
    } catch (const std::exception& error) {
        state.error = couldNotSave(path, error);
        return false;
    }
    state.error.clear();
    state.status = "Exported " + path.filename().string();
    return true;
}

namespace {
// Map `key` of the model's material `index` as a phrase: "base colour map of \"Texture\"".
std::string mapOfMaterial(const EditorState& state, int index, const std::string& key) {
    const ModelMaterial& material = state.model->materials.at(size_t(index));
    const auto map = mapWithKey(material, key);
    return (map ? std::string(map->name) + " map" : key) + " of \"" + material.name + "\"";
}

// The edit of the maps `index` has that `change` makes, with the model retextured to match, as
// one undoable step.
template <typename Change>
void changeMaps(EditorState& state, Change&& change) {
    Scene scene = state.scene;
    change(scene);
    std::shared_ptr<const Model> model = state.assets->retextured(state.model, scene);
    applyEdit(state, [&](Document& d) {
        d.scene.modelMaterials = scene.modelMaterials;
        d.model = std::move(model);
    });
}
}  // namespace

bool replaceMap(EditorState& state, int index, const std::string& key, const std::filesystem::path& path) {
    if (!state.model || index < 0 || index >= modelMaterialCount(state)) {
        return false;
    }
    const std::string what = "the " + mapOfMaterial(state, index, key);
    const std::string file = std::filesystem::absolute(path).lexically_normal().string();
    try {
        const std::shared_ptr<const ModelImage> image = state.assets->image(file);   // held: decoded once
        changeMaps(state, [&](Scene& scene) { setMapReplacement(state, scene, index, key, file); });
        state.error.clear();
        state.status = "Replaced " + what + " with " + path.filename().string() + ", " +
                       std::to_string(image->width) + " x " + std::to_string(image->height) + " (Ctrl+Z undoes it)";
        return true;
    } catch (const std::exception& error) {
        state.error = "Could not replace " + what + ": " + error.what();
        return false;
    }
}

void restoreMap(EditorState& state, int index, const std::string& key) {
    if (!state.model || index < 0 || index >= modelMaterialCount(state)) {
        return;
    }
    try {
        changeMaps(state, [&](Scene& scene) { setMapReplacement(state, scene, index, key, ""); });
        state.status = "The file's own " + mapOfMaterial(state, index, key) + " is drawn again";
    } catch (const std::exception& error) {
        state.error = "Could not restore the " + mapOfMaterial(state, index, key) + ": " + error.what();
    }
}

bool saveMaterial(EditorState& state, const std::filesystem::path& path) {
    commitEdits(state);   // what was saved is a step of its own to come back to
    try {
        saveMaterialFile(path, state.scene.material);
    } catch (const std::exception& error) {
        state.error = couldNotSave(path, error);
        return false;
    }
    state.materialPath = path;
    state.savedMaterial = state.scene.material;
    state.error.clear();
    state.status = "Saved " + path.filename().string();
    rememberRecent(state, path);
    return true;
}

namespace {
// Where a preset saved as `path` goes: a name alone, or any path not from the root, into the
// user's presets folder, where the browser shows it (a bare "my copper" once went into the
// working folder, unseen); ".json" added when missing.
std::filesystem::path presetFile(const EditorState& state, const std::filesystem::path& path) {
    std::filesystem::path file = path.is_relative() && !state.userPresetFolder.empty() ? state.userPresetFolder / path : path;
    if (file.extension() != ".json") {
        file += ".json";
    }
    return file;
}

// "in your presets", or where it went and that the browser does not show it there.
std::string presetPlace(const EditorState& state, const std::filesystem::path& file) {
    if (isPreset(state, file)) {
        return "in your presets (" + shownPath(file.parent_path()) + ")";
    }
    return "as " + shownPath(file) + ", outside your presets folder (" + shownPath(state.userPresetFolder) +
           "): the browser does not show it";
}
}  // namespace

bool saveAsPreset(EditorState& state, const std::filesystem::path& path) {
    const std::filesystem::path file = presetFile(state, path);
    try {
        std::filesystem::create_directories(file.has_parent_path() ? file.parent_path() : ".");
    } catch (const std::exception& error) {
        state.error = couldNotSave(file, error);
        return false;
    }
    // The preset is known by its file in the browser: the material takes the file's name.
    const std::string name = file.stem().string();
    if (modelMaterialCount(state) > 0) {   // a model's material: written as it is, its key kept
        Material preset = editedMaterial(state);
        preset.name = name;
        try {
            saveMaterialFile(file, preset);
        } catch (const std::exception& error) {
            state.error = couldNotSave(file, error);
            return false;
        }
        state.status = "Saved " + editedMaterial(state).name + " as the preset " + name + " " + presetPlace(state, file);
        return true;
    }
    if (state.scene.material.name != name) {
        applyEdit(state, [&](Document& d) { d.scene.material.name = name; });
    }
    if (!saveMaterial(state, file)) {
        return false;
    }
    state.status = "Saved the preset " + name + " " + presetPlace(state, file);
    return true;
}

}  // namespace patina::editor
