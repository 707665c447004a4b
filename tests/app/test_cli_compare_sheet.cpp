// `patina compare` and `patina sheet` end to end: image sizes, captions, one cell per material,
// and bad input refused with exit code 3 and no output file.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "picture/compositing.h"
#include "image/image.h"
#include "scratch_test.h"
#include "files/file_bytes.h"
#include "io/json_writer.h"
#include "io/scene_file.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

const char* kRed = R"({"format": "patina-material", "version": 1, "name": "red",
                       "baseColor": [0.9, 0.03, 0.03], "roughness": 0.5})";
const char* kBlue = R"({"format": "patina-material", "version": 1, "name": "blue",
                        "baseColor": [0.03, 0.03, 0.9], "roughness": 0.5})";

struct Rgb {
    int r, g, b;
};

Rgb at(const LdrImage& image, int x, int y) {
    const uint8_t* p = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
    return {p[0], p[1], p[2]};
}

bool isColour(Rgb pixel, Rgb8 colour) {
    return pixel.r == colour.r && pixel.g == colour.g && pixel.b == colour.b;
}

// Pixels in [x0, x1) x [y0, y1) that are not the sheet background.
int inkIn(const LdrImage& image, int x0, int y0, int x1, int y1) {
    int ink = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            ink += !isColour(at(image, x, y), kSheetBackground);
        }
    }
    return ink;
}

class CompareAndSheet : public test::ScratchTest {
protected:
    void SetUp() override {
        ScratchTest::SetUp();
        write("red.json", kRed);
        write("blue.json", kBlue);
    }

    std::string path(const std::string& name) const { return ScratchTest::path(name).string(); }

    // The exit code; stderr in errors_.
    int run(const std::string& arguments) {
        const test::CliRun result = test::runPatina(arguments, dir_);
        errors_ = result.stderrText;
        return result.exitCode;
    }

    LdrImage image(const std::string& name) const { return decodePng(readFileBytes(path(name))); }

    std::string errors_;
};

TEST_F(CompareAndSheet, CompareShowsBothMaterialsCaptioned) {
    ASSERT_EQ(run("compare " + path("red.json") + " " + path("blue.json") +
                  " --width 96 --height 64 --out " + path("c.png")), 0) << errors_;
    const LdrImage out = image("c.png");
    const SheetLayout layout = sheetLayout(96, 64, 2, 2);
    ASSERT_EQ(out.width, layout.width);
    ASSERT_EQ(out.height, layout.height);
    EXPECT_EQ(out.height, 64 + captionHeight(1));
    const Rgb left = at(out, layout.cellX(0) + 48, 32), right = at(out, layout.cellX(1) + 48, 32);
    EXPECT_GT(left.r, left.b + 40);
    EXPECT_GT(right.b, right.r + 40);
    // 96 pixels hold the name alone ("red", "blue"): the numbers give way to it.
    for (int i = 0; i < 2; ++i) {
        EXPECT_GT(inkIn(out, layout.cellX(i), 64, layout.cellX(i) + 96, out.height), 20) << i;
    }
}

TEST_F(CompareAndSheet, CompareDiffAddsAHeatMapThatIsBlackWhereEqual) {
    ASSERT_EQ(run("compare " + path("red.json") + " " + path("blue.json") +
                  " --width 80 --height 80 --diff --out " + path("d.png")), 0) << errors_;
    const LdrImage out = image("d.png");
    const SheetLayout layout = sheetLayout(80, 80, 3, 3);
    ASSERT_EQ(out.width, layout.width);
    ASSERT_EQ(out.height, layout.height);
    const int x = layout.cellX(2);
    EXPECT_FALSE(isColour(at(out, x + 40, 40), {0, 0, 0}));   // the sphere differs
    EXPECT_TRUE(isColour(at(out, x + 1, 1), {0, 0, 0}));      // the background does not
    EXPECT_GT(inkIn(out, x, 80, x + 80, out.height), 50);

    ASSERT_EQ(run("compare " + path("red.json") + " " + path("red.json") +
                  " --width 80 --height 80 --diff --out " + path("same.png")), 0) << errors_;
    const LdrImage same = image("same.png");
    for (int y = 0; y < 80; ++y) {
        for (int i = 0; i < 80; ++i) {
            ASSERT_TRUE(isColour(at(same, x + i, y), {0, 0, 0})) << i << "," << y;
        }
    }
}

TEST_F(CompareAndSheet, CompareUsesTheGivenScene) {
    write("green.json", R"({"format": "patina-scene", "version": 1,
                            "display": {"background": [0, 1, 0]}})");
    ASSERT_EQ(run("compare " + path("red.json") + " " + path("blue.json") + " --scene " +
                  path("green.json") + " --width 40 --height 40 --out " + path("g.png")), 0)
        << errors_;
    const Rgb corner = at(image("g.png"), 1, 1);
    EXPECT_EQ(corner.g, 255);
    EXPECT_EQ(corner.r, 0);
}

// Over a model each material goes on every part, keeping the part's maps (BoxTextured's
// logo multiplies it), or on --part's alone; a part the model lacks is refused by name.
TEST_F(CompareAndSheet, OnAModelTheMaterialsGoOnItsPartsWithTheirMaps) {
    const fs::path box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!fs::exists(box)) {
        GTEST_SKIP() << "needs Debian's assimp-testmodels";
    }
    Scene scene = defaultScene();   // lit: a scene file without lights is unlit
    scene.meshFile = box.string();
    write("box.json", prettyJson(sceneToJson(scene)));
    const std::string pair = "compare " + path("red.json") + " " + path("blue.json") + " --scene " + path("box.json");
    ASSERT_EQ(run(pair + " --width 64 --height 64 --out " + path("box.png")), 0) << errors_;
    const LdrImage out = image("box.png");
    const SheetLayout layout = sheetLayout(64, 64, 2, 2);
    const Rgb left = at(out, layout.cellX(0) + 32, 32), right = at(out, layout.cellX(1) + 32, 32);
    EXPECT_GT(left.r, left.b + 20);
    EXPECT_GT(right.b, right.r + 20);
    ASSERT_EQ(run(pair + " --part Texture --width 64 --height 64 --out " + path("part.png")), 0) << errors_;
    EXPECT_EQ(image("part.png").rgba, out.rgba);   // the box's one part is every part

    EXPECT_EQ(run(pair + " --part Wood --out " + path("wood.png")), 3);
    EXPECT_NE(errors_.find("\"Texture\""), std::string::npos) << errors_;
    EXPECT_EQ(run("sheet " + path("red.json") + " --part Texture --out " + path("sphere.png")), 3);
    EXPECT_NE(errors_.find("built-in"), std::string::npos) << errors_;
    EXPECT_FALSE(fs::exists(path("wood.png")));
    EXPECT_FALSE(fs::exists(path("sphere.png")));

    // render --material does the same to the scene's model.
    ASSERT_EQ(run("render --scene " + path("box.json") + " --width 64 --height 64 --out " + path("own.png")), 0);
    ASSERT_EQ(run("render --scene " + path("box.json") + " --material " + path("red.json") +
                  " --width 64 --height 64 --out " + path("red.png")),
              0);
    const Rgb own = at(image("own.png"), 32, 32), red = at(image("red.png"), 32, 32);
    EXPECT_GT(red.r, red.b + 20);
    EXPECT_FALSE(own.r > own.b + 20) << "the box's own material is not red, so the check above can fail";
}

TEST_F(CompareAndSheet, SheetHasOneCaptionedCellPerMaterial) {
    ASSERT_EQ(run("sheet " + path("red.json") + " " + path("blue.json") + " " + path("red.json") +
                  " --columns 2 --size 48 --out " + path("s.png")), 0) << errors_;
    const LdrImage out = image("s.png");
    const SheetLayout layout = sheetLayout(48, 48, 3, 2);
    ASSERT_EQ(out.width, 2 * 48 + kCellGap);
    ASSERT_EQ(out.height, layout.height);
    for (int i = 0; i < 3; ++i) {
        const Rgb centre = at(out, layout.cellX(i) + 24, layout.cellY(i) + 24);
        if (i == 1) {
            EXPECT_GT(centre.b, centre.r + 40);
        } else {
            EXPECT_GT(centre.r, centre.b + 40) << i;
        }
        const int strip = layout.cellY(i) + 48;
        EXPECT_GT(inkIn(out, layout.cellX(i), strip, layout.cellX(i) + 48, strip + layout.captionHeight), 20) << i;
    }
    // The fourth place of the grid stays empty.
    EXPECT_EQ(inkIn(out, layout.cellX(3), layout.cellY(3), out.width, out.height), 0);
}

TEST_F(CompareAndSheet, BadMaterialsExitThreeAndWriteNothing) {
    write("bad.json", R"({"format": "patina-material", "version": 1, "metallic": 2})");
    EXPECT_EQ(run("compare " + path("red.json") + " " + path("bad.json") + " --out " + path("x.png")), 3);
    EXPECT_NE(errors_.find("bad.json: /metallic: value 2 is outside [0, 1]"), std::string::npos) << errors_;
    EXPECT_EQ(run("compare " + path("missing.json") + " " + path("red.json") + " --out " + path("x.png")), 3);
    EXPECT_NE(errors_.find("missing.json"), std::string::npos) << errors_;
    EXPECT_EQ(run("sheet " + path("red.json") + " " + path("bad.json") + " --out " + path("x.png")), 3);
    EXPECT_EQ(run("sheet " + path("red.json") + " --scene " + path("missing.json") + " --out " +
                  path("x.png")), 3);
    EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(CompareAndSheet, OversizedSheetsAreRefusedBeforeRendering) {
    EXPECT_EQ(run("sheet " + path("red.json") + " " + path("blue.json") + " " + path("red.json") +
                  " " + path("blue.json") + " " + path("red.json") +
                  " --size 4096 --columns 5 --out " + path("x.png")), 3);
    EXPECT_NE(errors_.find("the sheet is too large"), std::string::npos) << errors_;
    EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(CompareAndSheet, UsageErrorsExitTwo) {
    EXPECT_EQ(run("compare " + path("red.json") + " --out " + path("x.png")), 2);   // one material
    EXPECT_EQ(run("compare " + path("red.json") + " " + path("blue.json")), 2);     // no --out
    EXPECT_EQ(run("sheet --out " + path("x.png")), 2);                              // no material
    EXPECT_EQ(run("sheet " + path("red.json") + " --columns 0 --out " + path("x.png")), 2);
    EXPECT_EQ(run("compare --help"), 0);
    EXPECT_EQ(run("sheet --help"), 0);
    EXPECT_FALSE(fs::exists(path("x.png")));
}

}  // namespace
}  // namespace patina
