// Linear images from different renderers compared as displayed (image/linear_difference.h,
// `patina difference`): the box shrink, the coverage mask and its erosion, and the mean |sRGB
// difference| after one exposure and tone curve, checked against values worked out here from the
// published formulas (IEC 61966-2-1's sRGB, Khronos PBR Neutral below its compression).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "files/file_bytes.h"
#include "picture/compositing.h"
#include "image/image.h"
#include "picture/linear_difference.h"
#include "scratch_test.h"

namespace patina {
namespace {

HdrImage grey(int width, int height, float value) {
    return {width, height, std::vector<float>(size_t(width) * size_t(height) * 3, value)};
}

void setPixel(HdrImage& image, int x, int y, float r, float g, float b) {
    float* rgb = &image.rgb[(size_t(y) * size_t(image.width) + size_t(x)) * 3];
    rgb[0] = r, rgb[1] = g, rgb[2] = b;
}

// IEC 61966-2-1, in levels of 255.
double srgbLevels(double linear) {
    return 255.0 * (linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055);
}

TEST(LinearDifference, DownsampleBoxTakesEachBlocksMean) {
    HdrImage image = grey(4, 2, 0.0f);
    setPixel(image, 0, 0, 1.0f, 2.0f, 4.0f);
    setPixel(image, 1, 1, 3.0f, 2.0f, 0.0f);
    setPixel(image, 3, 0, 8.0f, 0.0f, 0.0f);
    const HdrImage small = downsampleBox(image, 2);
    ASSERT_EQ(small.width, 2);
    ASSERT_EQ(small.height, 1);
    EXPECT_FLOAT_EQ(small.rgb[0], 1.0f);   // (1 + 3) / 4
    EXPECT_FLOAT_EQ(small.rgb[1], 1.0f);   // (2 + 2) / 4
    EXPECT_FLOAT_EQ(small.rgb[2], 1.0f);   // 4 / 4
    EXPECT_FLOAT_EQ(small.rgb[3], 2.0f);   // 8 / 4
    EXPECT_EQ(downsampleBox(image, 1), image);
    EXPECT_THROW(downsampleBox(image, 3), std::invalid_argument);   // 4 x 2 is no multiple of 3
    EXPECT_THROW(downsampleBox(image, 0), std::invalid_argument);
}

TEST(LinearDifference, CoverageMaskKeepsFullyCoveredPixelsAwayFromTheEdge) {
    // A covered 4 x 4 square at (1, 1) in a 6 x 6 channel image; one covered pixel has a zero
    // red and green but not blue, which is still covered (a normal along +Z).
    HdrImage coverage = grey(6, 6, 0.0f);
    for (int y = 1; y <= 4; ++y) {
        for (int x = 1; x <= 4; ++x) {
            setPixel(coverage, x, y, 0.3f, -0.5f, 0.8f);
        }
    }
    setPixel(coverage, 2, 2, 0.0f, 0.0f, 1.0f);
    auto count = [](const std::vector<uint8_t>& mask) { return std::count(mask.begin(), mask.end(), uint8_t(1)); };
    const std::vector<uint8_t> whole = coverageMask(coverage, 1, 0);
    EXPECT_EQ(count(whole), 16);
    EXPECT_EQ(whole[2 * 6 + 2], 1);
    const std::vector<uint8_t> eroded = coverageMask(coverage, 1, 1);
    EXPECT_EQ(count(eroded), 4);   // the 2 x 2 inside
    EXPECT_EQ(eroded[2 * 6 + 2], 1);
    EXPECT_EQ(eroded[1 * 6 + 1], 0);
    // Halved: only the block (1, 1) of pixels 2..3 is wholly covered; eroded, nothing is.
    const std::vector<uint8_t> halved = coverageMask(coverage, 2, 0);
    ASSERT_EQ(halved.size(), 9u);
    EXPECT_EQ(count(halved), 1);
    EXPECT_EQ(halved[1 * 3 + 1], 1);
    EXPECT_EQ(count(coverageMask(coverage, 2, 1)), 0);
    // What the frame cuts is an edge too.
    EXPECT_EQ(count(coverageMask(grey(3, 3, 1.0f), 1, 1)), 1);
    EXPECT_THROW(coverageMask(coverage, 1, -1), std::invalid_argument);
    EXPECT_THROW(coverageMask(coverage, 4, 0), std::invalid_argument);
}

TEST(LinearDifference, MeanIsOverTheMaskedPixelsAndChannelsAsDisplayed) {
    // a: linear 0.18 grey; b: 0.5 grey, but for one pixel the mask leaves out, which differs wildly.
    HdrImage a = grey(3, 1, 0.18f), b = grey(3, 1, 0.5f);
    setPixel(b, 2, 0, 100.0f, 0.0f, 0.0f);
    const std::vector<uint8_t> mask{1, 1, 0};
    DisplaySettings display;   // exposure 0, no tone map: sRGB alone
    MaskedDifference difference = maskedDifference(a, b, mask, display);
    const double plain = srgbLevels(0.5) - srgbLevels(0.18);   // 188.0 - 117.9
    EXPECT_EQ(difference.pixels, 2u);
    EXPECT_NEAR(difference.meanAbsolute, plain, 1e-3);
    EXPECT_NEAR(difference.meanSigned, plain, 1e-3);
    EXPECT_NEAR(maskedDifference(b, a, mask, display).meanSigned, -plain, 1e-3);   // a is the darker

    // One stop down on both: 0.09 against 0.25.
    display.exposure = -1.0f;
    EXPECT_NEAR(maskedDifference(a, b, mask, display).meanAbsolute, srgbLevels(0.25) - srgbLevels(0.09), 1e-3);

    // PBR Neutral below its compression: x - 0.04 where the smallest channel is 0.08 or more,
    // x - 6.25 x^2 below it (Khronos 3D Commerce 2024).
    display.exposure = 0.0f;
    display.tonemap = Tonemap::PbrNeutral;
    const double neutral = srgbLevels(0.5 - 0.04) - srgbLevels(0.18 - 0.04);
    EXPECT_NEAR(maskedDifference(a, b, mask, display).meanAbsolute, neutral, 1e-3);

    // A difference of one colour channel counts a third: the mean is over R, G and B.
    HdrImage c = a;
    setPixel(c, 0, 0, 0.5f, 0.18f, 0.18f);
    display.tonemap = Tonemap::None;
    EXPECT_NEAR(maskedDifference(a, c, mask, display).meanAbsolute, plain / 6.0, 1e-3);

    EXPECT_EQ(maskedDifference(a, b, {0, 0, 0}, display).pixels, 0u);
    EXPECT_THROW(maskedDifference(a, grey(2, 1, 0.5f), {1, 1}, display), std::invalid_argument);
    EXPECT_THROW(maskedDifference(a, b, {1, 1}, display), std::invalid_argument);
}

TEST(LinearDifference, HeatMapGreysWhatTheMaskLeavesOut) {
    const HdrImage a = grey(2, 1, 0.18f), b = grey(2, 1, 0.5f);
    const LdrImage map = maskedHeatMap(a, b, {1, 0}, DisplaySettings{}, 1.0f);
    ASSERT_EQ(map.rgba.size(), 8u);
    const Rgb8 hot = heatColour(int(std::lround(srgbLevels(0.5) - srgbLevels(0.18))));
    EXPECT_EQ(map.rgba[0], hot.r);
    EXPECT_EQ(map.rgba[1], hot.g);
    EXPECT_EQ(map.rgba[2], hot.b);
    EXPECT_EQ(map.rgba[4], 96);
    EXPECT_EQ(map.rgba[5], 96);
    EXPECT_EQ(map.rgba[6], 96);
    const LdrImage same = maskedHeatMap(a, a, {1, 0}, DisplaySettings{}, 4.0f);
    EXPECT_EQ(same.rgba[0], 0);   // equal: black
}

class DifferenceCommand : public test::ScratchTest {};

TEST_F(DifferenceCommand, PrintsTheComparisonCsvAndASheet) {
    // 4 x 4 images shrunk by 2: a coverage of the left half leaves the left column of 2 x 2.
    HdrImage coverage = grey(4, 4, 0.0f), a = grey(4, 4, 0.18f), b = grey(4, 4, 0.18f);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 2; ++x) {
            setPixel(coverage, x, y, 0.0f, 1.0f, 0.0f);
            setPixel(b, x, y, 0.5f, 0.5f, 0.5f);
        }
    }
    writeFileAtomic(path("coverage.pfm"), encodePfm(coverage));
    writeFileAtomic(path("a.pfm"), encodePfm(a));
    writeFileAtomic(path("b.pfm"), encodePfm(b));
    const std::string files = path("a.pfm").string() + " " + path("b.pfm").string() + " " + path("a.pfm").string();
    test::CliRun run = test::runPatina("difference " + files + " --names truth lighter same --coverage " +
                                           path("coverage.pfm").string() + " --downsample 2 --erode 0 --scene box" +
                                           " --sheet " + path("sheet.png").string(),
                                       dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    char expected[160];
    std::snprintf(expected, sizeof expected,
                  "scene,image,against,mean_abs_srgb,mean_signed_srgb,pixels\nbox,lighter,truth,%.3f,%.3f,2\n"
                  "box,same,truth,0.000,0.000,2\n",
                  srgbLevels(0.5) - srgbLevels(0.18), srgbLevels(0.5) - srgbLevels(0.18));
    EXPECT_EQ(run.stdoutText, expected);
    const LdrImage sheet = decodePng(readFileBytes(path("sheet.png")));
    EXPECT_GT(sheet.width, 3 * 2);   // three cells a row, captioned

    // Bad input: a tone map, a name count, a CSV-breaking name, sizes that differ.
    EXPECT_EQ(test::runPatina("difference " + files + " --tonemap filmic", dir_).exitCode, 3);
    EXPECT_EQ(test::runPatina("difference " + files + " --names one two", dir_).exitCode, 3);
    EXPECT_EQ(test::runPatina("difference " + files + " --scene a,b", dir_).exitCode, 3);
    EXPECT_EQ(test::runPatina("difference " + files + " --downsample 3", dir_).exitCode, 3);
    writeFileAtomic(path("small.pfm"), encodePfm(grey(2, 2, 0.1f)));
    run = test::runPatina("difference " + path("a.pfm").string() + " " + path("small.pfm").string(), dir_);
    EXPECT_EQ(run.exitCode, 3);
    EXPECT_NE(run.stderrText.find("cannot compare a 4x4 image with a 2x2 one"), std::string::npos) << run.stderrText;
    EXPECT_EQ(test::runPatina("difference " + path("a.pfm").string() + " " + path("none.pfm").string(), dir_).exitCode,
              3);
}

}  // namespace
}  // namespace patina
