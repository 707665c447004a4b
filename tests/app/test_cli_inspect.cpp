// The inspector on the command line (docs/INSPECTOR.md): `render --channel` writes a channel as
// data (the PFM untouched, the PNG without exposure or tone map), on the GPU or with
// --reference the CPU twin, and refuses what it cannot show with exit 2 or 3.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "files/file_bytes.h"
#include "image/image.h"
#include "scene/json_value.h"
#include "scene/scene.h"
#include "scratch_test.h"
#include "shading/shading.h"
#include "test_support.h"

namespace patina {
namespace {

class CliInspect : public test::ScratchTest {
protected:
    test::CliRun run(const std::string& arguments) const { return test::runPatina(arguments, dir_); }
};

// The default material's base colour, untouched in the PFM at the sphere's centre and 0 off it;
// the PNG holds the value itself (x 255), or with --channel-srgb its sRGB encoding.
TEST_F(CliInspect, AChannelIsWrittenAsData) {
    const glm::vec3 base = defaultScene().material.baseColor;
    for (const char* where : {"", " --reference"}) {
        const test::CliRun r = run(std::string("render --channel base-color --width 64 --height 64") + where +
                                   " --out " + path("b.png").string() + " --hdr " + path("b.pfm").string());
        ASSERT_EQ(r.exitCode, 0) << r.stderrText;
        const HdrImage pfm = decodePfm(readFileBytes(path("b.pfm")));
        EXPECT_EQ(test::pixel(pfm, 32, 32), base) << where;
        EXPECT_EQ(test::pixel(pfm, 0, 0), glm::vec3(0.0f)) << where;
        const LdrImage png = decodePng(readFileBytes(path("b.png")));
        EXPECT_EQ(png.rgba[(32 * 64 + 32) * 4], uint8_t(std::lround(base.r * 255.0f))) << where;
    }
    ASSERT_EQ(run("render --channel base-color --channel-srgb --width 64 --height 64 --out " + path("s.png").string())
                  .exitCode,
              0);
    const LdrImage srgb = decodePng(readFileBytes(path("s.png")));
    EXPECT_EQ(srgb.rgba[(32 * 64 + 32) * 4], uint8_t(std::lround(shader::srgbEncode(base.r) * 255.0f)));
}

// Normals are signed: the PNG shows n / 2 + 1/2 of the PFM's n, and the sphere's normal at its
// centre points at the camera.
TEST_F(CliInspect, ASignedChannelIsShownAroundMidGrey) {
    ASSERT_EQ(run("render --channel shading-normal --width 65 --height 65 --out " + path("n.png").string() +
                  " --hdr " + path("n.pfm").string())
                  .exitCode,
              0);
    const LdrImage png = decodePng(readFileBytes(path("n.png")));
    const glm::vec3 normal = test::pixel(decodePfm(readFileBytes(path("n.pfm"))), 32, 32);
    const Camera camera = defaultScene().camera;
    EXPECT_GT(glm::dot(normal, glm::normalize(camera.position - camera.target)), 0.999f);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(png.rgba[(32 * 65 + 32) * 4 + c], uint8_t(std::lround((normal[c] * 0.5f + 0.5f) * 255.0f))) << c;
    }
}

TEST_F(CliInspect, AnUnknownChannelIsAUsageErrorAndAMissingLightBadInput) {
    const test::CliRun unknown = run("render --channel albedo --out " + path("u.png").string());
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_NE(unknown.stderrText.find("unknown channel \"albedo\" (known: base-color, alpha,"), std::string::npos)
        << unknown.stderrText;
    const test::CliRun light = run("render --channel light:nobody --out " + path("l.png").string());
    EXPECT_EQ(light.exitCode, 3);
    EXPECT_NE(light.stderrText.find("no enabled light of that name"), std::string::npos) << light.stderrText;
    EXPECT_FALSE(std::filesystem::exists(path("u.png")));
    EXPECT_FALSE(std::filesystem::exists(path("l.png")));
}

// "pbr-validation: N of M surface pixels flagged ..." on stdout: N and M.
std::pair<long, long> flaggedOf(const std::string& out) {
    long flagged = -1, surface = -1;
    std::sscanf(out.c_str(), "pbr-validation: %ld of %ld surface pixels flagged", &flagged, &surface);
    return {flagged, surface};
}

// `render --channel pbr-validation` counts what it flags: none of the rubber preset's pixels
// by the default ranges (albedo 42 sRGB), all of them by the strict ones (from 50); on a real
// textured model (BoxTextured, 8.7% of whose texels are brighter than snow: `patina validate`)
// some of the pixels, the same number within 2% on the GPU and the CPU twin.
TEST_F(CliInspect, PbrValidationCountsTheFlaggedPixels) {
    const std::string rubber = " --material " + (std::filesystem::path(PATINA_SOURCE_DIR) / "presets/rubber.json").string();
    const test::CliRun lenient = run("render --channel pbr-validation --width 64 --height 64 --out " +
                                     path("r.png").string() + rubber);
    ASSERT_EQ(lenient.exitCode, 0) << lenient.stderrText;
    const test::CliRun strict = run("render --channel pbr-validation --pbr-strict --width 64 --height 64 --out " +
                                    path("s.png").string() + rubber);
    ASSERT_EQ(strict.exitCode, 0) << strict.stderrText;
    EXPECT_EQ(flaggedOf(lenient.stdoutText).first, 0) << lenient.stdoutText;
    EXPECT_GT(flaggedOf(lenient.stdoutText).second, 1000) << lenient.stdoutText;
    EXPECT_EQ(flaggedOf(strict.stdoutText).first, flaggedOf(strict.stdoutText).second) << strict.stdoutText;
    EXPECT_NE(strict.stdoutText.find("dielectric below 50 sRGB"), std::string::npos) << strict.stdoutText;

    const std::string box = " --mesh /usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    long counts[2];
    for (int reference = 0; reference < 2; ++reference) {
        const test::CliRun r = run("render --channel pbr-validation --width 128 --height 128 --out " +
                                   path("b.png").string() + box + (reference ? " --reference" : ""));
        ASSERT_EQ(r.exitCode, 0) << r.stderrText;
        const auto [flagged, surface] = flaggedOf(r.stdoutText);
        EXPECT_GT(flagged, surface / 50) << r.stdoutText;
        EXPECT_LT(flagged, surface / 4) << r.stdoutText;
        counts[reference] = flagged;
    }
    EXPECT_NEAR(double(counts[0]), double(counts[1]), 0.02 * double(counts[1]));
}

// `slice` writes BRDF Explorer's slice: the diffuse lobe's values are c_diff / pi at every pixel
// above the horizon (the default material is a dielectric: c_diff is its base colour), the PNG
// the size asked; `albedo` writes the split sum beside the ground truth with its error, a row an
// angle; a lobe it does not know is a usage error.
TEST_F(CliInspect, SliceAndAlbedoWriteBrdfExplorersViews) {
    const test::CliRun slice = run("slice --lobe diffuse --phi-d 0 --size 32 --out " + path("s.png").string() +
                                   " --hdr " + path("s.pfm").string());
    ASSERT_EQ(slice.exitCode, 0) << slice.stderrText;
    const HdrImage values = decodePfm(readFileBytes(path("s.pfm")));
    ASSERT_EQ(values.width, 32);
    const glm::vec3 expected = defaultScene().material.baseColor / 3.14159265f;
    int above = 0, below = 0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const glm::vec3 f = test::pixel(values, x, y);
            if (f.x < 0.0f) {
                ++below;
                continue;
            }
            ++above;
            EXPECT_NEAR(f.g, expected.g, 1e-5f);
        }
    }
    EXPECT_GT(above, 400);
    EXPECT_GT(below, 400);   // phi_d = 0: theta_h + theta_d past 90 degrees
    EXPECT_EQ(decodePng(readFileBytes(path("s.png"))).width, 32);

    const test::CliRun albedo =
        run("albedo --points 5 --samples 256 --out " + path("a.csv").string() + " --chart " + path("a").string());
    ASSERT_EQ(albedo.exitCode, 0) << albedo.stderrText;
    const std::string csv(reinterpret_cast<const char*>(readFileBytes(path("a.csv")).data()),
                          readFileBytes(path("a.csv")).size());
    EXPECT_EQ(csv.rfind("theta_v_deg,split_sum_r,", 0), 0u) << csv;
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 6);
    float theta = -1, product = -1, truth = -1;
    ASSERT_EQ(std::sscanf(csv.c_str() + csv.find('\n') + 1, "%f,%f,%*f,%*f,%f", &theta, &product, &truth), 3);
    EXPECT_EQ(theta, 0.0f);
    EXPECT_NEAR(product, truth, 0.05f);
    for (const char* extension : {".png", ".svg", ".pdf"}) {
        EXPECT_TRUE(std::filesystem::exists(path(std::string("a") + extension))) << extension;
    }

    EXPECT_EQ(run("slice --lobe shiny --out " + path("x.png").string()).exitCode, 2);
    EXPECT_FALSE(std::filesystem::exists(path("x.png")));
}

glm::vec3 vec3Of(const Json& values) {
    return {values.at(0).get<float>(), values.at(1).get<float>(), values.at(2).get<float>()};
}

// `inspect` tells the pixel's story from the CPU twin, and it is the GPU's pixel: the radiance
// the render wrote there (without MSAA), the display value its PNG holds; the lights' and the
// environment's lobes add up to that radiance.
TEST_F(CliInspect, InspectAgreesWithTheRenderedPixel) {
    ASSERT_EQ(run("render --msaa 1 --width 120 --height 90 --out " + path("r.png").string() + " --hdr " +
                  path("r.pfm").string())
                  .exitCode,
              0);
    const HdrImage rendered = decodePfm(readFileBytes(path("r.pfm")));
    const LdrImage shown = decodePng(readFileBytes(path("r.png")));
    for (const auto& [x, y] : {std::pair{60, 45}, std::pair{45, 30}, std::pair{75, 60}}) {
        const test::CliRun r = run("inspect --width 120 --height 90 --x " + std::to_string(x) + " --y " +
                                   std::to_string(y));
        ASSERT_EQ(r.exitCode, 0) << r.stderrText;
        const Json story = Json::parse(r.stdoutText);
        ASSERT_TRUE(story.at("surface").get<bool>());
        const glm::vec3 radiance = vec3Of(story.at("radiance")), expected = test::pixel(rendered, x, y);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(radiance[c], expected[c], 1e-3f + 1e-2f * expected[c]) << x << " " << y;
            EXPECT_NEAR(story.at("display").at(c).get<int>(), shown.rgba[size_t(y * 120 + x) * 4 + size_t(c)], 1)
                << x << " " << y;
        }
        glm::vec3 sum = vec3Of(story.at("emission"));
        for (const Json& light : story.at("lights")) {
            sum += vec3Of(light.at("diffuse")) + vec3Of(light.at("specular"));
        }
        sum += vec3Of(story.at("environment").at("diffuse")) + vec3Of(story.at("environment").at("specular"));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(sum[c], radiance[c], 1e-5f + 1e-5f * radiance[c]);
        }
        EXPECT_EQ(vec3Of(story.at("baseColor")), defaultScene().material.baseColor);
        EXPECT_EQ(story.at("keyLight"), "warm key");
    }
}

// `inspect` lists the layers' own light (issue 36): the hand-written velvet's sheen at its
// centre, no coat or transmission there; on the default scene's bare sphere all are 0.
TEST_F(CliInspect, InspectListsTheLayersOfAPartThatHasThem) {
    const std::string velvet = std::string(PATINA_SOURCE_DIR) + "/tests/data/sheen/velvet.gltf";
    const test::CliRun sheened = run("inspect --mesh " + velvet + " --width 64 --height 64 --x 32 --y 32");
    ASSERT_EQ(sheened.exitCode, 0) << sheened.stderrText;
    const Json story = Json::parse(sheened.stdoutText);
    ASSERT_TRUE(story.at("surface").get<bool>()) << sheened.stdoutText;
    const glm::vec3 sheen = vec3Of(story.at("sheen"));
    EXPECT_GT(sheen.x + sheen.y + sheen.z, 0.0f) << sheened.stdoutText;
    EXPECT_EQ(vec3Of(story.at("clearcoat")), glm::vec3(0.0f));
    EXPECT_EQ(vec3Of(story.at("transmission")), glm::vec3(0.0f));
    const test::CliRun bare = run("inspect --width 120 --height 90 --x 60 --y 45");
    ASSERT_EQ(bare.exitCode, 0) << bare.stderrText;
    const Json plain = Json::parse(bare.stdoutText);
    EXPECT_EQ(vec3Of(plain.at("sheen")), glm::vec3(0.0f));
    EXPECT_EQ(vec3Of(plain.at("clearcoat")), glm::vec3(0.0f));
    EXPECT_EQ(vec3Of(plain.at("transmission")), glm::vec3(0.0f));
}

// `inspect` says where an anisotropic part's highlight stretches (KHR_materials_anisotropy): the
// built-in sphere has no tangent ("tangent" 0), so the direction is the fallback's, round the y
// axis at rotation 0 (no y), turned a quarter by a rotation of pi/2, in the surface; the
// roughness along it above the one across. A part without the layer has none.
TEST_F(CliInspect, InspectSaysWhereAnAnisotropicHighlightStretches) {
    auto stretch = [&](float rotation) {
        write("brushed.json", R"({"format": "patina-material", "version": 1, "name": "brushed", "model": "gltf",
                                  "baseColor": [0.9, 0.9, 0.9], "roughness": 0.3, "metallic": 1,
                                  "anisotropyStrength": 0.8, "anisotropyRotation": )" +
                                  std::to_string(rotation) + "}");
        const test::CliRun r = run("inspect --material " + path("brushed.json").string() +
                                   " --width 64 --height 64 --x 36 --y 28");
        EXPECT_EQ(r.exitCode, 0) << r.stderrText;
        return Json::parse(r.stdoutText);
    };
    const Json along = stretch(0.0f), across = stretch(1.5707963f);
    ASSERT_TRUE(along.at("anisotropy").is_object()) << along.dump();
    EXPECT_EQ(vec3Of(along.at("tangent")), glm::vec3(0.0f));
    const glm::vec3 t = vec3Of(along.at("anisotropy").at("direction"));
    const glm::vec3 n = vec3Of(along.at("normal"));
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-4f);
    EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-4f);
    EXPECT_NEAR(t.y, 0.0f, 1e-4f);
    EXPECT_NEAR(glm::dot(t, vec3Of(across.at("anisotropy").at("direction"))), 0.0f, 1e-4f);
    EXPECT_GT(along.at("anisotropy").at("alphaT").get<float>(), along.at("anisotropy").at("alphaB").get<float>());
    EXPECT_NEAR(along.at("anisotropy").at("strength").get<float>(), 0.8f, 1e-6f);
    const test::CliRun bare = run("inspect --width 64 --height 64 --x 36 --y 28");
    EXPECT_TRUE(Json::parse(bare.stdoutText).at("anisotropy").is_null()) << bare.stdoutText;
}

TEST_F(CliInspect, APixelOutsideTheImageIsAUsageErrorAndTheBackgroundHasNoSurface) {
    const test::CliRun outside = run("inspect --width 100 --height 50 --x 10 --y 50");
    EXPECT_EQ(outside.exitCode, 2);
    EXPECT_NE(outside.stderrText.find("pixel (10, 50) is outside the 100 x 50 image"), std::string::npos)
        << outside.stderrText;
    const test::CliRun corner = run("inspect --width 100 --height 50 --x 0 --y 0");
    ASSERT_EQ(corner.exitCode, 0) << corner.stderrText;
    EXPECT_FALSE(Json::parse(corner.stdoutText).at("surface").get<bool>());
}

}  // namespace
}  // namespace patina
