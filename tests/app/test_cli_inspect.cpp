// The inspector on the command line (docs/INSPECTOR.md): `render --channel` writes a channel as
// data (the PFM untouched, the PNG without exposure or tone map), on the GPU or with
// --reference the CPU twin, and refuses what it cannot show with exit 2 or 3.
#include <cmath>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "files/file_bytes.h"
#include "image/image.h"
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

}  // namespace
}  // namespace patina
