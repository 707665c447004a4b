// RenderInputs: what a render reads. Names, notes and a file's unknown keys change nothing
// drawn, so they leave the inputs equal; everything the shaders or the rasteriser read does not.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/render_inputs.h"

namespace patina {
namespace {

// `scene` as prepared with its built-in mesh, or `mesh`, and `environment`.
RenderInputs inputsOf(const Scene& scene, std::shared_ptr<const Mesh> mesh = nullptr,
                      std::shared_ptr<const Environment> environment = nullptr) {
    return renderInputs({scene, mesh ? mesh : builtinMesh(scene.mesh), std::move(environment)});
}

TEST(RenderInputs, NamesAndUnknownKeysDrawNothing) {
    const Scene scene = defaultScene();
    Scene renamed = scene;
    renamed.material.name = "another";
    renamed.material.notes = "from a file";
    renamed.material.extras["vendor"] = Json::array({1, 2, 3});
    renamed.lights[0].name = "key light";
    renamed.lights[1].extras["colourTemperature"] = 6500;
    renamed.camera.extras["lens"] = "50mm";
    renamed.display.extras["grain"] = true;
    renamed.extras["author"] = "someone";
    EXPECT_EQ(inputsOf(renamed), inputsOf(scene));
}

TEST(RenderInputs, EverythingDrawnChangesThem) {
    const Scene scene = defaultScene();
    const std::vector<std::pair<std::string, std::function<void(Scene&)>>> changes = {
        {"roughness", [](Scene& s) { s.material.roughness += 0.01f; }},
        {"model", [](Scene& s) { s.material.model = BrdfModelId::Burley; }},
        {"base colour", [](Scene& s) { s.material.baseColor.g = 0.5f; }},
        {"light intensity", [](Scene& s) { s.lights[0].intensity *= 2.0f; }},
        {"light disabled", [](Scene& s) { s.lights[1].enabled = false; }},
        {"light range", [](Scene& s) { s.lights[0].range = 3.0f; }},
        {"light added", [](Scene& s) { s.lights.push_back(s.lights[0]); }},
        {"camera", [](Scene& s) { s.camera.position.x += 0.1f; }},
        {"field of view", [](Scene& s) { s.camera.fovYDegrees = 30.0f; }},
        {"exposure", [](Scene& s) { s.display.exposure = 1.0f; }},
        {"tone map", [](Scene& s) { s.display.tonemap = Tonemap::AcesNarkowicz; }},
        {"background", [](Scene& s) { s.display.background = glm::vec3(1.0f); }},
        {"built-in mesh", [](Scene& s) { s.mesh = MeshKind::Torus; }},
        {"environment source", [](Scene& s) { s.lights[2].source = "builtin:white"; }},
        {"light shadows", [](Scene& s) { s.lights[1].shadows = true; }},
        {"ground", [](Scene& s) { s.display.ground = Ground::Floor; }},
        {"ground colour", [](Scene& s) { s.display.groundColor = glm::vec3(0.1f); }},
        {"ground roughness", [](Scene& s) { s.display.groundRoughness = 0.3f; }},
    };
    const RenderInputs original = inputsOf(scene);
    for (const auto& [what, change] : changes) {
        Scene changed = scene;
        change(changed);
        EXPECT_FALSE(inputsOf(changed) == original) << what;
    }
    // What was loaded for it: another mesh, another environment.
    EXPECT_FALSE(inputsOf(scene, std::make_shared<const Mesh>(makeUvSphere(8, 16))) == original);
    EXPECT_FALSE(inputsOf(scene, nullptr, std::make_shared<const Environment>()) == original);
    // The ambient occlusion baked for it (display.ambientOcclusion on: prepareScene's).
    EXPECT_FALSE(renderInputs({scene, builtinMesh(scene.mesh), nullptr, nullptr,
                               std::make_shared<const AmbientOcclusion>()}) == original);
    // A disabled light draws nothing, whatever its values.
    Scene off = scene;
    off.lights[1].enabled = false;
    Scene offAndChanged = off;
    offAndChanged.lights[1].intensity = 99.0f;
    EXPECT_EQ(inputsOf(offAndChanged), inputsOf(off));
    // A disabled environment light draws nothing, whatever was loaded for it.
    Scene dark = scene;
    dark.lights[2].enabled = false;
    EXPECT_EQ(inputsOf(dark, nullptr, std::make_shared<const Environment>()), inputsOf(dark));
}

// A model's parts as the scene tunes them: an undo of a part's factors or of a map left out
// changes nothing else, and must still draw again (the editor's viewport compares these).
TEST(RenderInputs, APartsTuningChangesThemOnAModel) {
    Scene scene = defaultScene();
    scene.meshFile = "/models/two.glb";
    const auto model = std::make_shared<const Model>();
    const auto mesh = builtinMesh(MeshKind::Sphere);
    auto inputs = [&](const Scene& s) { return renderInputs({s, mesh, nullptr, model}); };
    const RenderInputs untuned = inputs(scene);
    Scene tuned = scene;
    tuned.modelMaterials.push_back({0, scene.material});
    EXPECT_FALSE(inputs(tuned) == untuned) << "a part's factors";
    Scene mapOff = tuned;
    mapOff.modelMaterials[0].mapsOff = {"baseColorTexture"};
    EXPECT_FALSE(inputs(mapOff) == inputs(tuned)) << "a map left out";
    // Without a model nothing of it is drawn.
    EXPECT_EQ(inputsOf(mapOff), inputsOf(scene));
}

}  // namespace
}  // namespace patina
