// Scenes whose "mesh" is a glTF file (docs/FORMATS.md): resolved against the scene file,
// written back, rendered; refused in a PNG's embedded scene.
#include <filesystem>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "gltf_builder.h"
#include "image/image.h"
#include "picture/png_text.h"
#include "io/scene_file.h"
#include "scratch_test.h"
#include "files/file_bytes.h"
#include "assets/asset_cache.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

// A scene file beside a folder holding a small cube.
class GltfScene : public test::ScratchTest {
protected:
    void SetUp() override {
        ScratchTest::SetUp();
        fs::create_directory(path("models"));
        test::GltfBuilder cube = test::cubeModel();
        cube.json["nodes"][0]["scale"] = {0.4, 0.4, 0.4};
        // The file's material is what shows: a dielectric, which the scenes' hemisphere light
        // (diffuse only) lights. glTF's defaults make a metal, which it leaves black.
        cube.json["materials"][0]["pbrMetallicRoughness"] = {{"metallicFactor", 0.0}};
        cube.writeGlb(path("models/cube.glb"));
    }
    test::CliRun run(const std::string& arguments) const { return test::runPatina(arguments, dir_); }
    std::string scene(const std::string& mesh) const {
        return R"({"format": "patina-scene", "version": 1, "mesh": ")" + mesh +
               R"(", "lights": [{"type": "hemisphere", "sky": [1, 1, 1], "ground": [1, 1, 1]}],
                  "display": {"background": [0, 0, 0]}})";
    }
};

TEST_F(GltfScene, AMeshPathIsResolvedAgainstTheSceneFileAndRoundTrips) {
    write("scene.json", scene("models/cube.glb"));
    std::vector<std::string> warnings;
    Scene loaded = loadSceneFile(path("scene.json"), warnings);
    EXPECT_EQ(fs::path(loaded.meshFile), fs::absolute(path("models/cube.glb")));
    EXPECT_EQ(sceneFromJson(sceneToJson(loaded), "x", "/elsewhere", warnings), loaded);
    AssetCache assets;
    EXPECT_EQ(assets.mesh(loaded)->positions.size(), 24u);
    EXPECT_EQ(sceneToJson(defaultScene())["mesh"], "sphere");

    write("typo.json", scene("models/cube"));
    try {
        loadSceneFile(path("typo.json"), warnings);
        FAIL() << "a mesh that is neither built in nor glTF was accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("/mesh: unknown mesh \"models/cube\" (expected \"sphere\", \"torus\" "
                                                 "or a .gltf or .glb file)"),
                  std::string::npos)
            << error.what();
    }
}

TEST_F(GltfScene, RenderDrawsTheFile) {
    write("cube.json", scene("models/cube.glb"));
    write("sphere.json", scene("sphere"));
    for (const char* name : {"cube", "sphere"}) {
        const std::string scenePath = path(std::string(name) + ".json").string();
        const test::CliRun r = run("render --width 64 --height 64 --msaa 1 --scene " + scenePath + " --out " +
                                   path(std::string(name) + ".png").string());
        ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    }
    const LdrImage cube = decodePng(readFileBytes(path("cube.png")));
    const LdrImage sphere = decodePng(readFileBytes(path("sphere.png")));
    auto lit = [](const LdrImage& image, int x, int y) { return image.rgba[size_t(y * image.width + x) * 4] > 40; };
    EXPECT_TRUE(lit(cube, 32, 32));
    EXPECT_TRUE(lit(sphere, 32, 32));
    EXPECT_TRUE(lit(sphere, 32, 14));    // inside the unit sphere, outside the small cube
    EXPECT_FALSE(lit(cube, 32, 14));

    write("missing.json", scene("models/none.gltf"));
    const test::CliRun missing =
        run("render --scene " + path("missing.json").string() + " --out " + path("m.png").string());
    EXPECT_EQ(missing.exitCode, 3);
    EXPECT_NE(missing.stderrText.find("none.gltf"), std::string::npos) << missing.stderrText;
    EXPECT_FALSE(fs::exists(path("m.png")));
}

TEST_F(GltfScene, AScreenshotSceneNamesItsModelByAbsolutePathOnly) {
    // A screenshot of a model holds the model's absolute path (Scene::meshFile) and reopens
    // with it. A relative one, like a material path, would make the PNG read files beside it.
    write("scene.json", scene("models/cube.glb"));
    std::vector<std::string> warnings;
    const Scene shown = loadSceneFile(path("scene.json"), warnings);
    auto shot = [&](const std::string& json) {
        writeFileAtomic(path("shot.png"), encodePngWithText(LdrImage{1, 1, {0, 0, 0, 255}}, {{kSceneTextKeyword, json}}));
        return sceneFromPng(path("shot.png"), warnings);
    };
    const std::optional<Scene> reopened = shot(sceneToJson(shown).dump());
    ASSERT_TRUE(reopened);
    EXPECT_EQ(reopened->meshFile, shown.meshFile);
    try {
        shot(scene("models/cube.glb"));
        FAIL() << "a screenshot naming a mesh file beside it was accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("/mesh: an embedded scene must use a built-in mesh"),
                  std::string::npos)
            << error.what();
    }
    // An image replacing one of its maps likewise: absolute, as a screenshot writes it.
    Scene replaced = shown;
    Material edited;
    edited.name = "cube";
    replaced.modelMaterials = {{0, edited}};
    replaced.modelMaterials[0].mapsReplaced = {{"baseColorTexture", path("worn.png").string()}};
    const std::optional<Scene> withImage = shot(sceneToJson(replaced).dump());
    ASSERT_TRUE(withImage);
    EXPECT_EQ(withImage->modelMaterials, replaced.modelMaterials);
    Json relative = sceneToJson(replaced);
    relative["modelMaterials"][0]["mapsReplaced"]["baseColorTexture"] = "worn.png";
    try {
        shot(relative.dump());
        FAIL() << "a screenshot naming an image beside it was accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("/modelMaterials/0/mapsReplaced/baseColorTexture: an embedded scene "
                                                 "must name a replacing image by its absolute path"),
                  std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace patina
