#include "storage/document_files.h"

#include <optional>
#include <utility>

#include "state/camera_choice.h"
#include "state/editor_state.h"
#include "assets/prepare_scene.h"
#include "gltf/model_export.h"
#include "picture/png_text.h"
#include "io/file_kinds.h"
#include "files/input_error.h"
#include "files/regular_file.h"
#include "io/scene_file.h"
#include "scene/light_rig.h"
#include "storage/save_errors.h"
#include "views/screenshot_comparison.h"
#include "storage/shown_path.h"

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
void applyMesh(EditorState& state, const std::filesystem::path& path,
               const std::shared_ptr<const LoadedModel>& loaded) {
    const std::shared_ptr<const Mesh> mesh(loaded, &loaded->mesh);
    const std::shared_ptr<const Model> model(loaded, &loaded->model);   // no map replaced yet
    Scene scene = state.scene;
    scene.meshFile = std::filesystem::absolute(path).lexically_normal().string();
    scene.modelMaterials.clear();
    scene.modelBrdf.reset();   // shaded as its file says (glTF's BRDF), whatever the last one chose
    fitSceneTo(scene, meshBounds(state), shapeBounds(scene, mesh.get()));   // as `render --mesh` fits it
    startDocument(state, state, state, scene, {}, {}, {mesh, model, loaded}, state.environment);
    rememberCamera(state, state.scene.camera, kFrontCamera);
    state.error.clear();
    state.status = "Opened " + path.filename().string() + modelSummary(*model);
    rememberRecent(state, path);
}

bool openMesh(EditorState& state, const std::filesystem::path& path) {
    try {
        // Before anything changes: a bad file changes nothing.
        applyMesh(state, path, state.assets->model(path));
        return true;
    } catch (const std::exception& error) {
        state.error = error.what();   // the previous mesh stays
        return false;
    }
}
}  // namespace

void startModelLoad(const Document& document, Jobs& jobs, Prompts& prompts, const std::filesystem::path& path) {
    cancelModelLoad(jobs, prompts);   // a newer choice replaces one under way
    jobs.modelLoad = std::make_shared<ModelLoad>(path, jobs.assets);
    jobs.modelReplaces = document.scene;
    prompts.status = "Loading " + path.filename().string() + "...";
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
bool dropModelLoad(Jobs& jobs) {
    if (!jobs.modelLoad) {
        return false;
    }
    jobs.modelLoad->cancel();   // its worker stops at the next image
    jobs.droppedModelLoads.push_back(std::move(jobs.modelLoad));
    return true;
}
}  // namespace

void cancelModelLoad(Jobs& jobs, Prompts& prompts) {
    if (dropModelLoad(jobs)) {
        prompts.status = "Mesh left as it was";
    }
}

void startDocument(Document& document, Interaction& interaction, Jobs& jobs, const Scene& scene,
                   const std::filesystem::path& scenePath, const std::filesystem::path& materialPath,
                   AssetCache::Shape shape, std::shared_ptr<const Environment> environment) {
    document.scene = scene;
    document.fileModel = std::move(shape.fileModel);
    document.model = std::move(shape.model);
    interaction.selectedModelMaterial = 0;
    interaction.partFilter.clear();
    interaction.partPresets.clear();
    document.environment = std::move(environment);
    document.scenePath = scenePath;
    document.materialPath = materialPath;
    document.savedScene = scene;
    document.savedMaterial = scene.material;
    document.history = UndoHistory();   // the last document's steps would restore its content under this path
    document.committed = document.snapshot();
    interaction.selectedLight = scene.lights.empty() ? -1 : 0;
    interaction.soloLight = -1;
    interaction.draggedLight = -1;
    // An environment still being prepared was chosen for the last document.
    jobs.environmentLoad.reset();
    dropModelLoad(jobs);   // the last document's model does not land in this one
    jobs.environmentFailed.clear();
}

void newDocument(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts) {
    startDocument(document, interaction, jobs, defaultScene(), {}, {});
    prompts.error.clear();
    prompts.status = "New scene";
}

void requestNew(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts) {
    if (document.dirty()) {
        prompts.pendingNew = true;
    } else {
        newDocument(document, interaction, jobs, prompts);
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

DocumentFile readDocumentFile(AssetCache& assets, PrefilterFunction prefilter, const std::filesystem::path& path) {
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
        const AssetCache::Shape shape = assets.shape(*file.scene);
        const PreparedScene prepared = prepareScene(*file.scene, shape, assets, file.warnings, prefilter);
        if (!file.scene->meshFile.empty()) {
            file.shape = shape;
        }
        file.environment = prepared.environment;
    }
    return file;
}

// Whether opening `path` starts a new document (a scene, a screenshot, a material file, a glTF
// model) rather than editing the open one (a preset, an environment image).
bool startsADocument(const Preferences& preferences, const std::filesystem::path& path) {
    const bool environment = path.extension() == ".hdr" || path.extension() == ".exr";
    return !environment && !isPreset(preferences, path);
}

// Whether `file` is a material that goes onto the part the panel edits, an undoable edit: a
// preset, or any material onto a model (the scene's own material is the built-in meshes', and a
// document of it would show nothing of it; it also dropped the model: an empty viewport).
bool ontoEditedPart(const Document& document, const Preferences& preferences, const std::filesystem::path& path,
                    const DocumentFile& file) {
    return file.material && (isPreset(preferences, path) || modelMaterialCount(document) > 0);
}

void applyDocumentFile(EditorState& state, const std::filesystem::path& path, DocumentFile file) {
    const bool onPart = ontoEditedPart(state, state, path, file);
    if (file.scene) {
        // A scene file is the document; a screenshot's scene is not a file to save into.
        startDocument(state, state, state, *file.scene, path.extension() == ".png" ? std::filesystem::path() : path, {},
                      file.shape, file.environment);
        // A screenshot reopens as what it shows: a comparison with its A, view and split, or
        // a single view.
        if (path.extension() == ".png") {
            state.compareView = CompareView::Single;
        }
        if (file.comparison) {
            state.compareA = file.comparison->a;
            state.compareView = file.comparison->view;
            state.splitPosition = file.comparison->split;
            // Both sides on the part they were on: A is that part's material.
            state.selectedModelMaterial = file.comparison->part;
        }
    } else if (onPart) {
        // A preset is a template: an undoable edit of the material; Save never writes into it
        // (Save as preset does, when asked to).
        // On a model, onto the material the panel edits: its factors, the part keeping its BRDF
        // model (a preset's is for the built-in meshes; a glTF part stays glTF's).
        Material preset = *file.material;
        if (modelMaterialCount(state) > 0) {
            preset.model = editedMaterial(state, state).model;
        }
        applyEdit(state, [&](Document& d) { setEditedMaterial(state, state, d.scene, preset); });
        if (modelMaterialCount(state) > 0) {   // the part keeps its name: the labels say which preset
            state.partPresets[state.selectedModelMaterial] = {file.material->name, editedMaterial(state, state)};
        }
    } else {
        Scene scene = state.scene;   // the stage stays: lights, camera, display and mesh, as loaded
        scene.material = *file.material;
        startDocument(state, state, state, scene, {}, path, {state.mesh(), state.model, state.fileModel},
                      state.environment);
    }
    state.error.clear();
    state.status = (onPart ? std::string(isPreset(state, path) ? "Preset " : "Material ") + file.material->name +
                                 " applied" +
                                 (modelMaterialCount(state) > 0 ? " to " + editedMaterial(state, state).name : "") +
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
        return setEnvironmentSource(state, state, state, state,
                                    std::filesystem::absolute(path).lexically_normal().string());
    }
    try {
        applyDocumentFile(state, path, readDocumentFile(*state.assets, state.uiPrefilter, path));
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
        if (!openFile(state, path) ||
            (state.environmentLoad && !finishEnvironmentLoad(state, state, state, state, true))) {
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
        startModelLoad(state, state, state, *model);   // its error, if any, joins the others once it is read
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
            file = readDocumentFile(*state.assets, state.uiPrefilter, path);
        }
    } catch (const std::exception& error) {
        state.error = error.what();
        return;
    }
    // A material onto a model's part is an undoable edit, as a preset is: nothing to ask.
    if (state.dirty() && !ontoEditedPart(state, state, path, file)) {
        state.pendingOpen = path;
    } else if (model) {
        startModelLoad(state, state, state, path);   // read and decoded on a worker: the window keeps drawing
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
            cancelModelLoad(state, state);
        }
    } else if (modelRead) {
        state.modelReplaces = state.scene;   // what was answered for: applied in the next frame
    } else if (!gltfExtension(*path).empty()) {
        startModelLoad(state, state, state, *path);
    } else {
        openFile(state, *path);
    }
}

bool saveScene(Document& document, Preferences& preferences, Prompts& prompts, const std::filesystem::path& path) {
    commitEdits(document);
    try {
        saveSceneFile(path, document.scene);
    } catch (const std::exception& error) {
        prompts.error = couldNotSave(path, error);
        return false;
    }
    document.scenePath = path;
    document.savedScene = document.scene;
    document.savedMaterial = document.scene.material;   // inline in the scene file
    prompts.error.clear();
    prompts.status = "Saved " + path.filename().string();
    rememberRecent(preferences, path);
    return true;
}

bool exportGltfFile(const Document& document, Prompts& prompts, std::filesystem::path path) {
    if (gltfExtension(path).empty()) {
        path += ".glb";
    }
    try {
        if (document.scene.meshFile.empty()) {
            exportGltf(path, *builtinMesh(document.scene.mesh), document.scene.material);
        } else if (document.model) {
            exportGltfModel(path, tunedModel(*document.model, document.scene));
        } else {
            throw std::runtime_error("the model is still loading");
        }
    } catch (const std::exception& error) {
        prompts.error = couldNotSave(path, error);
        return false;
    }
    prompts.error.clear();
    prompts.status = "Exported " + path.filename().string();
    return true;
}

namespace {
// Map `key` of the model's material `index` as a phrase: "base colour map of \"Texture\"".
std::string mapOfMaterial(const Document& document, int index, const std::string& key) {
    const ModelMaterial& material = document.model->materials.at(size_t(index));
    const auto map = mapWithKey(material, key);
    return (map ? std::string(map->name) + " map" : key) + " of \"" + material.name + "\"";
}

// The edit of the maps `index` has that `change` makes, with the model retextured to match, as
// one undoable step.
template <typename Change>
void changeMaps(Document& document, AssetCache& assets, Change&& change) {
    Scene scene = document.scene;
    change(scene);
    std::shared_ptr<const Model> model = assets.retextured(document.fileModel, scene);
    applyEdit(document, [&](Document& d) {
        d.scene.modelMaterials = scene.modelMaterials;
        d.model = std::move(model);
    });
}
}  // namespace

bool replaceMap(Document& document, AssetCache& assets, Prompts& prompts, int index, const std::string& key,
                const std::filesystem::path& path) {
    if (!document.model || index < 0 || index >= modelMaterialCount(document)) {
        return false;
    }
    const std::string what = "the " + mapOfMaterial(document, index, key);
    const std::string file = std::filesystem::absolute(path).lexically_normal().string();
    try {
        const std::shared_ptr<const ModelImage> image = assets.image(file);   // held: decoded once
        // A map switched off is switched on by its replacement: choosing an image is asking to see it.
        changeMaps(document, assets, [&](Scene& scene) {
            setMapReplacement(document, scene, index, key, file);
            setMapShown(document, scene, index, key, true);
        });
        prompts.error.clear();
        prompts.status = "Replaced " + what + " with " + path.filename().string() + ", " +
                       std::to_string(image->width) + " x " + std::to_string(image->height) + " (Ctrl+Z undoes it)";
        return true;
    } catch (const std::exception& error) {
        prompts.error = "Could not replace " + what + ": " + error.what();
        return false;
    }
}

void restoreMap(Document& document, AssetCache& assets, Prompts& prompts, int index, const std::string& key) {
    if (!document.model || index < 0 || index >= modelMaterialCount(document)) {
        return;
    }
    try {
        changeMaps(document, assets, [&](Scene& scene) { setMapReplacement(document, scene, index, key, ""); });
        prompts.status = "The file's own " + mapOfMaterial(document, index, key) + " is drawn again";
    } catch (const std::exception& error) {
        prompts.error = "Could not restore the " + mapOfMaterial(document, index, key) + ": " + error.what();
    }
}

bool saveMaterial(Document& document, Preferences& preferences, Prompts& prompts, const std::filesystem::path& path) {
    commitEdits(document);   // what was saved is a step of its own to come back to
    try {
        saveMaterialFile(path, document.scene.material);
    } catch (const std::exception& error) {
        prompts.error = couldNotSave(path, error);
        return false;
    }
    document.materialPath = path;
    document.savedMaterial = document.scene.material;
    prompts.error.clear();
    prompts.status = "Saved " + path.filename().string();
    rememberRecent(preferences, path);
    return true;
}

namespace {
// Where a preset saved as `path` goes: a name alone, or any path not from the root, into the
// user's presets folder, where the browser shows it (a bare "my copper" once went into the
// working folder, unseen); ".json" added when missing.
std::filesystem::path presetFile(const Preferences& preferences, const std::filesystem::path& path) {
    std::filesystem::path file =
        path.is_relative() && !preferences.userPresetFolder.empty() ? preferences.userPresetFolder / path : path;
    if (file.extension() != ".json") {
        file += ".json";
    }
    return file;
}

// "in your presets", or where it went and that the browser does not show it there.
std::string presetPlace(const Preferences& preferences, const std::filesystem::path& file) {
    if (isPreset(preferences, file)) {
        return "in your presets (" + shownPath(file.parent_path()) + ")";
    }
    return "as " + shownPath(file) + ", outside your presets folder (" + shownPath(preferences.userPresetFolder) +
           "): the browser does not show it";
}
}  // namespace

bool saveAsPreset(Document& document, const Interaction& interaction, Preferences& preferences, Prompts& prompts,
                  const std::filesystem::path& path) {
    const std::filesystem::path file = presetFile(preferences, path);
    try {
        std::filesystem::create_directories(file.has_parent_path() ? file.parent_path() : ".");
    } catch (const std::exception& error) {
        prompts.error = couldNotSave(file, error);
        return false;
    }
    // The preset is known by its file in the browser: the material takes the file's name.
    const std::string name = file.stem().string();
    if (modelMaterialCount(document) > 0) {   // a model's material: written as it is, its key kept
        Material preset = editedMaterial(document, interaction);
        preset.name = name;
        try {
            saveMaterialFile(file, preset);
        } catch (const std::exception& error) {
            prompts.error = couldNotSave(file, error);
            return false;
        }
        prompts.status = "Saved " + editedMaterial(document, interaction).name + " as the preset " + name + " " +
                         presetPlace(preferences, file);
        return true;
    }
    if (document.scene.material.name != name) {
        applyEdit(document, [&](Document& d) { d.scene.material.name = name; });
    }
    if (!saveMaterial(document, preferences, prompts, file)) {
        return false;
    }
    prompts.status = "Saved the preset " + name + " " + presetPlace(preferences, file);
    return true;
}

}  // namespace patina::editor
