#include "inputs.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "shading/brdf_models.h"
#include "assets/prepare_scene.h"
#include "image/image.h"
#include "picture/png_text.h"
#include "io/file_kinds.h"
#include "files/input_error.h"
#include "io/scene_file.h"
#include "files/file_bytes.h"
#include "scene/camera_placement.h"
#include "scene/light_rig.h"

namespace patina::cli {

void printWarnings(const std::vector<std::string>& warnings) {
    for (const std::string& warning : warnings) {
        std::cerr << "warning: " << warning << "\n";
    }
}

void addMeshOption(CLI::App& command, std::string& mesh) {
    command.add_option("--mesh", mesh,
                       "sphere, torus, or a .gltf/.glb model instead of the scene's mesh, framed by the camera "
                       "with the lights fitted to its size (default: the scene's mesh, camera and lights)");
}

void SceneInputs::addOptions(CLI::App& command, bool withScene, bool withPart) {
    if (withScene) {
        command.add_option("--scene", scenePath, "Scene JSON, or a Patina screenshot (.png) (default: the embedded scene)");
    }
    CLI::Option* material = command.add_option("--material", materialPath, "Material JSON, replacing the scene's");
    if (withPart) {
        command
            .add_option("--part", part,
                        "With --material and a glTF model: the material on the parts of this name only "
                        "(default: every part)")
            ->needs(material);   // a usage mistake (exit 2), said before anything is read
    }
    if (withPart) {
        addMeshOption(command, mesh);
    }
    command.add_option("--model", model,
                       "BRDF model, replacing the material's and every model part's: " + brdfModelNames());
}

Scene SceneInputs::load() const {
    std::vector<std::string> warnings;
    // The embedded scene, a scene file, or the scene a Patina screenshot (.png) holds.
    Scene scene = scenePath.empty()                       ? defaultScene()
                  : lowerExtension(scenePath) == ".png" ? screenshotScene(scenePath, warnings)
                                                          : loadSceneFile(scenePath, warnings);
    if (!materialPath.empty()) {
        scene.material = loadMaterialFile(materialPath, warnings);
    }
    if (!model.empty()) {
        const auto id = brdfModelFromName(model);
        if (!id) {
            throw InputError("--model: unknown BRDF model \"" + model + "\" (known: " + brdfModelNames() + ")");
        }
        scene.material.model = *id;
        scene.modelBrdf = *id;   // a glTF model's parts too (each has its own otherwise)
    }
    printWarnings(warnings);
    return scene;
}

void SceneInputs::replaceMesh(Scene& scene) const {
    if (mesh.empty()) {
        return;
    }
    if (const auto kind = meshKindFromName(mesh)) {
        scene.mesh = *kind;
        scene.meshFile.clear();
    } else if (!gltfExtension(mesh).empty()) {
        scene.meshFile = std::filesystem::absolute(mesh).lexically_normal().string();
    } else {
        throw InputError("--mesh: \"" + mesh + "\" is neither sphere, torus nor a .gltf/.glb file");
    }
}

PreparedScene SceneInputs::prepare(Scene& scene, AssetCache& assets, PrefilterFunction prefilter) const {
    std::vector<std::string> warnings;
    if (mesh.empty()) {
        PreparedScene prepared = prepareScene(scene, assets, warnings, prefilter);
        printWarnings(warnings);
        view.apply(scene, prepared);
        return prepared;
    }
    // The rig was made for the scene's own shape: measured before it is replaced. A model the
    // scene names that cannot be read is being replaced anyway: its lights are taken as made
    // for the unit sphere, and the warning says so.
    std::shared_ptr<const Mesh> own;
    if (!scene.meshFile.empty()) {
        try {
            own = assets.mesh(scene);
        } catch (const InputError& error) {
            warnings.push_back(std::string(error.what()) + "; --mesh replaces it, and the scene's lights are fitted "
                                                           "as if made for the unit sphere");
        }
    }
    const BoundingSphere before = shapeBounds(scene, own.get());
    replaceMesh(scene);
    PreparedScene prepared = prepareScene(scene, assets, warnings, prefilter);
    printWarnings(warnings);
    fitSceneTo(scene, before, shapeBounds(scene, prepared.mesh.get()));   // `prepared` reads `scene`
    view.apply(scene, prepared);
    return prepared;
}

void ViewOptions::addOptions(CLI::App& command) {
    CLI::Option* camera =
        command.add_option("--camera", this->camera,
                           "One of the glTF model's own cameras, by name or by its index in the file's cameras "
                           "(perspective ones, shown with +Y up)");
    CLI::Option* orbit = command.add_option("--orbit", this->orbit,
                                            "THETA PHI RADIUS: the eye at target + RADIUS (sin PHI sin THETA, cos PHI, "
                                            "sin PHI cos THETA), as model-viewer's camera-orbit (degrees, scene units)");
    orbit->expected(3);
    CLI::Option* target = command.add_option(
        "--target", this->target, "X Y Z: the point the camera looks at and orbits, as model-viewer's camera-target "
                                  "(the eye keeps its offset from it unless --orbit says another)");
    target->expected(3);
    camera->excludes(orbit)->excludes(target);
    command.add_option("--tonemap", tonemap, "The view transform after exposure: " + tonemapNames() +
                                                 " (default: the scene's)");
}

namespace {
std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(value));
    return text;
}

// Each number finite, or InputError naming the option.
void requireFinite(const std::vector<float>& numbers, const char* option) {
    for (const float value : numbers) {
        if (!std::isfinite(value)) {
            throw InputError(std::string(option) + ": " + number(value) + " is not a finite number");
        }
    }
}

// --camera: the model's camera on `scene`, or InputError.
void useModelCamera(Scene& scene, const PreparedScene& prepared, const std::string& name) {
    if (!prepared.model) {
        throw InputError("--camera names a camera of a glTF model, and the scene's mesh is the built-in " +
                         std::string(meshKindName(scene.mesh)));
    }
    try {
        const ModelCamera& camera = findModelCamera(prepared.model->cameras, name);
        const float roll = placeModelCamera(scene.camera, camera, shapeBounds(scene, prepared.mesh.get()));
        if (std::abs(roll) > 0.5f) {
            char line[200];
            std::snprintf(line, sizeof line, " is rolled %.1f degrees about its view: Patina's camera keeps +Y up "
                                             "and shows it level", roll);
            printWarnings({"--camera \"" + camera.name + "\"" + line});
        }
    } catch (const std::invalid_argument& error) {
        throw InputError("--camera " + name + ": " + error.what());
    }
}
}  // namespace

void ViewOptions::apply(Scene& scene, const PreparedScene& prepared) const {
    if (!tonemap.empty()) {
        const auto parsed = tonemapFromName(tonemap);
        if (!parsed) {
            throw InputError("--tonemap: unknown tone map \"" + tonemap + "\" (known: " + tonemapNames() + ")");
        }
        scene.display.tonemap = *parsed;
    }
    if (!camera.empty()) {
        useModelCamera(scene, prepared, camera);
    }
    requireFinite(target, "--target");
    requireFinite(orbit, "--orbit");
    if (!target.empty()) {
        const glm::vec3 to(target[0], target[1], target[2]);
        scene.camera.position += to - scene.camera.target;
        scene.camera.target = to;
    }
    if (!orbit.empty()) {
        if (orbit[1] < 0.0f || orbit[1] > 180.0f) {
            throw InputError("--orbit: PHI (from +Y down) must be between 0 and 180 degrees, not " +
                             number(orbit[1]));
        }
        if (!(orbit[2] > 0.0f)) {
            throw InputError("--orbit: RADIUS must be above 0, not " + number(orbit[2]));
        }
        placeOnOrbit(scene.camera, scene.camera.target, {orbit[0], orbit[1], orbit[2]});
    }
}

void putMaterialOnParts(Scene& scene, const Model* model, const Material& material, const std::string& part) {
    if (!model) {
        if (!part.empty()) {
            throw InputError("--part names a part of a glTF model, and the scene's mesh is a built-in one");
        }
        return;
    }
    try {
        setPartMaterials(scene, *model, material, part);
    } catch (const std::invalid_argument& error) {
        throw InputError("--part: " + std::string(error.what()));
    }
}

void SceneInputs::putMaterialOnParts(Scene& scene, const Model* model) const {
    if (materialPath.empty()) {
        return;   // --part without --material is refused as a usage mistake (addOptions)
    }
    const Material material = scene.material;   // setPartMaterials adds to `scene`
    cli::putMaterialOnParts(scene, model, material, part);
}

LoadedScene::LoadedScene(const SceneInputs& inputs, PrefilterFunction prefilter)
    : scene(inputs.load()), prepared(inputs.prepare(scene, assets, prefilter)) {
    inputs.putMaterialOnParts(scene, prepared.model.get());   // `prepared` reads `scene`
}

void writeOutput(const std::string& path, const std::vector<uint8_t>& bytes) {
    try {
        writeFileAtomic(path, bytes);
    } catch (const std::runtime_error& error) {
        throw InputError(error.what());
    }
}

void writeOutputText(const std::string& path, const std::string& text) {
    writeOutput(path, std::vector<uint8_t>(text.begin(), text.end()));
}

std::string readInputText(const std::string& path) {
    try {
        const std::vector<uint8_t> bytes = readFileBytes(path);
        return std::string(bytes.begin(), bytes.end());
    } catch (const std::runtime_error& error) {
        throw InputError(error.what());
    }
}

}  // namespace patina::cli
