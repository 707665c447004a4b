#include "editor_state.h"

#include <algorithm>

#include "scene/camera_control.h"
#include "assets/prepare_scene.h"
#include "gltf/import.h"
#include "io/input_error.h"
#include "image/png_text.h"
#include "io/scene_file.h"
#include "shading/shading.h"
#include "save_errors.h"
#include "screenshot_comparison.h"

namespace patina::editor {

namespace {
constexpr size_t kRecentFiles = 10;

bool validIndex(const EditorState& state, int index) {
    return index >= 0 && index < int(state.scene.lights.size());
}

std::string joinWarnings(const std::vector<std::string>& warnings) {
    std::string text;
    for (const std::string& warning : warnings) {
        text += (text.empty() ? "" : "\n") + warning;
    }
    return text;
}
}  // namespace

bool EditorState::sceneChanged() const {
    return scene.lights != savedScene.lights || scene.camera != savedScene.camera ||
           scene.display != savedScene.display || scene.mesh != savedScene.mesh ||
           scene.meshFile != savedScene.meshFile;
}

std::string windowTitle(const EditorState& state) {
    const std::string name = !state.scenePath.empty()      ? state.scenePath.filename().string()
                             : !state.materialPath.empty() ? state.materialPath.filename().string()
                                                           : state.scene.material.name;
    return (state.dirty() ? "*" : "") + name + " - Patina";
}

std::string unsavedParts(const EditorState& state) {
    const Scene& now = state.scene;
    const Scene& saved = state.savedScene;
    std::vector<std::string> parts;
    if (state.materialChanged()) {
        parts.push_back("the material");
    }
    if (now.lights != saved.lights) {
        parts.push_back("the lights");
    }
    if (now.camera != saved.camera) {
        parts.push_back("the camera");
    }
    if (now.display != saved.display) {
        parts.push_back("the display settings");
    }
    if (now.mesh != saved.mesh || now.meshFile != saved.meshFile) {
        parts.push_back("the mesh");
    }
    std::string text;
    for (size_t i = 0; i < parts.size(); ++i) {
        text += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
    }
    return text;
}

namespace {
bool sameValues(const Material& a, const Material& b) {
    return a.baseColor == b.baseColor && a.roughness == b.roughness && a.specular == b.specular &&
           a.metallic == b.metallic;
}

// A material's notes describe it as saved (where a preset's numbers come from): once a value is
// edited by hand they are untrue, and go in the same step; values back at the file's bring its
// notes back. An edit that sets notes too (a preset, a file) keeps its own.
void dropStaleNotes(Material& material, const Material& committed, const Material& saved) {
    if (sameValues(material, committed) || material.notes != committed.notes) {
        return;
    }
    material.notes = sameValues(material, saved) ? saved.notes : "";
}
}  // namespace

void commitEdits(EditorState& state) {
    dropStaleNotes(state.scene.material, state.committed.material, state.savedMaterial);
    EditSnapshot current = state.snapshot();
    if (current != state.committed) {
        state.history.record(std::move(state.committed));
        state.committed = std::move(current);
    }
}

namespace {
void restore(EditorState& state, const EditSnapshot& snapshot) {
    state.scene.material = snapshot.material;
    state.scene.lights = snapshot.lights;
    state.scene.display = snapshot.display;
    state.committed = snapshot;
    const int count = int(state.scene.lights.size());
    state.selectedLight = std::clamp(state.selectedLight, count ? 0 : -1, count - 1);
    if (state.soloLight >= count) {
        state.soloLight = -1;
    }
}
}  // namespace

// The status says what a step undid or redid, and an error from before it is old news.
void undo(EditorState& state) {
    commitEdits(state);
    const EditSnapshot current = state.snapshot();
    if (auto previous = state.history.undo(current)) {
        state.status = "Undid " + describeChange(*previous, current);
        state.error.clear();
        restore(state, *previous);
    } else {
        state.status = "Nothing to undo";
    }
}

void redo(EditorState& state) {
    commitEdits(state);
    const EditSnapshot current = state.snapshot();
    if (auto next = state.history.redo(current)) {
        state.status = "Redid " + describeChange(current, *next);
        state.error.clear();
        restore(state, *next);
    } else {
        state.status = "Nothing to redo";
    }
}

namespace {
int environmentIndex(const EditorState& state) {
    const std::vector<Light>& lights = state.scene.lights;
    for (size_t i = 0; i < lights.size(); ++i) {
        if (lights[i].type == LightType::Environment) {
            return int(i);
        }
    }
    return -1;
}

constexpr const char* kOneEnvironment = "A scene has one environment at most: change the one in the light list.";

// A point of the view: `depth` of the way from the camera to what it looks at, `right` and
// `up` fractions of the view's half height there (inside any view at least as wide as high).
glm::vec3 pointInView(const Camera& camera, float right, float up, float depth) {
    const glm::vec3 at = camera.position + depth * (camera.target - camera.position);
    return unprojectAtDepthOf(camera, glm::vec2(2.0f), glm::vec2(1.0f + right, 1.0f - up), at);
}
}  // namespace

void addLight(EditorState& state, LightType type) {
    if (state.scene.lights.size() >= size_t(shader::MAX_LIGHTS)) {
        state.error = "A scene holds at most " + std::to_string(shader::MAX_LIGHTS) + " lights.";
        return;
    }
    if (type == LightType::Environment && environmentIndex(state) >= 0) {
        state.error = kOneEnvironment;
        state.selectedLight = environmentIndex(state);
        return;
    }
    Light light;
    light.type = type;
    light.name = std::string(lightTypeName(type)) + " " + std::to_string(state.scene.lights.size() + 1);
    // Point, sphere and tube lights start up and to the left between the camera and what it
    // looks at, wherever the camera is, so there is a handle to drag at once (a tube used to
    // start above the picture).
    if (type == LightType::Point || type == LightType::Sphere) {
        light.position = pointInView(state.scene.camera, -0.45f, 0.45f, 0.65f);
        light.range = 10.0f;
        light.intensity = 5.0f;
        if (type == LightType::Sphere) {   // a point light keeps every other type's default
            light.sourceRadius = 0.25f;
        }
    } else if (type == LightType::Tube) {
        light.start = pointInView(state.scene.camera, -0.75f, 0.5f, 0.65f);
        light.end = pointInView(state.scene.camera, 0.05f, 0.5f, 0.65f);
        light.range = 10.0f;
        light.intensity = 8.0f;
        light.sourceRadius = 0.05f;
    } else if (type == LightType::Directional) {
        light.direction = {-0.5f, -0.7f, -0.5f};
        light.intensity = 2.0f;
    } else if (type == LightType::Hemisphere) {
        light.sky = {0.3f, 0.4f, 0.6f};
        light.ground = {0.1f, 0.08f, 0.06f};
    } else {
        light.name = "studio";   // builtin:studio, the default source
    }
    applyEdit(state, [&](EditorState& s) { s.scene.lights.push_back(light); });
    state.selectedLight = int(state.scene.lights.size()) - 1;
}

void duplicateLight(EditorState& state, int index) {
    if (!validIndex(state, index) || state.scene.lights.size() >= size_t(shader::MAX_LIGHTS)) {
        return;
    }
    Light copy = state.scene.lights[size_t(index)];
    if (copy.type == LightType::Environment) {
        state.error = kOneEnvironment;
        return;
    }
    copy.name += " copy";
    applyEdit(state, [&](EditorState& s) { s.scene.lights.insert(s.scene.lights.begin() + index + 1, copy); });
    state.selectedLight = index + 1;
}

void deleteLight(EditorState& state, int index) {
    if (!validIndex(state, index)) {
        return;
    }
    applyEdit(state, [&](EditorState& s) { s.scene.lights.erase(s.scene.lights.begin() + index); });
    if (state.soloLight == index) {
        state.soloLight = -1;
    } else if (state.soloLight > index) {
        --state.soloLight;
    }
    state.selectedLight = std::min(state.selectedLight, int(state.scene.lights.size()) - 1);
}

void moveLight(EditorState& state, int index, int delta) {
    const int target = index + delta;
    if (!validIndex(state, index) || !validIndex(state, target)) {
        return;
    }
    applyEdit(state, [&](EditorState& s) {
        std::swap(s.scene.lights[size_t(index)], s.scene.lights[size_t(target)]);
    });
    if (state.selectedLight == index) {
        state.selectedLight = target;
    }
    if (state.soloLight == index) {
        state.soloLight = target;
    } else if (state.soloLight == target) {
        state.soloLight = index;
    }
}

void toggleSolo(EditorState& state, int index) {
    state.soloLight = state.soloLight == index ? -1 : index;
}

bool soloedOut(const EditorState& state, int index) {
    return validIndex(state, state.soloLight) && index != state.soloLight;
}

Scene renderedScene(const EditorState& state) {
    Scene scene = state.scene;
    if (validIndex(state, state.soloLight)) {
        for (size_t i = 0; i < scene.lights.size(); ++i) {
            scene.lights[i].enabled = !soloedOut(state, int(i));
        }
    }
    return scene;
}

PreparedScene preparedScene(const EditorState& state, const Scene& shown) {
    return {shown, shown.meshFile.empty() ? builtinMesh(shown.mesh) : state.mesh, state.environment};
}

Scene withMaterial(const EditorState& state, const Material& material) {
    Scene scene = renderedScene(state);
    scene.material = material;
    return scene;
}

void rememberRecent(EditorState& state, const std::filesystem::path& path) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    const std::filesystem::path entry = error ? path : absolute.lexically_normal();
    auto& recent = state.recentFiles;
    recent.erase(std::remove(recent.begin(), recent.end(), entry), recent.end());
    recent.insert(recent.begin(), entry);
    if (recent.size() > kRecentFiles) {
        recent.resize(kRecentFiles);
    }
}

void frameMesh(EditorState& state) {
    if (state.scene.meshFile.empty() || !state.mesh) {
        frameCamera(state.scene.camera, glm::vec3(0.0f), state.scene.mesh == MeshKind::Torus ? 1.05f : 1.0f);
        return;
    }
    const BoundingSphere bounds = boundingSphere(*state.mesh);
    frameCamera(state.scene.camera, bounds.center, std::max(bounds.radius, 1e-3f));
}

namespace {
// "; 2 more materials and 3 textures not used (Patina reads the first material's factors)".
std::string unusedParts(const GltfImport& imported) {
    std::vector<std::string> parts;
    if (imported.materialCount > 1) {
        parts.push_back(std::to_string(imported.materialCount - 1) + " more material" +
                        (imported.materialCount > 2 ? "s" : ""));
    }
    if (imported.textureCount > 0) {
        parts.push_back(std::to_string(imported.textureCount) + " texture" + (imported.textureCount > 1 ? "s" : ""));
    }
    if (parts.empty()) {
        return "";
    }
    return "; " + (parts.size() == 2 ? parts[0] + " and " + parts[1] : parts[0]) +
           " not used (Patina reads the first material's factors)";
}

bool openMesh(EditorState& state, const std::filesystem::path& path) {
    try {
        // Before anything changes: a bad file changes nothing.
        const std::shared_ptr<const GltfImport> model = state.assets->model(path);
        const GltfImport& imported = *model;
        state.scene.meshFile = std::filesystem::absolute(path).lexically_normal().string();
        state.mesh = std::shared_ptr<const Mesh>(model, &model->mesh);
        frameMesh(state);
        std::string material = ", no material (the current one kept)";
        if (imported.material) {
            applyEdit(state, [&](EditorState& s) { s.scene.material = *imported.material; });
            material = ", material \"" + imported.material->name + "\" applied";
        }
        state.error.clear();
        state.status = "Mesh " + path.filename().string() + material + unusedParts(imported);
        rememberRecent(state, path);
        return true;
    } catch (const std::exception& error) {
        state.error = error.what();   // the previous mesh stays
        return false;
    }
}
}  // namespace

namespace {
// The loaded environment becomes the scene's (one undo step), adding a light if there is none.
void applyEnvironment(EditorState& state, const std::string& source, std::shared_ptr<const Environment> environment,
                      const std::vector<std::string>& warnings) {
    if (environmentIndex(state) < 0) {
        addLight(state, LightType::Environment);
    }
    const int index = environmentIndex(state);
    applyEdit(state, [&](EditorState& s) {
        Light& light = s.scene.lights[size_t(index)];
        // The light is named after its image until the artist names it.
        if (light.name == environmentName(light.source) || light.name == lightTypeName(LightType::Environment)) {
            light.name = environmentName(source);
        }
        light.source = source;
        s.environment = std::move(environment);   // kept while disabled, for the checkbox
    });
    state.selectedLight = index;
    state.environmentFailed.clear();
    state.error.clear();   // a load that worked: an older error is no longer news
    // Replaced pixels (real HDRIs hold a few slightly negative ones) are worth a note, not an
    // error box over the toolbar.
    state.status = "Environment " + environmentName(source) + (warnings.empty() ? "" : ": " + joinWarnings(warnings));
}
}  // namespace

bool setEnvironmentSource(EditorState& state, const std::string& source) {
    state.environmentLoad.reset();   // a newer choice replaces one under way (cancelled)
    if (!source.starts_with("builtin:")) {
        state.environmentLoad = std::make_shared<EnvironmentLoad>(source, state.assets);
        state.status = "Preparing the environment " + environmentName(source) + "...";
        return true;
    }
    std::vector<std::string> warnings;
    try {
        applyEnvironment(state, source, state.assets->environment(source, warnings), warnings);
        return true;
    } catch (const std::exception& error) {
        state.error = error.what();   // the previous environment stays
        return false;
    }
}

bool finishEnvironmentLoad(EditorState& state, bool wait) {
    if (!state.environmentLoad || (!wait && !state.environmentLoad->ready())) {
        return false;
    }
    const std::shared_ptr<EnvironmentLoad> load = std::move(state.environmentLoad);
    try {
        EnvironmentLoad::Result result = load->take();
        if (!result.environment) {
            return false;   // cancelled
        }
        applyEnvironment(state, load->source(), std::move(result.environment), result.warnings);
        return true;
    } catch (const std::exception& error) {
        state.error = error.what();   // the previous environment stays
        state.status.clear();
        return false;
    }
}

void resolveEnvironmentShown(EditorState& state) {
    const int index = environmentIndex(state);
    if (index < 0) {
        return;
    }
    const std::string& source = state.scene.lights[size_t(index)].source;
    const std::shared_ptr<const Environment>& loaded = state.environment;
    if ((loaded && loaded->source == source) || state.environmentFailed == source) {
        return;
    }
    std::vector<std::string> warnings;
    try {
        state.environment = state.assets->environment(source, warnings);
        state.environmentFailed.clear();
    } catch (const std::exception& error) {
        state.error = error.what();
        state.environmentFailed = source;
    }
}

Light* editedEnvironment(EditorState& state) {
    const int index = environmentIndex(state);
    return index < 0 ? nullptr : &state.scene.lights[size_t(index)];
}

std::string environmentName(const std::string& source) {
    if (source.starts_with("builtin:")) {
        return source.substr(8);
    }
    return std::filesystem::path(source).stem().string();
}

bool isPreset(const EditorState& state, const std::filesystem::path& path) {
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::weakly_canonical(path, error).parent_path();
    return std::any_of(state.presetFolders.begin(), state.presetFolders.end(), [&](const std::filesystem::path& f) {
        std::error_code e;
        return std::filesystem::weakly_canonical(f, e) == folder;
    });
}

void startDocument(EditorState& state, const Scene& scene, const std::filesystem::path& scenePath,
                   const std::filesystem::path& materialPath, std::shared_ptr<const Mesh> mesh,
                   std::shared_ptr<const Environment> environment) {
    state.scene = scene;
    state.mesh = std::move(mesh);
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

bool promptOpen(const EditorState& state) {
    return state.recoverable.has_value() || state.pendingOpen.has_value() || state.pendingNew ||
           state.pendingQuit || state.pathDialog != EditorState::PathDialog::None ||
           !state.presets.renaming.empty() || !state.presets.deleting.empty();
}

namespace {
// A scene, material or screenshot file, read and checked before anything changes.
struct DocumentFile {
    std::optional<Scene> scene;          // a scene file or a screenshot
    // What the scene names, loaded: its glTF file's mesh and its enabled environment.
    std::shared_ptr<const Mesh> mesh;
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
        file.scene = sceneFromPng(path, file.warnings);
        if (!file.scene) {
            throw InputError(path.string() + ": this PNG holds no Patina scene");
        }
        file.comparison = comparisonFromPng(path);
    } else {
        const Json json = readJsonFile(path);
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
        file.mesh = file.scene->meshFile.empty() ? nullptr : prepared.mesh;
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
        startDocument(state, *file.scene, path.extension() == ".png" ? std::filesystem::path() : path, {}, file.mesh,
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
        applyEdit(state, [&](EditorState& s) { s.scene.material = *file.material; });
    } else {
        Scene scene = state.scene;   // the stage stays: lights, camera, display and mesh
        scene.material = *file.material;
        startDocument(state, scene, {}, path, state.mesh, state.environment);
    }
    state.error.clear();
    const bool preset = !file.scene && isPreset(state, path);
    state.status = (preset ? "Preset " + file.material->name + " applied (Ctrl+Z undoes it)"
                           : "Opened " + path.filename().string()) +
                   (file.warnings.empty() ? "" : "\n" + joinWarnings(file.warnings));
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

void requestOpen(EditorState& state, const std::filesystem::path& path) {
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
    if (state.scene.material.name != name) {
        applyEdit(state, [&](EditorState& s) { s.scene.material.name = name; });
    }
    if (!saveMaterial(state, file)) {
        return false;
    }
    state.status = "Saved preset " + name + " in " + std::filesystem::absolute(file).parent_path().string();
    return true;
}

}  // namespace patina::editor
