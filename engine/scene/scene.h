#pragma once
#include <map>
#include <string>
#include <string_view>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "scene/light.h"
#include "scene/material.h"

namespace patina {

struct Camera {
    glm::vec3 position{0.0f, 0.6f, 3.4f};
    glm::vec3 target{0.0f};
    float fovYDegrees = 45.0f;
    Json extras = Json::object();   // unknown keys of the file, as Material::extras

    bool operator==(const Camera&) const = default;
};

// A camera saved under a name, to come back to (the editor's Bookmarks; the scene file's
// "bookmarks"). Names are not empty and differ within a scene.
struct CameraBookmark {
    std::string name;
    Camera camera;
    Json extras = Json::object();   // unknown keys of the file, as Material::extras

    bool operator==(const CameraBookmark&) const = default;
};

// The view transforms (shaders/shared/display.glsl has each one's source). The ACES fits are
// two: Narkowicz's (named "aces" before Hill's joined it, a name still read as his) and Hill's
// as three.js and the Khronos viewer apply it.
enum class Tonemap { None, AcesNarkowicz, Reinhard, PbrNeutral, AcesHill, Agx };
// Every tone map, in the order the editor offers them.
inline constexpr Tonemap kTonemaps[] = {Tonemap::None,       Tonemap::PbrNeutral,    Tonemap::AcesHill,
                                        Tonemap::Agx,        Tonemap::AcesNarkowicz, Tonemap::Reinhard};
// "none", "pbr-neutral", "aces-hill", "agx", "aces-narkowicz", "reinhard": the name in files,
// on the command line and in the editor.
std::string_view tonemapName(Tonemap tonemap);
// The tone map of `name`, or of "aces" (older files' name for "aces-narkowicz"); nothing for
// any other name.
std::optional<Tonemap> tonemapFromName(std::string_view name);
// "none, pbr-neutral, ...": the names, for messages and help.
std::string tonemapNames();
// The shaders' TONEMAP_* value (shaders/shared/display.glsl) of a tone map.
int tonemapShaderIndex(Tonemap tonemap);

// What lies under the model (DisplaySettings::ground): nothing; a shadow catcher (the
// background darkened by the light the ground loses to shadows); or a floor drawn with its own
// material. "none", "shadow", "floor" in files and the editor.
enum class Ground { None, Shadow, Floor };
inline constexpr Ground kGrounds[] = {Ground::None, Ground::Shadow, Ground::Floor};
std::string_view groundName(Ground ground);
std::optional<Ground> groundFromName(std::string_view name);
std::string groundNames();   // "none, shadow, floor"

struct DisplaySettings {
    float exposure = 0.0f;                         // stops
    Tonemap tonemap = Tonemap::None;
    glm::vec3 background{0.02f, 0.02f, 0.025f};    // linear
    // Show the scene's environment behind the mesh instead of `background` (which stays the
    // colour where the scene has none), read from the prefiltered chain at this roughness.
    bool backgroundFromEnvironment = false;
    float backgroundBlur = 0.0f;
    // A plane under the model at its lowest point (scene/ground.h), and the floor's material:
    // a dielectric of this base colour (linear) and roughness.
    Ground ground = Ground::None;
    glm::vec3 groundColor{0.5f};
    float groundRoughness = 0.8f;
    // The environment's and the hemisphere lights' light occluded by the model itself and the
    // ground, as baked once per model (scene/ambient_occlusion.h), with the specular occlusion
    // that keeps cavities from glowing with reflections. Off: nothing baked, nothing compiled.
    bool ambientOcclusion = false;
    Json extras = Json::object();

    bool operator==(const DisplaySettings&) const = default;
};


// A material of the scene's model as the user tuned it: the factors it is drawn with instead of
// the file's (its maps still multiply in, as glTF defines). Keyed by the material's index in
// the file and its name (material.name), so that an edit never lands on another material
// when the file changes: a key the file no longer has is ignored.
struct ModelMaterialEdit {
    int index = 0;
    Material material;
    Json extras = Json::object();   // unknown keys of the file, as Material::extras
    // The maps left out (glTF's keys: "baseColorTexture", "normalTexture", ...; model/model.h
    // mapsOf): the factor alone is drawn where each was.
    std::vector<std::string> mapsOff = {};
    // Images put in place of the file's maps, by key: an absolute path each (a scene file's
    // relative one is resolved against its folder when read). The map keeps its UV set,
    // sampler and transform; a map left out above stays out. assets/ loads them.
    std::map<std::string, std::string> mapsReplaced = {};
    Json mapsReplacedExtras = Json::object();   // keys there that name no map, kept as extras are
    bool operator==(const ModelMaterialEdit&) const = default;
};

// The document: what a scene file says, values only, no graph. What it names (a glTF file, an
// environment image) is loaded apart from it, by assets/, into a PreparedScene.
struct Scene {
    MeshKind mesh = MeshKind::Sphere;
    // A .gltf or .glb file shown instead of `mesh` when not empty; an absolute path (a scene
    // file's relative path is resolved against the scene file's folder when it is read).
    std::string meshFile;
    Material material;   // the built-in meshes'
    std::vector<ModelMaterialEdit> modelMaterials;   // the model's materials as tuned, by index
    // The BRDF model every part of the model is shaded with, in place of each part's own (the
    // file's materials are glTF's, `gltf`; an edit names its own): set by `render --model`, and
    // by a scene written before version 3, which shaded the whole model with `material`'s model.
    std::optional<BrdfModelId> modelBrdf;
    Camera camera;
    std::vector<CameraBookmark> bookmarks;   // in the order they were saved
    std::vector<Light> lights;
    DisplaySettings display;
    Json extras = Json::object();   // top-level unknown keys; the parts keep their own

    bool operator==(const Scene&) const = default;
};

// The first enabled environment light (a scene file holds one at most), or null.
const Light* enabledEnvironment(const std::vector<Light>& lights);
inline const Light* enabledEnvironment(const Scene& scene) { return enabledEnvironment(scene.lights); }

// The embedded default: a sphere lit by a warm point light, a cool directional light, the
// built-in studio environment and a faint sky/ground hemisphere light, under PBR Neutral. The
// editor starts with it (and File > New makes it), `patina render` renders it, and
// examples/default_scene.json is it as a file.
Scene defaultScene();

}  // namespace patina
