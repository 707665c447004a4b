// The environment's diffuse light, exact (issue 35, item 3): a matte grey cube and sphere
// (specular 0, roughness 1) under every high-contrast environment render within 1% of their
// ground truth in the mean and within 3% from the 5th to the 95th percentile of their pixels.
// Under the nine SH coefficients they did not (Blender's sunrise.exr: the sphere's diffuse light
// from 0.52 to 1.67 of the truth; docs/LIGHTING.md, "Diffuse").
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "accuracy/diffuse_accuracy.h"
#include "test_support.h"

namespace patina {
namespace {

constexpr const char* kBlenderWorlds = "/usr/share/blender/datafiles/studiolights/world/";

class MatteUnderEnvironment : public ::testing::TestWithParam<std::string> {
protected:
    // The built-in studio, a generated small sun 10^4 times its sky, or a Blender HDRI by name
    // (skipped where blender-data is not installed).
    std::shared_ptr<const Environment> environment() {
        const std::string& name = GetParam();
        if (name == "studio-builtin") {
            return test::madeEnvironment("builtin:studio");
        }
        if (name == "sun") {
            return prepareEnvironment(sunEnvironment(1024), "generated:sun");
        }
        const std::filesystem::path file = std::filesystem::path(kBlenderWorlds) / (name + ".exr");
        if (!std::filesystem::is_regular_file(file)) {
            return nullptr;
        }
        return test::madeEnvironment(file.string());
    }
};

TEST_P(MatteUnderEnvironment, IsWithinOnePercentInTheMeanAndThreeFromTheFifthToTheNinetyFifthPercentile) {
    test::glContext();
    const std::shared_ptr<const Environment> made = environment();
    if (!made) {
        GTEST_SKIP() << GetParam() << ".exr is not installed (blender-data)";
    }
    const NamedEnvironment named{GetParam(), made};
    for (MatteShape shape : {MatteShape::Cube, MatteShape::Sphere}) {
        MatteOptions options;
        options.size = 32;        // 316 pixels of the cube, 432 of the sphere
        options.samples = 128;    // the specular lobe's estimate; the diffuse lobe's truth is exact
        options.referenceRender = false;
        const MatteRow row = measureMatte(named, shape, options);
        const std::string where = GetParam() + " " + row.shape;
        // The truth's own noise is far below the bounds: a pixel's relative standard error, at
        // the median and at the 95th percentile of the pixels (measured: at most 0.33% and 0.8%).
        EXPECT_LT(row.truthMedianRelativeError, 0.005) << where;
        EXPECT_LT(row.truthP95RelativeError, 0.01) << where;
        // The diffuse light, what the irradiance decides: the renderer's own diffuse channel.
        EXPECT_NEAR(row.diffuseMeanRatio, 1.0, 0.01) << where;
        EXPECT_GE(row.diffuseP5, 0.97) << where;
        EXPECT_LE(row.diffuseP95, 1.03) << where;
        // The whole pixel. Not under sunrise.exr, where `epic`'s specular lobe, which F0 = 0 keeps
        // (Schlick's Fresnel at grazing), is off by the split sum's N = V at r = 1 in a sun
        // holding 61% of the light: the cube's mean 1.028 and the sphere's 95th percentile 1.11
        // with its diffuse light at 0.999 (docs/LIGHTING.md; the split sum is item 1's).
        if (GetParam() != "sunrise") {
            EXPECT_NEAR(row.meanRatio, 1.0, 0.01) << where;
            EXPECT_GE(row.p5, 0.97) << where;
            EXPECT_LE(row.p95, 1.03) << where;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Environments, MatteUnderEnvironment,
                         ::testing::Values("studio-builtin", "sun", "city", "courtyard", "forest", "interior", "night",
                                           "studio", "sunrise", "sunset"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

}  // namespace
}  // namespace patina
