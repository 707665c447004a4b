#include "document_files.h"

#include <optional>

#include "camera_choice.h"
#include "editor_state.h"
#include "assets/prepare_scene.h"
#include "gltf/import.h"
#include "gltf/model_export.h"
#include "image/png_text.h"
#include "io/file_kinds.h"
#include "files/input_error.h"
#include "io/scene_file.h"
#include "scene/light_rig.h"
#include "save_errors.h"
#include "screenshot_comparison.h"

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

// The loaded model becomes the shown mesh: framed, the lights following its size.
void applyMesh(EditorState& state, const std::filesystem::path& path, const ModelLoad::Result& loaded) {
    const std::shared_ptr<const GltfImport>& imported = loaded.imported;
    const std::shared_ptr<const Model>& model = loaded.model;
    const std::string file = std::filesystem::absolute(path).lexically_normal().string();
    // One undoable step: the model shown, framed, and the lights following its size and place
    // (a model of hundreds of units used to swallow every point light). Its materials are its
    // own (the scene's material stays the built-in meshes'). The tuning belongs to the file it
    // was made on: another model, even with a material of the same index and name, starts as
    // its file says (reopening the same one keeps it).
    applyEdit(state, [&](Document& d) {
        const BoundingSphere before = meshBounds(d);
        const bool another = file != d.scene.meshFile;
        d.scene.meshFile = file;
        d.mesh = std::shared_ptr<const Mesh>(imported, &imported->mesh);
        fitSceneTo(d.scene, before, meshBounds(d));   // as `render --mesh` fits it
        if (another) {
            d.scene.modelMaterials.clear();
            d.scene.modelBrdf.reset();   // shaded as its file says (glTF's BRDF), whatever the last one chose
        }
        d.model = state.assets->retextured(model, d.scene);   // the same file keeps its maps replaced
    });
    state.selectedModelMaterial = 0;
    rememberCamera(state, kFrontCamera);
    state.error.clear();
    state.status = "Mesh " + path.filename().string() + modelSummary(*model);
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
    state.status = "Loading " + path.filename().string() + "...";
}

bool finishModelLoad(EditorState& state, bool wait) {
    std::erase_if(state.droppedModelLoads, [](const std::shared_ptr<ModelLoad>& load) { return load->ready(); });
    if (!state.modelLoad || (!wait && !state.modelLoad->ready())) {
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

// Whether opening `path` starts a new document (a scene, a screenshot, a material file) rather
// than editing the open one (a preset, a mesh, an environment image).
bool startsADocument(const EditorState& state, const std::filesystem::path& path) {
    const bool environment = path.extension() == ".hdr" || path.extension() == ".exr";
    return !environment && gltfExtension(path).empty() && !isPreset(state, path);
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
    if (!gltfExtension(path).empty()) {
        startModelLoad(state, path);   // read and decoded on a worker: the window keeps drawing
        return;
    }
    if (!startsADocument(state, path)) {
        openFile(state, path);   // undoable: nothing can be lost
        return;
    }
    // The file is checked before anything is asked: a missing or broken one says so at once.
    DocumentFile file;
    try {
        file = readDocumentFile(*state.assets, path);
    } catch (const std::exception& error) {
        state.error = error.what();
        return;
    }
    if (state.dirty()) {
        state.pendingOpen = path;
    } else {
        applyDocumentFile(state, path, std::move(file));
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

bool saveAsPreset(EditorState& state, const std::filesystem::path& path) {
    std::filesystem::path file = path;
    if (file.extension() != ".json") {
        file += ".json";
    }
    try {
        std::filesystem::create_directories(file.parent_path().empty() ? "." : file.parent_path());
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
        state.status = "Saved " + editedMaterial(state).name + " as the preset " + name + " in " +
                       std::filesystem::absolute(file).parent_path().string();
        return true;
    }
    if (state.scene.material.name != name) {
        applyEdit(state, [&](Document& d) { d.scene.material.name = name; });
    }
    if (!saveMaterial(state, file)) {
        return false;
    }
    state.status = "Saved preset " + name + " in " + std::filesystem::absolute(file).parent_path().string();
    return true;
}

}  // namespace patina::editor
