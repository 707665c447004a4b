#pragma once
// What the renderer and the ground truth draw: the document with what was loaded for it.
#include <memory>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "environment/environment.h"
#include "geometry/mesh.h"
#include "model/model.h"
#include "scene/ambient_occlusion.h"
#include "scene/scene.h"
#include "shading/material_parameters.h"

namespace patina {

// A scene document and the things it names, made ready (assets/prepare_scene.h). Whoever
// draws it loads nothing: a mesh or an environment missing here is the caller's mistake.
// It refers to the document, which must outlive it; the loaded things are shared.
struct PreparedScene {
    const Scene& scene;
    // The built-in kind's mesh, or the model's draws flattened into one world-space mesh: what
    // the camera frames and a caller showing one material over the whole shape (the editor, a
    // sheet) draws. Never null.
    std::shared_ptr<const Mesh> mesh;
    // The enabled environment light's source made ready (kept while the light is off, so
    // turning it on again loads nothing); null when the scene has none.
    std::shared_ptr<const Environment> environment;
    // The scene's glTF file as drawn: primitives, materials and draw items. Null: `mesh` is
    // drawn alone, with the document's material.
    std::shared_ptr<const Model> model = nullptr;
    // The shape's ambient occlusion (DisplaySettings::ambientOcclusion), baked for this mesh or
    // model and the display's ground; null where the display has it off.
    std::shared_ptr<const AmbientOcclusion> occlusion = nullptr;
};

// One primitive drawn once, as both the renderer and the ground truth draw it.
struct SceneDraw {
    const Mesh* mesh = nullptr;          // in its own space; the prepared scene holds it
    int primitive = 0;                   // its index in the model (0: the one mesh)
    int item = -1;                       // its DrawItem in the model's draws; -1 for the one mesh
    glm::mat4 transform{1.0f};           // its space into the world
    glm::mat3 normalTransform{1.0f};     // model/placement.h
    MaterialParameters material;         // shaded by the document's BRDF model
    // Both sides drawn; false culls back faces (glTF 2.0 §3.9.5).
    bool doubleSided = true;
    // glTF's double-sided lighting: a back face's normal is reversed before shading (§3.9.5).
    // The built-in meshes have always been shaded with the normals they have.
    bool reverseBackNormals = false;
    // glTF's BLEND (§3.9.4): "over" what is behind it by `alpha`, after every opaque draw.
    bool blend = false;
    float alpha = 1.0f;
    // The item's material with its texture maps (model/model.h), when hasMaps or when its mesh
    // has vertex colours: its factors are `material`'s, each map and the colours multiply in per
    // pixel (glTF 2.0 §3.9.2-3.9.3), emission added. Null: the factors alone. Points into the
    // prepared scene's model (or at the one default material, for a draw that names none).
    const ModelMaterial* maps = nullptr;
    std::shared_ptr<const ModelMaterial> tunedMaps;   // holds `maps` where the scene left some out
    // glTF's MASK (§3.9.4): a pixel whose alpha (the factor times the base colour map's) is
    // below this is not drawn; negative for OPAQUE and BLEND.
    float alphaCutoff = -1.0f;
    // The item's ambient occlusion, a value per vertex of `mesh` (scene/ambient_occlusion.h);
    // null without. Points into the prepared scene's occlusion.
    const std::vector<float>* occlusion = nullptr;
};

// Whether `material` needs its maps shaded: it has a texture map, or emits (emission is added
// only where maps are read).
bool hasMaps(const ModelMaterial& material);

// Which maps `material` has, a bit each in mapsOf's order (bit 0 base colour, ..., bit 4
// emissive): what a program specialised to the item compiles (PATINA_MAP_SET).
int mapSetOf(const ModelMaterial& material);

// glTF's default material (§3.9.6) in Patina's parameters: white, metallic 1, roughness 1, and
// specular 0.5 (F0 0.04, a glTF dielectric's), shaded as glTF's (`gltf`).
MaterialParameters defaultModelMaterial();

// What `prepared` draws, in order: without a model its mesh with the document's material, as
// it has always been drawn; with one each draw item with its own material (the default one for
// none; its factors the scene's edit of it, Scene::modelMaterials, where there is one), each
// under its own BRDF model (the file's `gltf`, an edit's own) unless Scene::modelBrdf names
// one for all. A MASK item whose alpha
// is below its cutoff is left out: a texture's alpha, at most 1, could only lower it. Throws
// std::invalid_argument for a scene without its mesh, or an item naming a primitive or
// material the model lacks.
std::vector<SceneDraw> sceneDraws(const PreparedScene& prepared);

// The scene's edit of material `index` of a model (`material`, the file's), where one has its
// index and name (Scene::modelMaterials); null otherwise.
const ModelMaterialEdit* editOf(const Scene& scene, int index, const ModelMaterial& material);
// A line for each of `scene`'s modelMaterials entries that tunes no material of `model` (an
// index it does not have, or a name that is not the one there: the file changed since the scene
// was saved), which editOf therefore never returns: the entry is kept and saved, not drawn.
std::vector<std::string> unmatchedEdits(const Scene& scene, const Model& model);

// Material `index` of a model (`material`, the file's) as the scene tunes it: the factors of
// the scene's edit of it (matched by index and name), without the maps the edit leaves out.
ModelMaterial tunedMaterial(const Scene& scene, int index, const ModelMaterial& material);

// `model` as the scene tunes it: each material with an edit in Scene::modelMaterials (matched
// by index and name, as sceneDraws matches them) takes the edit's factors and loses the maps
// it leaves out; its other maps, alpha, emission and the rest stay the file's. What an export
// of the scene's model writes.
Model tunedModel(const Model& model, const Scene& scene);

// `material`'s factors (not its name) on the parts of `model` whose material is named `part`,
// or on every part when `part` is empty, as the scene's edits of them (Scene::modelMaterials;
// each part keeps its name, maps and BRDF model, and an edit's maps left out or replaced: a
// material's model is for the built-in meshes): what a material named on the command line or a
// preset does to a model. Throws std::invalid_argument listing the parts when none is named `part`.
void setPartMaterials(Scene& scene, const Model& model, const Material& material, const std::string& part = {});

}  // namespace patina
