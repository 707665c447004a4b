#include "state/document.h"

#include "assets/asset_cache.h"

#include <algorithm>

#include "state/editor_state.h"
#include "geometry/mesh.h"
#include "scene/camera_control.h"
#include "scene/light_rig.h"
#include "views/text_match.h"

namespace patina::editor {

bool Document::sceneChanged() const {
    return scene.lights != savedScene.lights || scene.camera != savedScene.camera ||
           scene.display != savedScene.display || scene.mesh != savedScene.mesh ||
           scene.meshFile != savedScene.meshFile || scene.modelMaterials != savedScene.modelMaterials ||
           scene.modelBrdf != savedScene.modelBrdf || scene.bookmarks != savedScene.bookmarks;
}

int Document::environmentIndex() const {
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        if (scene.lights[i].type == LightType::Environment) {
            return int(i);
        }
    }
    return -1;
}

std::string windowTitle(const Document& document) {
    const std::string name = !document.scenePath.empty()       ? document.scenePath.filename().string()
                             : !document.scene.meshFile.empty() ? std::filesystem::path(document.scene.meshFile).filename().string()
                             : !document.materialPath.empty()   ? document.materialPath.filename().string()
                                                                : document.scene.material.name;
    return (document.dirty() ? "*" : "") + name + " - Patina";
}

void discardChanges(Document& document, AssetCache& assets) {
    Scene& scene = document.scene;
    const Scene& saved = document.savedScene;
    scene.material = document.savedMaterial;
    scene.lights = saved.lights;
    scene.camera = saved.camera;
    scene.bookmarks = saved.bookmarks;
    scene.display = saved.display;
    if (scene.mesh == saved.mesh && scene.meshFile == saved.meshFile) {
        scene.modelMaterials = saved.modelMaterials;
        scene.modelBrdf = saved.modelBrdf;
        if (document.fileModel) {
            document.model = assets.retextured(document.fileModel, scene);
        }
    }
    document.history = UndoHistory();
    document.committed = document.snapshot();
}

std::string unsavedParts(const Document& document) {
    const Scene& now = document.scene;
    const Scene& saved = document.savedScene;
    std::vector<std::string> parts;
    if (document.materialChanged()) {
        parts.push_back("the material");
    }
    if (now.lights != saved.lights) {
        parts.push_back("the lights");
    }
    if (now.camera != saved.camera) {
        parts.push_back("the camera");
    }
    if (now.bookmarks != saved.bookmarks) {
        parts.push_back("the camera bookmarks");
    }
    if (now.display != saved.display) {
        parts.push_back("the display settings");
    }
    if (now.mesh != saved.mesh || now.meshFile != saved.meshFile) {
        parts.push_back("the mesh");
    }
    if (now.modelMaterials != saved.modelMaterials || now.modelBrdf != saved.modelBrdf) {
        parts.push_back("the model's materials");
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

bool commitEdits(Document& document) {
    dropStaleNotes(document.scene.material, document.committed.material, document.savedMaterial);
    EditSnapshot current = document.snapshot();
    if (current == document.committed) {
        return false;
    }
    document.history.record(std::move(document.committed));
    document.committed = std::move(current);
    return true;
}

namespace {
void restore(Document& document, Interaction& interaction, const EditSnapshot& snapshot) {
    document.scene.material = snapshot.material;
    document.scene.lights = snapshot.lights;
    document.scene.display = snapshot.display;
    document.scene.modelMaterials = snapshot.modelMaterials;
    document.scene.modelBrdf = snapshot.modelBrdf;
    document.scene.bookmarks = snapshot.bookmarks;
    document.model = snapshot.shape.model;   // the same file with the maps it had replaced, or another
    if (!(document.shownShape() == snapshot.shape)) {   // the shape it had, as it was framed
        document.scene.mesh = snapshot.shape.kind;
        document.scene.meshFile = snapshot.shape.file;
        document.fileModel = snapshot.shape.fileModel;
        document.model = snapshot.shape.model;
        document.scene.camera = snapshot.shape.camera;
        interaction.selectedModelMaterial = 0;
    }
    document.committed = snapshot;
    const int count = int(document.scene.lights.size());
    interaction.selectedLight = std::clamp(interaction.selectedLight, count ? 0 : -1, count - 1);
    if (interaction.soloLight >= count) {
        interaction.soloLight = -1;
    }
}
}  // namespace

// An error from before the step is old news.
void undo(Document& document, Interaction& interaction, Prompts& prompts) {
    commitEdits(document);
    const EditSnapshot current = document.snapshot();
    if (auto previous = document.history.undo(current)) {
        prompts.status = "Undid " + describeChange(*previous, current);
        prompts.error.clear();
        restore(document, interaction, *previous);
    } else {
        prompts.status = "Nothing to undo";
    }
}

void redo(Document& document, Interaction& interaction, Prompts& prompts) {
    commitEdits(document);
    const EditSnapshot current = document.snapshot();
    if (auto next = document.history.redo(current)) {
        prompts.status = "Redid " + describeChange(current, *next);
        prompts.error.clear();
        restore(document, interaction, *next);
    } else {
        prompts.status = "Nothing to redo";
    }
}

BoundingSphere meshBounds(const Document& document) {
    return shapeBounds(document.scene, document.mesh().get());
}

float intensityScale(const Document& document, const Light& light) {
    const bool scaled = light.type == LightType::Point || light.type == LightType::Sphere || light.type == LightType::Tube;
    if (!scaled || document.scene.meshFile.empty()) {
        return 1.0f;
    }
    const float radius = meshBounds(document).radius;
    return radius * radius;
}

void frameMesh(Document& document) {
    const BoundingSphere bounds = meshBounds(document);
    frameCamera(document.scene.camera, bounds.center, bounds.radius);
}

void chooseBuiltinMesh(Document& document, MeshKind kind) {
    applyEdit(document, [&](Document& d) {   // one step, the lights' return with it
        const bool fromFile = !d.scene.meshFile.empty();
        const BoundingSphere before = meshBounds(d);
        d.scene.mesh = kind;
        d.scene.meshFile.clear();
        d.fileModel.reset();   // the built-in kind's mesh
        d.model.reset();
        if (fromFile) {   // back from a model: the camera and the lights return to the unit scale
            frameMesh(d);
            moveLightRig(d.scene.lights, before, {glm::vec3(0.0f), 1.0f});
        }
    });
}

PreparedScene sceneToDraw(const Document& document, const Scene& shown) {
    const bool file = !shown.meshFile.empty();
    return {shown, file ? document.mesh() : builtinMesh(shown.mesh), document.environment,
            file ? document.model : nullptr, shown.display.ambientOcclusion ? document.occlusion : nullptr};
}

std::vector<std::string> partNodes(const Document& document, int index) {
    std::vector<std::string> nodes;
    if (index < 0 || index >= modelMaterialCount(document)) {
        return nodes;
    }
    for (const DrawItem& draw : document.model->draws) {
        if (draw.material == index && std::find(nodes.begin(), nodes.end(), draw.node) == nodes.end()) {
            nodes.push_back(draw.node);
        }
    }
    return nodes;
}

bool partMatches(const Document& document, int index, const std::string& filter) {
    if (filter.empty()) {
        return true;
    }
    const std::vector<std::string> nodes = partNodes(document, index);
    return containsAnyCase(document.model->materials.at(size_t(index)).name, filter) ||
           std::any_of(nodes.begin(), nodes.end(), [&](const std::string& node) { return containsAnyCase(node, filter); });
}

int modelMaterialCount(const Document& document) {
    return document.model && !document.scene.meshFile.empty() ? int(document.model->materials.size()) : 0;
}

namespace {
// Part `index` as the scene has it, its own BRDF model kept (Scene::modelBrdf not applied).
Material ownModelMaterial(const Document& document, const Scene& scene, int index) {
    const ModelMaterial& file = document.model->materials.at(size_t(index));
    if (const ModelMaterialEdit* edit = patina::editOf(scene, index, file)) {
        return edit->material;
    }
    Material material;
    static_cast<MaterialParameters&>(material) = file.factors;
    material.name = file.name;
    return material;
}
}  // namespace

Material modelMaterial(const Document& document, const Scene& scene, int index) {
    Material material = ownModelMaterial(document, scene, index);
    material.model = scene.modelBrdf.value_or(material.model);   // as sceneDraws shades it
    return material;
}

void setModelMaterial(const Document& document, Scene& scene, int index, Material material) {
    material.name = document.model->materials.at(size_t(index)).name;
    if (scene.modelBrdf) {
        // One model shades every part (Scene::modelBrdf): the part keeps its own beneath it.
        material.model = ownModelMaterial(document, scene, index).model;
    }
    for (ModelMaterialEdit& edit : scene.modelMaterials) {
        if (edit.index == index) {
            edit.material = std::move(material);
            return;
        }
    }
    scene.modelMaterials.push_back({index, std::move(material)});
}

namespace {
// The scene's edit of the model's material `index`, or null (Scene or const Scene).
template <typename SceneType>
auto editOf(SceneType& scene, int index) -> decltype(&scene.modelMaterials.front()) {
    for (auto& edit : scene.modelMaterials) {
        if (edit.index == index) {
            return &edit;
        }
    }
    return nullptr;
}
}  // namespace

bool mapShown(const Scene& scene, int index, const std::string& key) {
    const ModelMaterialEdit* edit = editOf(scene, index);
    return !edit || std::find(edit->mapsOff.begin(), edit->mapsOff.end(), key) == edit->mapsOff.end();
}

void setMapShown(const Document& document, Scene& scene, int index, const std::string& key, bool shown) {
    if (mapShown(scene, index, key) == shown) {
        return;
    }
    if (!editOf(scene, index)) {
        setModelMaterial(document, scene, index, modelMaterial(document, scene, index));
    }
    std::vector<std::string>& off = editOf(scene, index)->mapsOff;
    if (shown) {
        std::erase(off, key);
    } else {
        off.push_back(key);
    }
}

std::string mapReplacement(const Scene& scene, int index, const std::string& key) {
    const ModelMaterialEdit* edit = editOf(scene, index);
    const auto found = edit ? edit->mapsReplaced.find(key) : decltype(edit->mapsReplaced.end()){};
    return edit && found != edit->mapsReplaced.end() ? found->second : "";
}

void setMapReplacement(const Document& document, Scene& scene, int index, const std::string& key,
                       const std::string& path) {
    if (mapReplacement(scene, index, key) == path) {
        return;
    }
    if (!editOf(scene, index)) {
        setModelMaterial(document, scene, index, modelMaterial(document, scene, index));
    }
    std::map<std::string, std::string>& replaced = editOf(scene, index)->mapsReplaced;
    if (path.empty()) {
        replaced.erase(key);
    } else {
        replaced[key] = path;
    }
}

bool hasVertexColours(const Document& document, int index) {
    const Model& model = *document.model;
    return std::any_of(model.draws.begin(), model.draws.end(), [&](const DrawItem& draw) {
        return draw.material == index && draw.primitive >= 0 && size_t(draw.primitive) < model.primitives.size() &&
               !model.primitives[size_t(draw.primitive)].colors.empty();
    });
}

std::string mapNames(const Document& document, int index) {
    std::string names;
    for (const auto& map : mapsOf(document.model->materials.at(size_t(index)))) {
        if (map.slot->present()) {
            names += (names.empty() ? "" : ", ") + std::string(map.name);
        }
    }
    return names;
}

}  // namespace patina::editor
