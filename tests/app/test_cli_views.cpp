// How the picture-making commands look at a scene as the web viewers do: --camera (the glTF
// file's own), --orbit and --target (model-viewer's camera-orbit and camera-target) and
// --tonemap, with bad values refused (exit 3; exit 2 for usage).
#include <cmath>
#include <filesystem>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "cli_runner.h"
#include "files/file_bytes.h"
#include "gltf_builder.h"
#include "image/image.h"
#include "io/json_reader.h"
#include "scene/camera_placement.h"
#include "scratch_test.h"
#include "test_support.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

class CliViews : public test::ScratchTest {
protected:
    test::CliRun run(const std::string& arguments) const { return test::runPatina(arguments, dir_); }

    // The linear image `arguments` render writes (as --hdr), at `size` x `size`.
    HdrImage rendered(const std::string& arguments, int size = 65) const {
        const test::CliRun r = run("render --msaa 1 --width " + std::to_string(size) + " --height " +
                                   std::to_string(size) + " --out " + path("v.png").string() + " --hdr " +
                                   path("v.pfm").string() + " " + arguments);
        EXPECT_EQ(r.exitCode, 0) << arguments << "\n" << r.stderrText;
        return r.exitCode == 0 ? decodePfm(readFileBytes(path("v.pfm"))) : HdrImage{};
    }
};

// Where the ray from `eye` along the unit `direction` first meets the unit sphere at the origin.
glm::vec3 firstHit(glm::vec3 eye, glm::vec3 direction) {
    const float b = glm::dot(eye, direction), c = glm::dot(eye, eye) - 1.0f;
    return eye + (-b - std::sqrt(b * b - c)) * direction;
}

void expectNear(glm::vec3 got, glm::vec3 want, float tolerance, const std::string& what) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], want[c], tolerance) << what << ", component " << c;
    }
}

// The centre pixel of the default scene's unit sphere shows the point the camera looks at: with
// --orbit it is target + r (sin phi sin theta, cos phi, sin phi cos theta), so the sphere's
// normal there points back along that direction; --target moves what it looks at, and alone
// keeps the eye's offset from it.
TEST_F(CliViews, OrbitAndTargetPlaceTheEyeAsModelViewerDoes) {
    struct Case {
        std::string arguments;
        glm::vec3 normal;
    };
    const glm::vec3 ownEye = defaultScene().camera.position;
    const glm::vec3 shifted(0.0f, 0.3f, 0.0f);
    const Case cases[] = {
        {"--orbit 90 90 3", {1.0f, 0.0f, 0.0f}},
        {"--orbit -90 90 3", {-1.0f, 0.0f, 0.0f}},
        {"--orbit 0 30 4", {0.0f, std::cos(glm::radians(30.0f)), std::sin(glm::radians(30.0f))}},
        {"--orbit 180 120 5", {0.0f, -0.5f, -std::sin(glm::radians(120.0f))}},
        {"--target 0.5 0 0 --orbit 0 90 3", firstHit({0.5f, 0.0f, 3.0f}, {0.0f, 0.0f, -1.0f})},
        {"--target 0 0.3 0", firstHit(ownEye + shifted, glm::normalize(-ownEye))},
    };
    for (const Case& c : cases) {
        const HdrImage normals = rendered("--channel shading-normal " + c.arguments);
        if (normals.width > 0) {
            expectNear(test::pixel(normals, 32, 32), c.normal, 0.01f, c.arguments);
        }
    }
}

TEST_F(CliViews, AnOrbitOutOfRangeIsBadInputAndAMissingNumberAUsageError) {
    for (const char* orbit : {"0 200 3", "0 -1 3", "0 90 0", "nan 90 3"}) {
        const test::CliRun r = run(std::string("render --orbit ") + orbit + " --out " + path("o.png").string());
        EXPECT_EQ(r.exitCode, 3) << orbit << ": " << r.stderrText;
        EXPECT_NE(r.stderrText.find("--orbit"), std::string::npos) << r.stderrText;
    }
    EXPECT_EQ(run("render --orbit 0 90 --out " + path("o.png").string()).exitCode, 2);
    EXPECT_EQ(run("render --target 1 2 --out " + path("o.png").string()).exitCode, 2);
    EXPECT_FALSE(fs::exists(path("o.png")));
}

// render --camera NAME|INDEX looks through the file's camera: the centre shows the quad it
// faces, where the model-viewer framing of the pair shows the gap between them.
TEST_F(CliViews, TheFilesOwnCameraIsTakenByNameOrIndex) {
    test::GltfBuilder model = test::twoQuadsAndTheirCameras();
    model.writeGltf(path("quads.gltf"));
    const std::string mesh = "--channel base-color --mesh " + path("quads.gltf").string();
    const glm::vec3 red(1, 0, 0), green(0, 1, 0);
    EXPECT_EQ(test::pixel(rendered(mesh), 32, 32), glm::vec3(0.0f)) << "framed: between the quads";
    EXPECT_EQ(test::pixel(rendered(mesh + " --camera right"), 32, 32), green);
    EXPECT_EQ(test::pixel(rendered(mesh + " --camera 0"), 32, 32), red);
    // yfov 0.4 rad from 4 away sees 2 tan(0.2) 4 = 1.62 units high: the 2-unit quad fills it.
    const HdrImage right = rendered(mesh + " --camera 1");
    EXPECT_EQ(test::pixel(right, 32, 0), green);
    EXPECT_EQ(test::pixel(right, 0, 32), green);

    const test::CliRun unknown = run("render " + mesh + " --camera top --out " + path("c.png").string());
    EXPECT_EQ(unknown.exitCode, 3);
    EXPECT_NE(unknown.stderrText.find("--camera top: the model has no camera \"top\" (its cameras, by index and name: "
                                      "0 \"left\" (perspective), 1 \"right\" (perspective), 2 \"plan\" (orthographic))"),
              std::string::npos)
        << unknown.stderrText;
    const test::CliRun orthographic = run("render " + mesh + " --camera 2 --out " + path("c.png").string());
    EXPECT_EQ(orthographic.exitCode, 3);
    EXPECT_NE(orthographic.stderrText.find("orthographic: Patina draws perspective cameras only"), std::string::npos)
        << orthographic.stderrText;
    const test::CliRun sphere = run("render --camera 0 --out " + path("c.png").string());
    EXPECT_EQ(sphere.exitCode, 3);
    EXPECT_NE(sphere.stderrText.find("the scene's mesh is the built-in sphere"), std::string::npos)
        << sphere.stderrText;
    EXPECT_EQ(run("render " + mesh + " --camera 0 --orbit 0 90 3 --out " + path("c.png").string()).exitCode, 2);
    EXPECT_FALSE(fs::exists(path("c.png")));
}

// assimp's Cameras.gltf (assimp-testmodels) has a perspective camera and an orthographic one.
TEST_F(CliViews, CamerasGltfRendersThroughItsPerspectiveCamera) {
    const std::string mesh = "--mesh /usr/share/assimp/models/glTF2/cameras/Cameras.gltf";
    const HdrImage framed = rendered(mesh), through = rendered(mesh + " --camera 0");
    EXPECT_NE(framed.rgb, through.rgb);
    const test::CliRun orthographic = run("render " + mesh + " --camera 1 --out " + path("c.png").string());
    EXPECT_EQ(orthographic.exitCode, 3) << orthographic.stderrText;
}

// --tonemap picks the view transform; the old "aces" is Narkowicz's fit, as scene files read it.
TEST_F(CliViews, TheToneMapIsChosenByNameAndTheOldAcesIsNarkowicz) {
    auto png = [&](const std::string& tonemap) {
        const test::CliRun r = run("render --width 48 --height 48 --tonemap " + tonemap + " --out " +
                                   path(tonemap + ".png").string());
        EXPECT_EQ(r.exitCode, 0) << tonemap << ": " << r.stderrText;
        return readFileBytes(path(tonemap + ".png"));
    };
    EXPECT_EQ(png("aces"), png("aces-narkowicz"));
    EXPECT_NE(png("aces-hill"), png("aces-narkowicz"));
    EXPECT_NE(png("agx"), png("aces-hill"));
    EXPECT_NE(png("agx"), png("pbr-neutral"));
    const test::CliRun unknown = run("render --tonemap filmic --out " + path("f.png").string());
    EXPECT_EQ(unknown.exitCode, 3);
    EXPECT_NE(unknown.stderrText.find("--tonemap: unknown tone map \"filmic\" (known: none, pbr-neutral, aces-hill, "
                                      "agx, aces-narkowicz, reinhard)"),
              std::string::npos)
        << unknown.stderrText;
}

// inspect, compare and sheet take the same options: inspect's pixel is where --orbit looks, its
// display value through --tonemap; a sheet's cell is render's picture.
TEST_F(CliViews, InspectCompareAndSheetLookAsRenderDoes) {
    const test::CliRun inspect =
        run("inspect --width 65 --height 65 --x 32 --y 32 --orbit 90 90 3 --tonemap aces-hill");
    ASSERT_EQ(inspect.exitCode, 0) << inspect.stderrText;
    const Json story = parseJsonText(inspect.stdoutText, "inspect");
    expectNear({story["normal"][0], story["normal"][1], story["normal"][2]}, {1, 0, 0}, 0.01f, "inspect");
    const glm::vec3 radiance(story["radiance"][0], story["radiance"][1], story["radiance"][2]);
    const glm::vec3 shown = shader::displayTransform(radiance, 0.0f, shader::TONEMAP_ACES_HILL) * 255.0f;
    expectNear({story["display"][0], story["display"][1], story["display"][2]}, shown, 0.51f, "display (of 255)");

    const std::string preset = (fs::path(PATINA_SOURCE_DIR) / "presets/gold.json").string();
    const std::string view = " --orbit 90 60 3.5 --target 0 0.2 0 --tonemap agx";
    ASSERT_EQ(run("sheet " + preset + " --size 40 --columns 1" + view + " --out " + path("s.png").string()).exitCode, 0);
    ASSERT_EQ(run("compare " + preset + " " + preset + " --width 40 --height 40" + view + " --out " +
                  path("c.png").string()).exitCode, 0);
    ASSERT_EQ(run("render --passes specialised --width 40 --height 40 --material " + preset + view + " --out " +
                  path("r.png").string()).exitCode, 0);
    ASSERT_EQ(run("render --passes specialised --width 40 --height 40 --material " + preset + " --out " +
                  path("plain.png").string()).exitCode, 0);
    const LdrImage cell = decodePng(readFileBytes(path("s.png"))), pair = decodePng(readFileBytes(path("c.png")));
    const LdrImage alone = decodePng(readFileBytes(path("r.png"))), plain = decodePng(readFileBytes(path("plain.png")));
    auto sameTopLeft = [&](const LdrImage& image) {   // the first panel's pixels, above any caption
        for (int y = 0; y < 20; ++y) {
            for (int x = 0; x < 40; ++x) {
                for (int c = 0; c < 3; ++c) {
                    if (image.rgba[size_t((y * image.width + x) * 4 + c)] != alone.rgba[size_t((y * 40 + x) * 4 + c)]) {
                        return false;
                    }
                }
            }
        }
        return true;
    };
    EXPECT_TRUE(sameTopLeft(cell));
    EXPECT_TRUE(sameTopLeft(pair));
    EXPECT_FALSE(sameTopLeft(plain));
}

}  // namespace
}  // namespace patina
