#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "environment/environment.h"
#include "geometry/mesh.h"
#include "scene/prepared_scene.h"
#include "scene/scene.h"
#include "state/undo_history.h"

namespace patina {
class AssetCache;
}

namespace patina::editor {

struct Interaction;
struct Prompts;

// The document: the scene being edited, the files it was opened from or saved to, what is in
// them, and the history of its edits. Everything Save writes and Undo restores is here.
struct Document {
    Scene scene = defaultScene();
    // What the scene names, loaded (assets/, through Jobs::assets): its glTF file's model as
    // loaded, with its flattened mesh (null: a built-in mesh); what is drawn, that model with
    // the images the scene puts in place of its maps (AssetCache::retextured; the file's model
    // itself without any; null: a built-in mesh); and its environment light's environment
    // (kept while the light is off, for the checkbox).
    std::shared_ptr<const LoadedModel> fileModel;
    std::shared_ptr<const Model> model;
    std::shared_ptr<const Environment> environment;
    // The shape's ambient occlusion while the display has it on (resolveAmbientOcclusion, baked
    // once per shape and ground through Jobs::assets); null while off.
    std::shared_ptr<const AmbientOcclusion> occlusion;
    std::filesystem::path materialPath;      // where Save writes the material; empty: never saved
    Material savedMaterial = scene.material; // what is on disk at materialPath
    // The scene as a document: where it was opened from or saved to (empty: none), and the
    // scene as it was then (or at start), against which lights, camera, display and mesh are
    // unsaved changes.
    std::filesystem::path scenePath;
    Scene savedScene = scene;
    UndoHistory history;
    EditSnapshot committed = snapshot();     // the state history knows; edits since are pending

    // What differs from the files: the material from its own (or the scene's), the rest of the
    // scene from the scene as opened, saved or started with.
    bool materialChanged() const { return scene.material != savedMaterial; }
    bool sceneChanged() const;
    bool dirty() const { return materialChanged() || sceneChanged(); }
    // The glTF file's flattened mesh; null: the built-in kind's.
    std::shared_ptr<const Mesh> mesh() const {
        return fileModel ? std::shared_ptr<const Mesh>(fileModel, &fileModel->mesh) : nullptr;
    }
    ShownShape shownShape() const { return {scene.mesh, scene.meshFile, fileModel, model, scene.camera}; }
    EditSnapshot snapshot() const {
        return {scene.material,       scene.lights,    scene.display,
                scene.modelMaterials, scene.modelBrdf, shownShape(), scene.bookmarks};
    }
    // Whether `index` is one of the scene's lights.
    bool hasLight(int index) const { return index >= 0 && index < int(scene.lights.size()); }
    // The scene's environment light's index, or -1.
    int environmentIndex() const;
};

// The window title: the document's file name (the scene's, else the model's shown, else the
// material's, else the material's name), a '*' while anything is unsaved.
std::string windowTitle(const Document& document);
// "the material", "the lights and the camera", ...: what is unsaved, for the prompt.
std::string unsavedParts(const Document& document);

// The prompt's Discard: the material, the stage (lights, camera and its bookmarks, display)
// and, on the same shape, the model's parts (retextured through `assets` as saved) back as last
// saved, so that what the next document keeps of this one (a material or model opened keeps the
// stage) is not the edits just discarded; the history goes with them (Ctrl+Z brought them back).
// The mesh stays: the file opened next replaces or keeps it with what is loaded for it.
void discardChanges(Document& document, AssetCache& assets);

// --- Undoable edits ---------------------------------------------------------------------
// Widgets write straight into the document's scene. Whatever changed since the last commit
// becomes one undo step when commitEdits runs, which the editor does once no widget is active:
// a slider drag over many frames is one step, whatever widget made it. Whether it made one.
bool commitEdits(Document& document);
// A discrete edit (a button): its own step, apart from anything pending.
template <typename Apply>
void applyEdit(Document& document, Apply&& apply) {
    commitEdits(document);
    apply(document);
    commitEdits(document);
}
// The status says what a step undid or redid; the selection and solo stay on lights that exist.
void undo(Document& document, Interaction& interaction, Prompts& prompts);
void redo(Document& document, Interaction& interaction, Prompts& prompts);

// The sphere the camera frames and the light rig is fitted to: the mesh file's bounds, or the
// built-in mesh's (about the origin, radius 1).
BoundingSphere meshBounds(const Document& document);
// What the lights panel shows a light's intensity divided by: for a point, sphere or tube light
// while a model is shown, the square of the model's radius, the factor opening it multiplied
// the intensity by (moveLightRig), so the panel reads as it did on the unit sphere (2Cylinder-
// Engine's key light read 784563.938); 1 otherwise. The scene file keeps the intensity itself.
float intensityScale(const Document& document, const Light& light);
// Aims the camera at the whole mesh (F, View > Frame mesh).
void frameMesh(Document& document);
// The built-in sphere or torus; coming back from a model, the camera frames it and the lights
// return to the unit scale (an undoable step).
void chooseBuiltinMesh(Document& document, MeshKind kind);
// `shown` (renderedScene, withMaterial) with the document's loaded mesh, model and environment:
// what the renderer draws (prepareScene's result, made from what the document holds, loading
// nothing). Refers to `shown`, which must outlive it.
PreparedScene sceneToDraw(const Document& document, const Scene& shown);

// --- A model's materials ----------------------------------------------------------------
// How many materials the shown model has (0 for a built-in mesh).
int modelMaterialCount(const Document& document);
// Material `index` of the model as `scene` draws it: its edit (Scene::modelMaterials) or the
// file's factors, under the file's name, with its BRDF model (the part's own: the file's are
// `gltf`; Scene::modelBrdf where the scene shades every part with one).
Material modelMaterial(const Document& document, const Scene& scene, int index);
// Writes `material`'s values as the edit of material `index` in `scene` (its name stays the
// file's: the key), made or replaced; under Scene::modelBrdf the part keeps its own model.
void setModelMaterial(const Document& document, Scene& scene, int index, Material material);
// "base colour, normal": the maps material `index` of the model uses; empty for none.
// Whether `scene` draws map `key` (model/model.h mapsOf) of the model's material `index`: false
// where the scene's edit of it leaves the map out.
bool mapShown(const Scene& scene, int index, const std::string& key);
// Draws or leaves out that map: an edit of the material (made with its values as they are
// where the scene has none).
void setMapShown(const Document& document, Scene& scene, int index, const std::string& key, bool shown);
std::string mapNames(const Document& document, int index);
// Whether a primitive drawn with material `index` has vertex colours (COLOR_0), which multiply
// its base colour as a map does.
bool hasVertexColours(const Document& document, int index);
// The names of the nodes the shown model draws with its material `index`, each once, in the
// file's order: what tells apart materials of one name.
std::vector<std::string> partNodes(const Document& document, int index);
// Whether material `index`'s name or one of its nodes' has `filter` in it, in any case (the
// Parts list's search box); everything matches an empty filter.
bool partMatches(const Document& document, int index, const std::string& filter);
// The image the scene puts in place of map `key` of the model's material `index`, or "".
std::string mapReplacement(const Scene& scene, int index, const std::string& key);
// Puts the image at `path` there (empty: the file's map again), an edit of the material as
// setMapShown makes one; the model drawn is retextured apart (document_files.h replaceMap).
void setMapReplacement(const Document& document, Scene& scene, int index, const std::string& key,
                       const std::string& path);

}  // namespace patina::editor
