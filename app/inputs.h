#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "assets/asset_cache.h"
#include "scene/prepared_scene.h"
#include "scene/scene.h"

namespace patina::cli {

// How the commands that draw a picture of the scene (render, inspect, compare, sheet) look at
// it: --camera (one of the glTF model's own), --orbit and --target (model-viewer's camera-orbit
// and camera-target) and --tonemap.
struct ViewOptions {
    std::string camera;          // a camera of the model, by name or by its index in the file
    std::vector<float> orbit;    // THETA PHI RADIUS: degrees, degrees, scene units
    std::vector<float> target;   // X Y Z
    std::string tonemap;         // a tone map's name (scene/scene.h tonemapName)

    void addOptions(CLI::App& command);
    // The options on `scene`, whose mesh `prepared` holds (after --mesh framed it): the file's
    // camera; else the target moved, the eye keeping its offset from it, then the eye on the
    // orbit about the target; and the tone map. InputError for a camera the model lacks (or a
    // built-in mesh), an orthographic one, an orbit or target out of range or a tone map's name
    // unknown. A camera rolled about its view is shown level, said on stderr.
    void apply(Scene& scene, const PreparedScene& prepared) const;
};

// --scene and --material, shared by the commands that shade.
struct SceneInputs {
    std::string scenePath;
    std::string materialPath;
    std::string model;   // empty: the material's own
    std::string part;    // --part: with --material over a model, only the parts of this name
    std::string mesh;    // --mesh: sphere, torus or a glTF model instead of the scene's; empty: the scene's
    ViewOptions view;    // for the commands that register them (ViewOptions::addOptions)

    // --scene (withScene), --material, --model, and --mesh and --part for the commands that draw
    // a model (withPart).
    void addOptions(CLI::App& command, bool withScene = true, bool withPart = false);
    // The scene file (or the embedded default) with --material over its material and --model
    // over the material's model: the document, nothing it names loaded. Warnings go to stderr;
    // errors throw InputError.
    Scene load() const;
    // --mesh as the scene's mesh (a file relative to the working folder); InputError for a
    // name that is neither a built-in mesh nor a .gltf/.glb file.
    void replaceMesh(Scene& scene) const;
    // `scene` with --mesh as its mesh, and its mesh and environment loaded through `assets`
    // (assets/prepare_scene.h), for the commands that draw it. --mesh is shown as the editor
    // opens a model: the camera frames it and the positional lights follow its size
    // (fitSceneTo); without --mesh the scene's camera and lights stay as its file says. Then
    // `view` is applied. An environment made afresh is prefiltered by `prefilter` (the GPU's
    // pass where the command made its GL context first). Warnings go to stderr; errors throw
    // InputError.
    PreparedScene prepare(Scene& scene, AssetCache& assets, PrefilterFunction prefilter = prefilterCube) const;
    // --material over `model` (the scene's, null for a built-in mesh): its factors on every
    // part, or on --part's, as the scene's edits of them (setPartMaterials). InputError for a
    // --part the model lacks, or given without a model (without --material the command line
    // refuses it).
    void putMaterialOnParts(Scene& scene, const Model* model) const;
};

// What a command that draws works on, from its SceneInputs: the scene (load), the cache that
// loaded what it names, the scene prepared (prepare, the environment prefiltered by `prefilter`)
// and --material put on the model's parts (putMaterialOnParts). `prepared` refers to `scene`:
// made in place, never copied or moved.
struct LoadedScene {
    explicit LoadedScene(const SceneInputs& inputs, PrefilterFunction prefilter = prefilterCube);
    LoadedScene(const LoadedScene&) = delete;
    LoadedScene& operator=(const LoadedScene&) = delete;

    Scene scene;
    AssetCache assets;
    PreparedScene prepared;
};

// --mesh (SceneInputs::mesh) for a command that sets up its own options.
void addMeshOption(CLI::App& command, std::string& mesh);

// `material` on `model`'s parts as the scene's edits of them: every part, or the parts named
// `part` (setPartMaterials). `model` null (a built-in mesh): nothing, or InputError for a
// `part`; InputError for a `part` the model lacks, listing its parts.
void putMaterialOnParts(Scene& scene, const Model* model, const Material& material, const std::string& part);

// "warning: ..." on stderr, one a line.
void printWarnings(const std::vector<std::string>& warnings);

// Writes the bytes all-or-nothing; an unwritable path is an InputError (exit 3).
void writeOutput(const std::string& path, const std::vector<uint8_t>& bytes);
void writeOutputText(const std::string& path, const std::string& text);
std::string readInputText(const std::string& path);

}  // namespace patina::cli
