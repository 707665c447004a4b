// The `patina` program end to end: outputs, exit codes (2 usage, 3 bad input) and messages,
// and no output file left behind by a failure.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "cli_runner.h"
#include "file_reads.h"
#include "gltf_builder.h"
#include "gltf/model_export.h"
#include "image/image.h"
#include "picture/png_text.h"
#include "io/json_writer.h"
#include "io/scene_file.h"
#include "scratch_test.h"
#include "files/file_bytes.h"
#include "test_support.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

class Cli : public test::ScratchTest {
protected:
    test::CliRun run(const std::string& arguments) const { return test::runPatina(arguments, dir_); }
    // The sum of every channel of a 48 x 48 render of the default scene with the material file
    // `material`, or of its ground truth (--reference, 64 samples).
    double renderedSum(const char* material, bool reference) const {
        const std::string out = path(std::string(material) + (reference ? "-r" : "") + ".pfm").string();
        const test::CliRun r = run("render --width 48 --height 48 --msaa 1 --material " + path(material).string() +
                                   (reference ? " --reference --reference-samples 64" : "") + " --out " +
                                   path("x.png").string() + " --hdr " + out);
        EXPECT_EQ(r.exitCode, 0) << r.stderrText;
        const HdrImage image = decodePfm(readFileBytes(out));
        double total = 0.0;
        for (float v : image.rgb) {
            total += v;
        }
        return total;
    }
};

TEST_F(Cli, RendersTheDefaultSceneToPngAndPfm) {
    const test::CliRun r = run("render --width 96 --height 64 --out " + path("a.png").string() + " --hdr " +
                      path("a.pfm").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    const LdrImage png = decodePng(readFileBytes(path("a.png")));
    EXPECT_EQ(png.width, 96);
    EXPECT_EQ(png.height, 64);
    const HdrImage pfm = decodePfm(readFileBytes(path("a.pfm")));
    EXPECT_EQ(pfm.width, 96);
    EXPECT_GT(pfm.rgb[(32 * 96 + 48) * 3], 0.0f);
}

TEST_F(Cli, TheReferenceRenderConvergesToTheRender) {
    // The default scene's studio by Monte Carlo through pixel centres, against the split sum
    // without MSAA: close on average (the split sum's own error is a few per cent), identical in
    // the background.
    ASSERT_EQ(run("render --width 48 --height 48 --msaa 1 --out " + path("s.png").string() + " --hdr " +
                  path("s.pfm").string()).exitCode, 0);
    const test::CliRun r = run("render --width 48 --height 48 --reference --reference-samples 64 --out " +
                               path("r.png").string() + " --hdr " + path("r.pfm").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_NE(r.stderrText.find("64 of 64 samples per pixel"), std::string::npos) << r.stderrText;
    const HdrImage split = decodePfm(readFileBytes(path("s.pfm")));
    const HdrImage reference = decodePfm(readFileBytes(path("r.pfm")));
    ASSERT_EQ(reference.rgb.size(), split.rgb.size());
    EXPECT_EQ(decodePng(readFileBytes(path("r.png"))).width, 48);
    EXPECT_EQ(reference.rgb[0], split.rgb[0]);   // a background corner
    double sumSplit = 0.0, sumReference = 0.0;
    for (size_t i = 0; i < split.rgb.size(); ++i) {
        sumSplit += split.rgb[i];
        sumReference += reference.rgb[i];
    }
    EXPECT_NEAR(sumReference / sumSplit, 1.0, 0.05);
}

// `render --reference --visibility` (issue 37): a floor under a small roof, in the default scene's
// lights and studio, takes the roof's shadow and occlusion, so the picture's light drops; the
// flag without --reference is refused by name.
TEST_F(Cli, TheReferenceWithVisibilityShadowsWhatStandsInTheWay) {
    test::GltfBuilder model;
    const auto quad = [&](float y, float half) {
        const int positions = model.positions({{-half, y, half}, {half, y, half}, {half, y, -half}, {-half, y, -half}});
        const int normals = model.positions({{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}});
        const int indices = model.data(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, test::kUnsignedShort, "SCALAR", 1);
        model.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}, {"indices", indices}});
    };
    quad(0.0f, 2.0f);
    quad(0.4f, 0.6f);
    model.writeGlb(path("roofed.glb"));
    const std::string common = "render --mesh " + path("roofed.glb").string() +
                               " --width 64 --height 48 --reference --reference-samples 16 --out ";
    ASSERT_EQ(run(common + path("open.png").string() + " --hdr " + path("open.pfm").string()).exitCode, 0);
    const test::CliRun shadowed = run(common + path("seen.png").string() + " --hdr " + path("seen.pfm").string() +
                                      " --visibility");
    ASSERT_EQ(shadowed.exitCode, 0) << shadowed.stderrText;
    const HdrImage open = decodePfm(readFileBytes(path("open.pfm")));
    const HdrImage seen = decodePfm(readFileBytes(path("seen.pfm")));
    double sumOpen = 0.0, sumSeen = 0.0;
    for (size_t i = 0; i < open.rgb.size(); ++i) {
        sumOpen += open.rgb[i];
        sumSeen += seen.rgb[i];
    }
    EXPECT_LT(sumSeen, 0.97 * sumOpen);
    const test::CliRun alone = run("render --visibility --out " + path("x.png").string());
    EXPECT_NE(alone.exitCode, 0);
    EXPECT_NE(alone.stderrText.find("--reference"), std::string::npos) << alone.stderrText;
}

// The ground truth measures the coat (KHR_materials_clearcoat): `render --reference` of a coated
// `gltf` sphere in the default studio (its lights and environment) takes the coated BRDF sample
// by sample, and the split sum's render is within the same 5% of it as the bare material's;
// without the coat in the reference, the two would part by the coat's share.
TEST_F(Cli, TheReferenceRenderMeasuresTheCoat) {
    Material coated;
    coated.model = BrdfModelId::Gltf;
    coated.baseColor = {0.05f, 0.05f, 0.3f};
    coated.roughness = 0.6f;
    coated.clearcoat = 1.0f;
    coated.clearcoatRoughness = 0.25f;
    saveMaterialFile(path("coated.json"), coated);
    Material bare = coated;
    bare.clearcoat = 0.0f;
    saveMaterialFile(path("bare.json"), bare);
    const double coatedRender = renderedSum("coated.json", false), coatedTruth = renderedSum("coated.json", true);
    const double bareRender = renderedSum("bare.json", false), bareTruth = renderedSum("bare.json", true);
    EXPECT_NEAR(coatedTruth / coatedRender, 1.0, 0.05);
    EXPECT_NEAR(bareTruth / bareRender, 1.0, 0.05);
    // The coat is a visible share of what both show.
    EXPECT_GT(std::abs(coatedTruth / bareTruth - 1.0), 0.1);
    EXPECT_GT(std::abs(coatedRender / bareRender - 1.0), 0.1);
}

// The ground truth measures the sheen (KHR_materials_sheen): `render --reference` of a sheened
// `gltf` sphere in the default studio takes the extension's sheened BRDF sample by sample (E at
// N.V and N.L), and the render (E at N.V alone under the environment, the sheen lit by the
// irradiance) is within the same 5% of it as the bare material's; the sheen is a visible share.
TEST_F(Cli, TheReferenceRenderMeasuresTheSheen) {
    Material sheened;
    sheened.model = BrdfModelId::Gltf;
    sheened.baseColor = {0.3f, 0.05f, 0.1f};
    sheened.roughness = 0.8f;
    sheened.sheenColor = {1.0f, 0.8f, 0.9f};
    sheened.sheenRoughness = 0.5f;
    saveMaterialFile(path("sheened.json"), sheened);
    Material bare = sheened;
    bare.sheenColor = glm::vec3(0.0f);
    saveMaterialFile(path("bare.json"), bare);
    const double sheenRender = renderedSum("sheened.json", false), sheenTruth = renderedSum("sheened.json", true);
    const double bareRender = renderedSum("bare.json", false), bareTruth = renderedSum("bare.json", true);
    std::cout << "sheen: truth / render " << sheenTruth / sheenRender << ", bare: " << bareTruth / bareRender
              << ", sheen's share of the truth " << sheenTruth / bareTruth - 1.0 << "\n";
    EXPECT_NEAR(sheenTruth / sheenRender, 1.0, 0.05);
    EXPECT_NEAR(bareTruth / bareRender, 1.0, 0.05);
    EXPECT_GT(sheenTruth / bareTruth - 1.0, 0.1);
    EXPECT_GT(sheenRender / bareRender - 1.0, 0.1);
}

TEST_F(Cli, TheEnvironmentMethodChangesThePictureAndIsChecked) {
    const std::string size = " --width 48 --height 48 --msaa 1 --hdr ";
    ASSERT_EQ(run("render" + size + path("s.pfm").string() + " --out " + path("s.png").string()).exitCode, 0);
    ASSERT_EQ(run("render --environment-method dominant" + size + path("d.pfm").string() + " --out " +
                  path("d.png").string()).exitCode, 0);
    ASSERT_EQ(run("render --environment-method stochastic --environment-samples 4" + size + path("t.pfm").string() +
                  " --out " + path("t.png").string()).exitCode, 0);
    const HdrImage split = decodePfm(readFileBytes(path("s.pfm")));
    for (const char* other : {"d.pfm", "t.pfm"}) {
        const HdrImage image = decodePfm(readFileBytes(path(other)));
        ASSERT_EQ(image.rgb.size(), split.rgb.size());
        EXPECT_NE(image.rgb, split.rgb) << other;
    }
    EXPECT_EQ(run("render --environment-method nearest --out " + path("x.png").string()).exitCode, 2);
    EXPECT_EQ(run("render --environment-samples 0 --out " + path("x.png").string()).exitCode, 2);
    EXPECT_FALSE(std::filesystem::exists(path("x.png")));
}

TEST_F(Cli, MultiPassGivesTheSamePicture) {
    ASSERT_EQ(run("render --width 64 --height 64 --passes multi --out " + path("m.png").string()).exitCode, 0);
    ASSERT_EQ(run("render --width 64 --height 64 --passes single --out " + path("s.png").string()).exitCode, 0);
    const LdrImage m = decodePng(readFileBytes(path("m.png")));
    const LdrImage s = decodePng(readFileBytes(path("s.png")));
    int worst = 0;
    for (size_t i = 0; i < m.rgba.size(); ++i) {
        worst = std::max(worst, std::abs(int(m.rgba[i]) - int(s.rgba[i])));
    }
    EXPECT_LE(worst, 1);
}

TEST_F(Cli, BadSceneExitsThreeNamingTheProblemAndWritesNothing) {
    write("bad.json", R"({"format": "patina-scene", "version": 1, "lights": [{"type": "laser"}]})");
    const test::CliRun r = run("render --scene " + path("bad.json").string() + " --out " + path("x.png").string());
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.stderrText.find("bad.json: /lights/0/type: unknown light type"), std::string::npos)
        << r.stderrText;
    EXPECT_FALSE(fs::exists(path("x.png")));
}

// A new user's slip: a glTF model given where a scene goes is named as a model, with where it goes.
TEST_F(Cli, AModelGivenAsASceneSaysItIsAModel) {
    write("model.gltf", R"({"asset": {"version": "2.0"}})");
    const test::CliRun r = run("render --scene " + path("model.gltf").string() + " --out " + path("x.png").string());
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.stderrText.find("model.gltf: /format: missing: this is a glTF model, not a patina-scene file (a model is "
                                "drawn with --mesh"),
              std::string::npos)
        << r.stderrText;
    EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(Cli, ANegativeLightSizeExitsThreeNamingTheKey) {
    write("size.json", R"({"format": "patina-scene", "version": 2, "lights": [{"type": "sphere", "sourceRadius": -0.5}]})");
    const test::CliRun r = run("render --scene " + path("size.json").string() + " --out " + path("x.png").string());
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.stderrText.find("size.json: /lights/0/sourceRadius: value -0.5 is outside"), std::string::npos)
        << r.stderrText;
    EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(Cli, BadInputsExitThree) {
    write("syntax.json", "{\n\"format\": \"patina-material\",\n\"version\": 1,,\n}");
    write("range.json", R"({"format": "patina-material", "version": 1, "metallic": 2})");
    const std::string out = " --out " + path("x.png").string();
    test::CliRun r = run("render --material " + path("syntax.json").string() + out);
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.stderrText.find("syntax.json:3:"), std::string::npos) << r.stderrText;
    r = run("render --material " + path("range.json").string() + out);
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.stderrText.find("/metallic: value 2 is outside [0, 1]"), std::string::npos) << r.stderrText;
    r = run("render --scene " + path("missing.json").string() + out);
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.stderrText.find("missing.json"), std::string::npos);
    r = run("render --out " + path("no/such/dir/x.png").string());
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(Cli, UsageErrorsExitTwo) {
    EXPECT_EQ(run("render").exitCode, 2);                                   // no --out
    EXPECT_EQ(run("render --passes triple --out x.png").exitCode, 2);
    EXPECT_EQ(run("render --width 0 --out x.png").exitCode, 2);
    EXPECT_EQ(run("--paint").exitCode, 2);
    EXPECT_EQ(run("paint").exitCode, 3);   // not a subcommand: a file for the editor, missing
    EXPECT_EQ(run("render --help").exitCode, 0);
    EXPECT_EQ(run("probe --help").exitCode, 0);
    EXPECT_EQ(run("lobe --help").exitCode, 0);
}

TEST_F(Cli, AModelByMeshIsFramedAndLitTheSameAtAnySize) {
    // The two balls as made (about 3.4 units across) and 300 times larger, far from the origin:
    // --mesh frames each and moves the default scene's point light onto it (the directional
    // light and the studio have no size), so both render the same picture. Without the fit
    // the large one fills the frame and swallows the light.
    Model small = test::twoBalls();
    Model large = small;
    const glm::mat4 grow = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(500.0f, -200.0f, 40.0f)),
                                      glm::vec3(300.0f));
    for (DrawItem& draw : large.draws) {
        draw.transform = grow * draw.transform;
    }
    exportGltfModel(path("small.glb"), small);
    exportGltfModel(path("large.glb"), large);
    for (const char* name : {"small", "large"}) {
        const test::CliRun r = run(std::string("render --msaa 1 --width 64 --height 48 --mesh ") +
                                   path(std::string(name) + ".glb").string() + " --out " +
                                   path(std::string(name) + ".png").string() + " --hdr " +
                                   path(std::string(name) + ".pfm").string());
        ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    }
    const HdrImage a = decodePfm(readFileBytes(path("small.pfm")));
    const HdrImage b = decodePfm(readFileBytes(path("large.pfm")));
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    double lit = 0.0, difference = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        lit += a.rgb[i];
        difference += std::abs(double(a.rgb[i]) - double(b.rgb[i]));
    }
    EXPECT_LT(difference / lit, 0.01);
    // The centre of the frame is between the balls: the background, not a ball filling it.
    EXPECT_EQ(test::pixel(a, 32, 24), test::pixel(a, 0, 0));
    EXPECT_EQ(test::pixel(b, 32, 24), test::pixel(b, 0, 0));
}

// A Patina screenshot is a scene for --scene, a model's too; a PNG without one is refused.
TEST_F(Cli, AScreenshotIsASceneForRender) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    Scene scene = defaultScene();
    scene.meshFile = path("two.glb").string();
    writeFileAtomic(path("shot.png"), encodePngWithText(LdrImage{1, 1, {0, 0, 0, 255}},
                                                        {{kSceneTextKeyword, sceneToJson(scene).dump()}}));
    test::CliRun r = run("render --width 48 --height 32 --scene " + path("shot.png").string() + " --out " +
                         path("again.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_EQ(decodePng(readFileBytes(path("again.png"))).width, 48);
    r = run("render --scene " + path("again.png").string() + " --out " + path("x.png").string());
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.stderrText.find("again.png: this PNG holds no scene"), std::string::npos) << r.stderrText;
}

// --mesh replaces a scene's model that is gone: the render goes ahead and says so.
TEST_F(Cli, MeshReplacesAModelTheSceneCannotRead) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    write("gone.json", R"({"format": "patina-scene", "version": 2, "mesh": "gone.glb"})");
    const test::CliRun r = run("render --width 32 --height 24 --scene " + path("gone.json").string() + " --mesh " +
                               path("two.glb").string() + " --out " + path("x.png").string());
    EXPECT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_NE(r.stderrText.find("gone.glb: cannot open"), std::string::npos) << r.stderrText;
    EXPECT_NE(r.stderrText.find("--mesh replaces it"), std::string::npos) << r.stderrText;
    EXPECT_TRUE(fs::exists(path("x.png")));
}

// A model drawn is read once: hashed and imported from the same bytes (AssetCache::model; it
// was read twice).
TEST_F(Cli, AModelsFileIsReadOnceForAPicture) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    test::FileReads reads(path("two.glb"));
    const test::CliRun r = run("render --width 32 --height 24 --mesh " + path("two.glb").string() + " --out " +
                               path("x.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_EQ(reads.count(), 1);
}

TEST_F(Cli, AMeshThatIsNoMeshIsRefused) {
    const test::CliRun r = run("render --mesh ball.obj --out " + path("x.png").string());
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.stderrText.find("--mesh: \"ball.obj\" is neither sphere, torus nor a .gltf/.glb file"),
              std::string::npos) << r.stderrText;
    EXPECT_FALSE(fs::exists(path("x.png")));
}

// `patina validate`: a line each, exit 0 when every material is in range, 1 when one is not,
// 3 when a file cannot be read (the others still checked).
TEST_F(Cli, ValidateSaysOfEachMaterialWhetherItIsInRange) {
    const fs::path presets = fs::path(PATINA_SOURCE_DIR) / "presets";
    std::string every;
    int count = 0;
    for (const auto& entry : fs::directory_iterator(presets)) {
        every += " " + entry.path().string();
        ++count;
    }
    test::CliRun r = run("validate" + every);
    EXPECT_EQ(r.exitCode, 0) << r.stdoutText << r.stderrText;
    int lines = 0;
    for (std::istringstream in(r.stdoutText); std::getline(in, every);) {
        EXPECT_NE(every.find(": ok: "), std::string::npos) << every;
        ++lines;
    }
    EXPECT_EQ(lines, count);

    write("coal.json", R"({"format": "patina-material", "version": 1, "name": "coal", "baseColor": [0.004, 0.004, 0.004]})");
    write("lead.json", R"({"format": "patina-material", "version": 1, "name": "lead", "baseColor": [0.1, 0.1, 0.1],
                           "metallic": 1.0})");
    r = run("validate " + path("coal.json").string() + " " + (presets / "gold.json").string() + " " +
            path("lead.json").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.stdoutText.find("coal.json: out of range: dielectric, albedo 13 sRGB, darker than any real dielectric"),
              std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("gold.json: ok: metal, reflectance"), std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("lead.json: out of range: metal, reflectance 89 sRGB, below the darkest measured metal"),
              std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stderrText.find("2 of 3 materials out of range"), std::string::npos) << r.stderrText;

    // A clear glass's white passes through (KHR_materials_transmission): its bright end is the
    // share it reflects; a white that passes 10% is still brighter than snow.
    write("glass.json", R"({"format": "patina-material", "version": 1, "name": "glass", "model": "gltf",
                            "baseColor": [1, 1, 1], "transmission": 1})");
    write("milk.json", R"({"format": "patina-material", "version": 1, "name": "milk", "model": "gltf",
                           "baseColor": [1, 1, 1], "transmission": 0.1})");
    r = run("validate " + path("glass.json").string() + " " + path("milk.json").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.stdoutText.find("glass.json: ok: dielectric, albedo 255 sRGB, 0 sRGB of it reflected diffusely (the rest passes through) "
                                "(30-240)"),
              std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("milk.json: out of range: dielectric, albedo 255 sRGB, 243 sRGB of it reflected diffusely (the rest passes "
                                "through), brighter than any real dielectric"),
              std::string::npos) << r.stdoutText;

    // Strict ranges; a file that does not read is said and the rest checked.
    r = run("validate --strict " + (presets / "titanium.json").string() + " " + path("missing.json").string());
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.stdoutText.find("titanium.json: out of range: metal, reflectance 171 sRGB"), std::string::npos)
        << r.stdoutText;
    EXPECT_NE(r.stderrText.find("missing.json"), std::string::npos) << r.stderrText;
}

// On a glTF model: each material, by its base colour map's texels where it has one.
TEST_F(Cli, ValidateChecksAModelsMaterialsTexelByTexel) {
    Model model = test::twoBalls();
    model.images.push_back({"half black", 2, 1, {0, 0, 0, 255, 200, 200, 200, 255}});
    model.materials[0].factors.metallic = 0.0f;
    model.materials[0].factors.baseColor = glm::vec3(1.0f);
    model.materials[0].baseColor.image = 0;
    model.materials[1].factors.metallic = 0.0f;
    model.materials[1].factors.baseColor = glm::vec3(0.5f);
    exportGltfModel(path("two.glb"), model);
    const test::CliRun r = run("validate " + path("two.glb").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.stdoutText.find("two.glb material 0 \"left\": out of range: base colour map, 50.0% of 2 texels flagged "
                                "(dielectric below 30 sRGB 50.0%"),
              std::string::npos) << r.stdoutText;
    EXPECT_NE(r.stdoutText.find("two.glb material 1 \"right\": ok: dielectric, albedo 188 sRGB (30-240)"), std::string::npos)
        << r.stdoutText;
}

// ClearCoatTest (assimp-testmodels, Khronos's sample): its "Coated" column shows the coat. The
// same file without KHR_materials_clearcoat draws that column as its "Base layer" (what every
// build before the coat drew); with it, only that column changes, and its highlights are the
// coat's, brighter than the rough base's.
TEST_F(Cli, ClearCoatTestsCoatedColumnShowsItsCoat) {
    const fs::path source = "/usr/share/assimp/models/glTF2/ClearCoat-glTF";
    if (!fs::exists(source / "ClearCoatTest.gltf")) {
        GTEST_SKIP() << "needs Debian's assimp-testmodels";
    }
    fs::copy(source, path("coat"), fs::copy_options::recursive);
    Json document = Json::parse(std::ifstream(path("coat/ClearCoatTest.gltf")));
    document.erase("extensionsUsed");
    for (Json& material : document["materials"]) {
        if (material.contains("extensions")) {
            material.erase("extensions");
        }
    }
    std::ofstream(path("coat/bare.gltf")) << document.dump();
    auto render = [&](const char* file, const char* out) {
        const test::CliRun r = run("render --mesh " + path(std::string("coat/") + file).string() +
                                   " --width 240 --height 200 --msaa 1 --out " + path("x.png").string() + " --hdr " +
                                   path(out).string());
        EXPECT_EQ(r.exitCode, 0) << r.stderrText;
        EXPECT_EQ(r.stderrText.find("not drawn"), std::string::npos) << r.stderrText;
        return decodePfm(readFileBytes(path(out)));
    };
    const HdrImage coated = render("ClearCoatTest.gltf", "coated.pfm");
    const HdrImage bare = render("bare.gltf", "bare.pfm");
    ASSERT_EQ(coated.rgb.size(), bare.rgb.size());
    int drawnLeft = coated.width, drawnRight = -1, changedLeft = coated.width, changedRight = -1;
    size_t changed = 0;
    double brightestCoated = 0.0, brightestBare = 0.0;
    for (int y = 0; y < coated.height; ++y) {
        for (int x = 0; x < coated.width; ++x) {
            const size_t i = (size_t(y) * size_t(coated.width) + size_t(x)) * 3;
            if (bare.rgb[i] != bare.rgb[0] || bare.rgb[i + 2] != bare.rgb[2]) {
                drawnLeft = std::min(drawnLeft, x);
                drawnRight = std::max(drawnRight, x);
            }
            const glm::vec3 a(coated.rgb[i], coated.rgb[i + 1], coated.rgb[i + 2]);
            const glm::vec3 b(bare.rgb[i], bare.rgb[i + 1], bare.rgb[i + 2]);
            if (a != b) {
                ++changed;
                changedLeft = std::min(changedLeft, x);
                changedRight = std::max(changedRight, x);
                brightestCoated = std::max(brightestCoated, double(a.x + a.y + a.z));
                brightestBare = std::max(brightestBare, double(b.x + b.y + b.z));
            }
        }
    }
    EXPECT_GT(changed, 500u);
    // One column of three (and the labels beside them) out of what is drawn.
    EXPECT_LT(changedRight - changedLeft, (drawnRight - drawnLeft) / 4) << changedLeft << ".." << changedRight;
    EXPECT_GT(brightestCoated, 1.5 * brightestBare);
}

// Every file told: render and validate print what the picture lacks of a file's extensions, the
// same lines; a file that requires one Patina cannot draw exits 3 naming it.
TEST_F(Cli, RenderAndValidateNameTheExtensionsPatinaDoesNotDraw) {
    test::GltfBuilder coated = test::cubeModel();
    coated.json["extensionsUsed"] = {"KHR_materials_diffuse_transmission"};
    coated.json["materials"][0]["extensions"]["KHR_materials_diffuse_transmission"] = {{"diffuseTransmissionFactor", 1.0}};
    coated.writeGlb(path("coated.glb"));
    const std::string line =
        "warning: uses KHR_materials_diffuse_transmission (not drawn): light through the surface is left out; the material "
        "shows opaque";
    const test::CliRun rendered = run("render --mesh " + path("coated.glb").string() + " --width 32 --height 24 --out " +
                                      path("coated.png").string());
    EXPECT_EQ(rendered.exitCode, 0) << rendered.stderrText;
    EXPECT_NE(rendered.stderrText.find(line), std::string::npos) << rendered.stderrText;
    const test::CliRun validated = run("validate " + path("coated.glb").string());
    EXPECT_NE(validated.stderrText.find(line), std::string::npos) << validated.stderrText;

    coated.json["extensionsRequired"] = {"KHR_materials_diffuse_transmission"};
    coated.writeGlb(path("required.glb"));
    const test::CliRun refused = run("render --mesh " + path("required.glb").string() + " --out " +
                                     path("required.png").string());
    EXPECT_EQ(refused.exitCode, 3);
    EXPECT_NE(refused.stderrText.find("requires the extension KHR_materials_diffuse_transmission, which Patina does not draw"),
              std::string::npos) << refused.stderrText;
    EXPECT_FALSE(std::filesystem::exists(path("required.png")));
}

TEST_F(Cli, ProbeOnCpuAndGpuAgree) {
    write("in.csv",
          "px,py,pz,nx,ny,nz,vx,vy,vz\n"
          "0,0,1,0,0,1,0,0,1\n"
          "0.6,0.8,0,0.6,0.8,0,0,0.3,0.95\n"
          "0,-1,0,0,-1,0,0,-1,0\n");
    ASSERT_EQ(run("probe --backend cpu --in " + path("in.csv").string() + " --out " + path("cpu.csv").string()).exitCode, 0);
    ASSERT_EQ(run("probe --backend gpu --in " + path("in.csv").string() + " --out " + path("gpu.csv").string()).exitCode, 0);
    std::istringstream cpu(read("cpu.csv")), gpu(read("gpu.csv"));
    std::string cpuLine, gpuLine;
    std::getline(cpu, cpuLine);
    std::getline(gpu, gpuLine);
    EXPECT_EQ(cpuLine, "r,g,b");
    EXPECT_EQ(gpuLine, "r,g,b");
    int rows = 0;
    while (std::getline(cpu, cpuLine) && std::getline(gpu, gpuLine)) {
        ++rows;
        double c[3], g[3];
        ASSERT_EQ(std::sscanf(cpuLine.c_str(), "%lf,%lf,%lf", &c[0], &c[1], &c[2]), 3);
        ASSERT_EQ(std::sscanf(gpuLine.c_str(), "%lf,%lf,%lf", &g[0], &g[1], &g[2]), 3);
        for (int i = 0; i < 3; ++i) {
            EXPECT_GT(c[i], 0.0);   // every row faces at least the hemisphere light
            EXPECT_NEAR(g[i], c[i], 1e-5 * c[i]);
        }
    }
    EXPECT_EQ(rows, 3);
}

TEST_F(Cli, ProbeRejectsBadCsvByLine) {
    write("in.csv", "px,py,pz,nx,ny,nz,vx,vy,vz\n0,0,1,0,0,1,0,0,1\n0,0,1,0,zero,1,0,0,1\n");
    const test::CliRun r = run("probe --backend cpu --in " + path("in.csv").string() + " --out " + path("o.csv").string());
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.stderrText.find("in.csv:3: column 5"), std::string::npos) << r.stderrText;
    EXPECT_FALSE(fs::exists(path("o.csv")));
    write("header.csv", "x,y,z\n");
    EXPECT_EQ(run("probe --in " + path("header.csv").string() + " --out " + path("o.csv").string()).exitCode, 3);
}

TEST_F(Cli, LobePeaksAtTheMirrorDirection) {
    write("shiny.json", R"({"format": "patina-material", "version": 1, "roughness": 0.2})");
    ASSERT_EQ(run("lobe --material " + path("shiny.json").string() +
                  " --theta-in 30 --samples 181 --out " + path("lobe.csv").string()).exitCode, 0);
    std::istringstream csv(read("lobe.csv"));
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "theta_out_deg,diffuse_r,diffuse_g,diffuse_b,specular_r,specular_g,specular_b,"
                    "total_r,total_g,total_b");
    double bestAngle = 0, bestSpecular = -1;
    int rows = 0;
    while (std::getline(csv, line)) {
        double v[10];
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1],
                              &v[2], &v[3], &v[4], &v[5], &v[6], &v[7], &v[8], &v[9]), 10);
        EXPECT_NEAR(v[7], v[1] + v[4], 1e-6 * v[7]);
        if (v[4] > bestSpecular) {
            bestSpecular = v[4];
            bestAngle = v[0];
        }
        ++rows;
    }
    EXPECT_EQ(rows, 181);
    EXPECT_NEAR(bestAngle, -30.0, 1.0);
}

}  // namespace
}  // namespace patina

namespace patina {
namespace {

TEST_F(Cli, ModelOptionAndKeyChooseTheBrdf) {
    write("in.csv", "px,py,pz,nx,ny,nz,vx,vy,vz\n0,0,1,0,0,1,0.6,0,0.8\n");
    ASSERT_EQ(run("probe --backend cpu --in " + path("in.csv").string() + " --out " + path("epic.csv").string()).exitCode, 0);
    ASSERT_EQ(run("probe --backend cpu --model reference --in " + path("in.csv").string() + " --out " +
                  path("reference.csv").string()).exitCode, 0);
    EXPECT_NE(read("epic.csv"), read("reference.csv"));
    write("m.json", R"({"format": "patina-material", "version": 1, "model": "reference"})");
    ASSERT_EQ(run("probe --backend cpu --material " + path("m.json").string() + " --in " + path("in.csv").string() +
                  " --out " + path("from-file.csv").string()).exitCode, 0);
    EXPECT_EQ(read("from-file.csv"), read("reference.csv"));
    const test::CliRun bad = run("probe --model phong --in " + path("in.csv").string() + " --out " + path("x.csv").string());
    EXPECT_EQ(bad.exitCode, 3);
    EXPECT_NE(bad.stderrText.find("unknown BRDF model \"phong\""), std::string::npos) << bad.stderrText;
    write("bad.json", R"({"format": "patina-material", "version": 1, "model": "phong"})");
    EXPECT_NE(run("lobe --theta-in 30 --material " + path("bad.json").string() + " --out " + path("l.csv").string())
                  .stderrText.find("bad.json: /model: unknown BRDF model"), std::string::npos);
}

}  // namespace
}  // namespace patina
