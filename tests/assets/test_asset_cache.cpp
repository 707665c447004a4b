// The assets layer: what a scene names, loaded once through a cache its caller owns, and the
// prepared scene the renderer draws without loading anything itself.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "assets/asset_cache.h"
#include "assets/prepare_scene.h"
#include "gltf/export.h"
#include "gltf/model_export.h"
#include "gltf/model_import.h"
#include "image/image.h"
#include "files/input_error.h"
#include "file_reads.h"
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
    EXPECT_EQ(cache.shape(scene).model.get(), &model->model);
    EXPECT_EQ(cache.shape(scene).fileModel, model);
}

// One door: each ask reads the model's file once, to hash it and, when it is not held, to
// import it (it was read twice, three times through the editor's load).
TEST_F(Assets, AModelsFileIsReadOnceEachTimeItIsAskedFor) {
    exportGltf(path("torus.glb"), makeTorus(), Material{});
    AssetCache cache;
    test::FileReads reads(path("torus.glb"));
    const std::shared_ptr<const LoadedModel> model = cache.model(path("torus.glb"));
    EXPECT_EQ(reads.count(), 1) << "loaded";
    EXPECT_EQ(model->mesh.positions.size(), makeTorus().positions.size());
    EXPECT_EQ(cache.model(path("torus.glb")), model);
    EXPECT_EQ(reads.count(), 1) << "held: hashed only";

    AssetCache fresh;
    const Scene scene = sceneOf(path("torus.glb").string(), "builtin:white");
    std::vector<std::string> warnings;
    const PreparedScene prepared = prepareScene(scene, fresh, warnings);
    EXPECT_EQ(reads.count(), 1) << "a scene prepared";
    EXPECT_EQ(prepared.mesh->positions.size(), makeTorus().positions.size());
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
    const std::shared_ptr<const LoadedModel> whole = assets.model(path("maps.glb"));   // nothing stale was kept
    ASSERT_NE(whole, nullptr);
    EXPECT_EQ(whole->model.images.size(), 4u);
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

TEST_F(Assets, AnEnvironmentComesBackFromTheDiskCacheAsItWasMade) {
    // The prefiltered chain and the irradiance map both: a second cache (nothing in memory)
    // reads the file the first wrote, bit for bit.
    test::writeFlatHdr(path("sky.hdr"), 64, 32, 100);
    std::vector<std::string> warnings;
    const auto made = AssetCache().environment(path("sky.hdr").string(), warnings);
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(path("cache"))) {
        files += entry.path().extension() == ".env";
    }
    EXPECT_EQ(files, 1u);
    const auto read = AssetCache().environment(path("sky.hdr").string(), warnings);
    ASSERT_NE(read, made);
    ASSERT_EQ(read->prefiltered.size(), made->prefiltered.size());
    for (size_t level = 0; level < made->prefiltered.size(); ++level) {
        EXPECT_EQ(read->prefiltered[level].faces, made->prefiltered[level].faces) << level;
    }
    EXPECT_EQ(read->irradiance.size, kIrradianceFaceSize);
    EXPECT_EQ(read->irradiance.faces, made->irradiance.faces);
    // A grey sky of radiance r everywhere: E = pi r.
    EXPECT_NEAR(read->irradiance.texel(2, 3, 4).x, std::numbers::pi_v<float> * read->image.rgb[0],
                3e-3f * std::numbers::pi_v<float> * read->image.rgb[0]);
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

// Where a chain is prefiltered is the caller's word, passed down (no thread-wide hook): the
// function given makes a chain made afresh, and a chain found in memory or on disk is not made.
int prefiltersRun = 0;
CubeChain countingPrefilter(const CubeChain& source, const PrefilterSettings& settings, const Progress& progress) {
    ++prefiltersRun;
    return prefilterCube(source, settings, progress);
}

TEST_F(Assets, AnEnvironmentIsPrefilteredWhereItsCallerSays) {
    prefiltersRun = 0;
    test::writeFlatHdr(path("sky.hdr"), 64, 32, 100);
    AssetCache cache;
    std::vector<std::string> warnings;
    const Scene scene = sceneOf("", path("sky.hdr").string());
    const PreparedScene prepared = prepareScene(scene, cache, warnings, countingPrefilter);
    ASSERT_TRUE(prepared.environment);
    EXPECT_EQ(prefiltersRun, 1);
    prepareScene(scene, cache, warnings, countingPrefilter);   // held in memory
    AssetCache().environment(path("sky.hdr").string(), warnings, {}, {}, countingPrefilter);   // on disk
    EXPECT_EQ(prefiltersRun, 1);
    // A built-in, made afresh by another cache, through the function given, and by default on
    // the CPU without it.
    AssetCache().environment("builtin:studio", warnings, {}, {}, countingPrefilter);
    EXPECT_EQ(prefiltersRun, 2);
    fs::remove_all(path("cache"));
    AssetCache().environment("builtin:studio", warnings);
    EXPECT_EQ(prefiltersRun, 2);
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
    EXPECT_EQ(sceneDraws(plain).at(0).material, defaultModelMaterial());   // shaded as glTF's

    scene.meshFile.clear();
    EXPECT_FALSE(prepareScene(scene, cache, warnings).model);
}

// A scene's tuning of a material the model does not have (an index past its materials, or a
// name that is not the one there: the file changed since the scene was saved) is said, naming
// the entry, as the model's own notes are; one that matches is not.
TEST_F(Assets, ATuningOfNoMaterialOfTheModelIsSaid) {
    AssetCache cache;
    exportGltfModel(path("two.glb"), test::twoBalls());
    Scene scene;
    scene.meshFile = path("two.glb").string();
    std::vector<std::string> warnings;
    const PreparedScene plain = prepareScene(scene, cache, warnings);
    ASSERT_TRUE(plain.model);
    const std::string first = plain.model->materials.at(0).name;
    Material matching;
    static_cast<MaterialParameters&>(matching) = plain.model->materials[0].factors;
    matching.name = first;
    Material renamed = matching;
    renamed.name = "old name";
    scene.modelMaterials = {{0, matching}, {1, renamed}, {7, matching}};
    warnings.clear();
    prepareScene(scene, cache, warnings);
    std::string all;
    for (const std::string& line : warnings) {
        all += line + "\n";
    }
    EXPECT_EQ(warnings.size(), 2u) << all;
    EXPECT_NE(all.find("modelMaterials: the tuning of material 1 \"old name\" is not drawn: the model's material 1 is \"" +
                       plain.model->materials.at(1).name + "\""),
              std::string::npos) << all;
    EXPECT_NE(all.find("the tuning of material 7 \"" + first + "\" is not drawn: the model has 2 materials"),
              std::string::npos) << all;
}

// The image a scene puts in place of a model's map: drawn there (the same picture as a file
// with that image as the map), only for that material (another sharing the file's image keeps
// it), with the map's UV set, sampler and transform; the same object while held; exported.
TEST_F(Assets, AReplacedMapIsDrawnInPlaceOfTheFilesForThatMaterialOnly) {
    test::glContext();
    Model file = test::twoBalls();
    file.images.push_back({"grey", 4, 4, std::vector<uint8_t>(4 * 4 * 4, 90)});
    for (ModelMaterial& material : file.materials) {
        material.baseColor.image = 0;   // shared
        material.baseColor.sampler.wrapS = TextureWrap::MirroredRepeat;
        material.baseColor.transform.scale = {2.0f, 3.0f};
    }
    exportGltfModel(path("grey.glb"), file);
    const LdrImage red{2, 2, {200, 20, 10, 255, 190, 30, 10, 255, 210, 10, 20, 255, 200, 25, 15, 255}};
    test::GltfBuilder::writeBytes(path("red.png"), encodePng(red));
    Model redLeft = file;   // what the replacement should draw: the left ball's map red
    redLeft.images.push_back({"red", 2, 2, red.rgba});
    redLeft.materials[0].baseColor.image = 1;
    exportGltfModel(path("red-left.glb"), redLeft);

    AssetCache cache;
    std::vector<std::string> warnings;
    Scene scene = defaultScene();   // lit: a scene without lights draws every map black
    scene.meshFile = path("grey.glb").string();
    Material left;
    left.name = "left";
    scene.modelMaterials = {{0, left}};
    scene.modelMaterials[0].material.baseColor = glm::vec3(1.0f);
    scene.modelMaterials[0].mapsReplaced = {{"baseColorTexture", path("red.png").string()}};
    const PreparedScene prepared = prepareScene(scene, cache, warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.at(0);
    const std::shared_ptr<const LoadedModel> loaded = cache.model(scene.meshFile);
    const Model* fromFile = &loaded->model;
    ASSERT_NE(prepared.model.get(), fromFile);
    const Model& model = *prepared.model;
    ASSERT_EQ(model.images.size(), 2u);
    EXPECT_EQ(model.images[1].rgba, red.rgba);
    EXPECT_EQ(model.images[1].name, "red.png") << "its file's name, no folder: a name goes into exports";
    EXPECT_EQ(model.materials[0].baseColor.image, 1);
    EXPECT_EQ(model.materials[1].baseColor.image, 0) << "the right ball shares the file's image and keeps it";
    EXPECT_EQ(model.materials[0].baseColor.sampler, fromFile->materials[0].baseColor.sampler);
    EXPECT_EQ(model.materials[0].baseColor.transform, fromFile->materials[0].baseColor.transform);
    EXPECT_EQ(model.primitives.at(0).positions, fromFile->primitives.at(0).positions);
    EXPECT_EQ(cache.shape(scene).model, prepared.model) << "made once while held";
    Scene untouched = scene;
    untouched.modelMaterials[0].mapsReplaced.clear();
    EXPECT_EQ(cache.retextured(loaded, untouched).get(), fromFile) << "no replacement: the file's model";
    EXPECT_EQ(cache.retextured(loaded, scene), prepared.model) << "found by its key";

    Scene expected = scene;
    expected.meshFile = path("red-left.glb").string();
    expected.modelMaterials[0].mapsReplaced.clear();
    const PreparedScene drawn = prepareScene(expected, cache, warnings);
    Renderer renderer;
    const RenderSettings settings = test::renderSettings(64, 48, RenderPath::Single, 1);
    const LdrImage want = renderer.render(drawn, settings).ldr;
    EXPECT_EQ(renderer.render(prepared, settings).ldr.rgba, want.rgba);
    const glm::ivec2 ball = test::pixelOf(scene.camera, glm::vec3(-1.2f, 0.0f, 1.0f), 64, 48);
    const uint8_t* shown = &want.rgba[(size_t(ball.y) * 64 + size_t(ball.x)) * 4];
    EXPECT_GT(shown[0], 2 * shown[1]) << "the left ball is red";
    scene.modelMaterials[0].mapsReplaced.clear();
    EXPECT_NE(renderer.render(prepareScene(scene, cache, warnings), settings).ldr.rgba, want.rgba);

    // The export writes the replacement as the map.
    exportGltfModel(path("export.glb"), tunedModel(model, expected));
    const Model exported = importGltfModel(path("export.glb"));
    ASSERT_GE(exported.materials.at(0).baseColor.image, 0);
    EXPECT_EQ(exported.images.at(size_t(exported.materials[0].baseColor.image)).rgba, red.rgba);
}

// A replacement that cannot be used leaves the file's map drawn and says why: an image that
// is missing or is not PNG nor JPEG, a map the material lacks, an edit of another material.
TEST_F(Assets, AReplacementThatCannotBeUsedKeepsTheFilesMapWithANote) {
    Model file = test::twoBalls();
    file.images.push_back({"grey", 4, 4, std::vector<uint8_t>(4 * 4 * 4, 90)});
    file.materials[0].baseColor.image = 0;
    exportGltfModel(path("grey.glb"), file);
    test::GltfBuilder::writeBytes(path("text.png"), std::vector<uint8_t>{'n', 'o', 't', ' ', 'a', 'n', ' ', 'i'});
    AssetCache cache;
    Scene scene;
    scene.meshFile = path("grey.glb").string();
    Material left;
    left.name = "left";
    Material other;
    other.name = "not right";   // index 1 is "right": this edit is of another file's material
    scene.modelMaterials = {{0, left}, {1, other}};
    for (const auto& [key, file, note] :
         {std::tuple{"baseColorTexture", "missing.png", "missing.png: cannot open"},
          std::tuple{"baseColorTexture", "text.png", "text.png: the image is neither PNG, JPEG nor WebP"},
          std::tuple{"normalTexture", "text.png", "the material has no normalTexture to replace"}}) {
        scene.modelMaterials[0].mapsReplaced = {{key, path(file).string()}};
        scene.modelMaterials[1].mapsReplaced = {{"baseColorTexture", path(file).string()}};
        std::vector<std::string> warnings;
        const PreparedScene prepared = prepareScene(scene, cache, warnings);
        // The replacement's note, and the other file's material's tuning said as not drawn (its
        // replacement not tried).
        ASSERT_EQ(warnings.size(), 2u) << key << " " << file;
        EXPECT_NE(warnings[1].find("the tuning of material 1 \"not right\" is not drawn"), std::string::npos)
            << warnings[1];
        EXPECT_NE(warnings[0].find("material 0 (\"left\"): the image for its " + std::string(key) + " is not used"),
                  std::string::npos)
            << warnings[0];
        EXPECT_NE(warnings[0].find(note), std::string::npos) << warnings[0];
        EXPECT_NE(warnings[0].find("the file's map is drawn"), std::string::npos) << warnings[0];
        EXPECT_EQ(prepared.model->images.size(), 1u);
        EXPECT_EQ(prepared.model->materials, cache.model(scene.meshFile)->model.materials);
    }
    EXPECT_NE(inputErrorOf([&] { cache.image(path("text.png")); }).find("text.png: the image is neither PNG, JPEG nor WebP"),
              std::string::npos);
}

// A material named on the command line changes a part's factors, not its maps.
TEST_F(Assets, AMaterialPutOnThePartsKeepsTheirMapsReplacedAndLeftOut) {
    const Model file = test::twoBalls();
    Scene scene;
    Material left;
    left.name = "left";
    scene.modelMaterials = {{0, left}};
    scene.modelMaterials[0].mapsOff = {"normalTexture"};
    scene.modelMaterials[0].mapsReplaced = {{"baseColorTexture", "/maps/red.png"}};
    Material gold;
    gold.name = "gold";
    gold.metallic = 1.0f;
    setPartMaterials(scene, file, gold);
    ASSERT_EQ(scene.modelMaterials.size(), 2u);
    EXPECT_EQ(scene.modelMaterials[0].material.metallic, 1.0f);
    EXPECT_EQ(scene.modelMaterials[0].material.name, "left");
    EXPECT_EQ(scene.modelMaterials[0].mapsOff, std::vector<std::string>{"normalTexture"});
    EXPECT_EQ(scene.modelMaterials[0].mapsReplaced.at("baseColorTexture"), "/maps/red.png");
    EXPECT_EQ(scene.modelMaterials[1].material.name, "right");
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
