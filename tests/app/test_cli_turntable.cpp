// `patina turntable`: the frames of one whole turn of the camera about the scene's target, as
// numbered PNGs or one animated PNG; each frame is what `render` draws from that camera, and bad
// arguments are refused before anything is drawn (exit 2 for usage, 3 for bad input).
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "files/file_bytes.h"
#include "image/image.h"
#include "image/png_chunks.h"
#include "io/json_writer.h"
#include "io/scene_file.h"
#include "scene/camera_control.h"
#include "scratch_test.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

const std::string kSize = " --msaa 1 --width 40 --height 32 ";

class CliTurntable : public test::ScratchTest {
protected:
    test::CliRun run(const std::string& arguments) const { return test::runPatina(arguments, dir_); }

    // The PNG `render` draws of `scene` (written to a file) at the turntable tests' size.
    std::vector<uint8_t> rendered(const Scene& scene, const std::string& name) const {
        std::ofstream(path(name + ".json")) << prettyJson(sceneToJson(scene));
        const test::CliRun r = run("render" + kSize + "--scene " + path(name + ".json").string() + " --out " +
                                   path(name + ".png").string());
        EXPECT_EQ(r.exitCode, 0) << r.stderrText;
        return r.exitCode == 0 ? readFileBytes(path(name + ".png")) : std::vector<uint8_t>{};
    }
};

// Chunk types in order, and how many of each.
std::vector<std::string> chunkTypes(const std::vector<uint8_t>& png) {
    std::vector<std::string> types;
    for (size_t at = kPngSignature.size(); at + 12 <= png.size(); at += 12 + readBigEndian32(&png[at])) {
        types.emplace_back(png.begin() + std::ptrdiff_t(at + 4), png.begin() + std::ptrdiff_t(at + 8));
    }
    return types;
}

// Frame k is render's picture from the camera turned 360 k / N degrees about the target: frame 0
// render's own, frame 2 of 4 the default scene seen from behind. The frames differ from each
// other, and the frame after the last (360 degrees) is the first: the camera a whole turn on is
// the start bit for bit (test_camera_placement.cpp), so its picture is frame 0's.
TEST_F(CliTurntable, EachFrameIsRendersPictureFromTheCameraTurnedSoFar) {
    const test::CliRun r = run("turntable" + kSize + "--frames 4 --out " + path("turn").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(path("turn"))) {
        names.insert(entry.path().filename().string());
    }
    EXPECT_EQ(names, (std::set<std::string>{"frame_000.png", "frame_001.png", "frame_002.png", "frame_003.png"}));
    std::vector<std::vector<uint8_t>> frames;
    for (const std::string& name : names) {
        frames.push_back(readFileBytes(path("turn") / name));
    }
    for (size_t a = 0; a < frames.size(); ++a) {
        for (size_t b = a + 1; b < frames.size(); ++b) {
            EXPECT_NE(decodePng(frames[a]).rgba, decodePng(frames[b]).rgba) << "frames " << a << " and " << b;
        }
    }
    Scene scene = defaultScene();
    const Camera start = scene.camera;
    EXPECT_EQ(frames[0], rendered(scene, "start"));
    scene.camera = turntableCamera(start, 180.0f);
    EXPECT_EQ(frames[2], rendered(scene, "behind"));
    scene.camera = turntableCamera(start, 360.0f);
    EXPECT_EQ(frames[0], rendered(scene, "whole_turn"));
}

// --out F.png: one APNG, its frames the folder's, its default image (what a reader without APNG
// shows) the first.
TEST_F(CliTurntable, APngOutputIsOneAnimatedPngOfEveryFrame) {
    ASSERT_EQ(run("turntable" + kSize + "--frames 3 --out " + path("turn").string()).exitCode, 0);
    const test::CliRun r = run("turntable" + kSize + "--frames 3 --fps 12 --out " + path("turn.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    const std::vector<uint8_t> apng = readFileBytes(path("turn.png"));
    EXPECT_EQ(chunkTypes(apng), (std::vector<std::string>{"IHDR", "acTL", "fcTL", "IDAT", "fcTL", "fdAT", "fcTL",
                                                          "fdAT", "IEND"}));
    EXPECT_EQ(readBigEndian32(&apng[kPngSignature.size() + 25 + 8]), 3u);   // acTL's num_frames
    EXPECT_EQ(decodePng(apng).rgba, decodePng(readFileBytes(path("turn") / "frame_000.png")).rgba);
}

TEST_F(CliTurntable, BadArgumentsAreRefusedBeforeAnythingIsDrawn) {
    const std::string out = " --out " + path("turn").string();
    for (const std::string& frames : {"--frames 0", "--frames -3", "--frames 721", "--frames many", ""}) {
        const test::CliRun r = run("turntable " + frames + out);
        EXPECT_EQ(r.exitCode, 2) << frames << ": " << r.stderrText;
        EXPECT_NE(r.stderrText.find("--frames"), std::string::npos) << r.stderrText;
    }
    EXPECT_FALSE(fs::exists(path("turn")));
    write("file.txt", "not a folder");
    const struct {
        fs::path out;
        std::string message;
    } unwritable[] = {{path("file.txt"), "a file, not a folder"},
                      {path("file.txt") / "frames", "cannot make the folder"},
                      {path("missing") / "turn.png", "there is no folder"}};
    for (const auto& bad : unwritable) {
        const test::CliRun r = run("turntable --frames 2 --out " + bad.out.string());
        EXPECT_EQ(r.exitCode, 3) << bad.out << ": " << r.stderrText;
        EXPECT_NE(r.stderrText.find("--out " + bad.out.string() + ": " + bad.message), std::string::npos)
            << r.stderrText;
    }
    EXPECT_FALSE(fs::exists(path("missing")));
}

}  // namespace
}  // namespace patina
