// The assets layer: what a scene names, loaded once through a cache its caller owns, and the
// prepared scene the renderer draws without loading anything itself.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "assets/asset_cache.h"
#include "assets/prepare_scene.h"
#include "gltf/export.h"
#include "gltf/model_export.h"
#include "gltf/model_import.h"
#include "files/input_error.h"
#include "gltf_builder.h"
#include "scratch_test.h"
#include "test_support.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

// A folder of its own for the environments' disk cache, so nothing is read from a user's.
class Assets : public test::ScratchTest {
protected:
    void SetUp() override {
        ScratchTest::SetUp();
        if (const char* kept = std::getenv("PATINA_CACHE_DIR")) {
            kept_ = kept;
        }
        setenv("PATINA_CACHE_DIR", path("cache").c_str(), 1);
    }
    void TearDown() override {
        if (kept_) {
            setenv("PATINA_CACHE_DIR", kept_->c_str(), 1);
        } else {
            unsetenv("PATINA_CACHE_DIR");
        }
        ScratchTest::TearDown();
    }

    // A scene showing `mesh` (a glTF file, or none for the sphere) under `environment` alone.
    static Scene sceneOf(const std::string& mesh, const std::string& environment) {
        Scene scene;
        scene.meshFile = mesh;
        Light light;
        light.type = LightType::Environment;
        light.source = environment;
        scene.lights = {light};
        return scene;
    }

    std::optional<std::string> kept_;
};

// The InputError's message, or "" when `load` throws none.
template <typename Load>
std::string inputErrorOf(Load&& load) {
    try {
        load();
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST_F(Assets, TheSameFileIsLoadedOnce) {
    AssetCache cache;
    std::vector<std::string> warnings;
    test::writeFlatHdr(path("sky.hdr"), 32, 16, 100);
    const auto sky = cache.environment(path("sky.hdr").string(), warnings);
    ASSERT_TRUE(sky);
    EXPECT_EQ(sky->source, path("sky.hdr").string());
    EXPECT_EQ(cache.environment(path("sky.hdr").string(), warnings), sky);

    exportGltf(path("torus.glb"), makeTorus(), Material{});
    const auto model = cache.model(path("torus.glb"));
    EXPECT_EQ(cache.model(path("torus.glb")), model);
    const Scene scene = sceneOf(path("torus.glb").string(), "builtin:white");
    EXPECT_EQ(cache.mesh(scene).get(), &model->mesh);
    EXPECT_EQ(cache.mesh(scene)->positions.size(), makeTorus().positions.size());
}

// A model's images decoded report their share done, and a stop leaves nothing loaded or kept:
// what the editor's Cancel does to a model with large maps.
TEST_F(Assets, AModelsImageDecodingReportsProgressAndStopsWhenAsked) {
    Model model = test::twoBalls();
    for (int i = 0; i < 4; ++i) {
        model.images.push_back({"map " + std::to_string(i), 8, 8, std::vector<uint8_t>(8 * 8 * 4, uint8_t(40 * i + 30))});
    }
    model.materials[0].baseColor.image = 0;
    model.materials[0].metallicRoughness.image = 1;
    model.materials[1].baseColor.image = 2;
    model.materials[1].occlusion.image = 3;
    exportGltfModel(path("maps.glb"), model);

    std::vector<float> told;
    const std::optional<Model> read = importGltfModel(path("maps.glb"), [&](float fraction) {
        told.push_back(fraction);
        return true;
    });
    ASSERT_TRUE(read);
    EXPECT_EQ(read->images.size(), 4u);
    EXPECT_EQ(told, (std::vector<float>{0.0f, 0.25f, 0.5f, 0.75f, 1.0f}));   // one at a time, in order

    int asked = 0;
    EXPECT_FALSE(importGltfModel(path("maps.glb"), [&](float fraction) { return ++asked < 2 || fraction < 0.0f; }));
    EXPECT_EQ(asked, 2) << "it stops at the first image done after the stop";

    AssetCache assets;
    EXPECT_EQ(assets.model(path("maps.glb"), [](float) { return false; }), nullptr);
    const std::shared_ptr<const GltfImport> whole = assets.model(path("maps.glb"));   // nothing stale was kept
    ASSERT_NE(whole, nullptr);
    EXPECT_EQ(assets.drawnModel(path("maps.glb"))->images.size(), 4u);
}

TEST_F(Assets, AChangedFileIsLoadedAgain) {
    AssetCache cache;
    std::vector<std::string> warnings;
    test::writeFlatHdr(path("sky.hdr"), 32, 16, 100);
    const auto before = cache.environment(path("sky.hdr").string(), warnings);
    test::writeFlatHdr(path("sky.hdr"), 32, 16, 200);   // same size, other contents
    const auto after = cache.environment(path("sky.hdr").string(), warnings);
    EXPECT_NE(after, before);
    EXPECT_GT(after->image.rgb[0], before->image.rgb[0]);

    exportGltf(path("model.glb"), makeTorus(), Material{});
    const auto torus = cache.model(path("model.glb"));
    exportGltf(path("model.glb"), makeUvSphere(), Material{});
    const auto sphere = cache.model(path("model.glb"));
    EXPECT_NE(sphere, torus);
    EXPECT_EQ(sphere->mesh.positions.size(), makeUvSphere().positions.size());
}

TEST_F(Assets, BuiltInsAreKeptForTheCachesLifeAndNoOtherCacheShares) {
    AssetCache cache;
    std::vector<std::string> warnings;
    // Not held by anyone between the calls, and the same object all the same.
    const Environment* studio = cache.environment("builtin:studio", warnings).get();
    EXPECT_EQ(cache.environment("builtin:studio", warnings).get(), studio);
    // Nothing is shared between caches: each caller owns what it loaded.
    AssetCache other;
    EXPECT_NE(other.environment("builtin:studio", warnings).get(), studio);
    EXPECT_TRUE(warnings.empty());
}

TEST_F(Assets, AMissingOrBrokenFileIsAnInputErrorNamingIt) {
    AssetCache cache;
    std::vector<std::string> warnings;
    const std::string sky = path("sky.hdr").string(), model = path("model.glb").string();

    const Scene noModel = sceneOf(model, "builtin:studio");
    std::string message = inputErrorOf([&] { prepareScene(noModel, cache, warnings); });
    EXPECT_NE(message.find(model), std::string::npos) << message;

    const Scene noSky = sceneOf("", sky);
    message = inputErrorOf([&] { prepareScene(noSky, cache, warnings); });
    EXPECT_NE(message.find(sky), std::string::npos) << message;

    std::ofstream(sky, std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16 +X 32\n";   // no pixels
    message = inputErrorOf([&] { prepareScene(noSky, cache, warnings); });
    EXPECT_NE(message.find(sky), std::string::npos) << message;

    std::ofstream(model, std::ios::binary) << "glTF";   // truncated
    message = inputErrorOf([&] { prepareScene(noModel, cache, warnings); });
    EXPECT_NE(message.find(model), std::string::npos) << message;

    const Scene unknown = sceneOf("", "builtin:nowhere");
    message = inputErrorOf([&] { prepareScene(unknown, cache, warnings); });
    EXPECT_NE(message.find("builtin:nowhere"), std::string::npos) << message;
}

TEST_F(Assets, APreparedSceneHoldsWhatItsDocumentNames) {
    AssetCache cache;
    std::vector<std::string> warnings;
    exportGltf(path("torus.glb"), makeTorus(), Material{});
    Scene scene = sceneOf(path("torus.glb").string(), "builtin:studio");
    const PreparedScene prepared = prepareScene(scene, cache, warnings);
    EXPECT_EQ(&prepared.scene, &scene);
    EXPECT_EQ(prepared.mesh->positions.size(), makeTorus().positions.size());
    ASSERT_TRUE(prepared.environment);
    EXPECT_EQ(prepared.environment->source, "builtin:studio");
    // No enabled environment light: nothing loaded for one; a built-in mesh: the shared one.
    scene.lights[0].enabled = false;
    scene.meshFile.clear();
    const PreparedScene dark = prepareScene(scene, cache, warnings);
    EXPECT_FALSE(dark.environment);
    EXPECT_EQ(dark.mesh, builtinMesh(MeshKind::Sphere));
}

// A glTF scene is prepared with the model it draws beside its flattened mesh, both from one
// load of the file: its primitive, its material's factors, one item where the file puts it;
// glTF's default material (item material -1) for a file without one. A built-in mesh has none.
TEST_F(Assets, AGltfSceneIsPreparedWithTheModelItDraws) {
    AssetCache cache;
    std::vector<std::string> warnings;
    Material gold;
    gold.baseColor = {1.0f, 0.78f, 0.34f};
    gold.metallic = 1.0f;
    gold.roughness = 0.25f;
    exportGltf(path("torus.glb"), makeTorus(), gold);
    Scene scene;
    scene.meshFile = path("torus.glb").string();
    const PreparedScene prepared = prepareScene(scene, cache, warnings);
    ASSERT_TRUE(prepared.model);
    const Model& model = *prepared.model;
    ASSERT_EQ(model.primitives.size(), 1u);
    EXPECT_EQ(model.primitives[0].positions.size(), prepared.mesh->positions.size());
    ASSERT_EQ(model.draws.size(), 1u);
    EXPECT_EQ(model.draws[0].primitive, 0);
    EXPECT_EQ(model.draws[0].transform, glm::mat4(1.0f));
    ASSERT_EQ(model.draws[0].material, 0);
    ASSERT_EQ(model.materials.size(), 1u);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(model.materials[0].factors.baseColor[c], gold.baseColor[c], 1e-6f);
    }
    EXPECT_NEAR(model.materials[0].factors.metallic, 1.0f, 1e-6f);
    EXPECT_NEAR(model.materials[0].factors.roughness, 0.25f, 1e-6f);
    EXPECT_EQ(prepareScene(scene, cache, warnings).model, prepared.model) << "loaded once";
    EXPECT_EQ(cache.mesh(scene), prepared.mesh);

    test::GltfBuilder cube = test::cubeModel();
    cube.json["meshes"][0]["primitives"][0].erase("material");
    cube.json.erase("materials");
    cube.writeGlb(path("plain.glb"));
    scene.meshFile = path("plain.glb").string();
    const PreparedScene plain = prepareScene(scene, cache, warnings);
    ASSERT_TRUE(plain.model);
    EXPECT_EQ(plain.model->draws.at(0).material, -1);
    MaterialParameters defaults = defaultModelMaterial();
    defaults.model = scene.material.model;
    EXPECT_EQ(sceneDraws(plain).at(0).material, defaults);

    scene.meshFile.clear();
    EXPECT_FALSE(prepareScene(scene, cache, warnings).model);
}

TEST_F(Assets, TheRendererDrawsAPreparedSceneWithoutLoading) {
    // Prepared, then the files are gone: the renderer reads nothing, so the image is the same.
    test::glContext();
    AssetCache cache;
    std::vector<std::string> warnings;
    exportGltf(path("torus.glb"), makeTorus(), Material{});
    test::writeFlatHdr(path("sky.hdr"), 32, 16, 100);
    Scene scene = sceneOf(path("torus.glb").string(), path("sky.hdr").string());
    scene.display.backgroundFromEnvironment = true;
    const PreparedScene prepared = prepareScene(scene, cache, warnings);
    Renderer renderer;
    const RenderSettings settings = test::renderSettings(48, 48, RenderPath::Single, 1);
    const LdrImage before = renderer.render(prepared, settings).ldr;
    fs::remove(path("torus.glb"));
    fs::remove(path("sky.hdr"));
    EXPECT_EQ(renderer.render(prepared, settings).ldr.rgba, before.rgba);
    Renderer fresh;
    EXPECT_EQ(fresh.render(prepared, settings).ldr.rgba, before.rgba);
}

}  // namespace
}  // namespace patina
