// `patina slice` (BRDF Explorer's image slice, shading/brdf_slice.h): --lobe transmitted writes
// a thin wall's transmitted lobe (KHR_materials_transmission) as brdfSlice images it; an unknown
// lobe is a usage error.
#include <algorithm>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "files/file_bytes.h"
#include "image/image.h"
#include "scratch_test.h"
#include "shading/brdf_slice.h"

namespace patina {
namespace {

class CliSlice : public test::ScratchTest {
protected:
    test::CliRun run(const std::string& arguments) const { return test::runPatina(arguments, dir_); }
};

TEST_F(CliSlice, TransmittedWritesTheWallsLobeBelowTheSurface) {
    write("glass.json", R"({"format": "patina-material", "version": 1, "model": "gltf", "roughness": 0.3,
                            "baseColor": [0.9, 0.6, 0.3], "transmission": 0.8, "clearcoat": 1})");
    const test::CliRun r = run("slice --material " + path("glass.json").string() + " --lobe transmitted --size 16 --out " +
                               path("t.png").string() + " --hdr " + path("t.pfm").string());
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    const HdrImage image = decodePfm(readFileBytes(path("t.pfm")));
    MaterialParameters glass;
    glass.model = BrdfModelId::Gltf;
    glass.roughness = 0.3f;
    glass.baseColor = {0.9f, 0.6f, 0.3f};
    glass.transmission = 0.8f;
    glass.clearcoat = 1.0f;
    const BrdfSlice slice = brdfSlice(glass, 90.0f, 16, SliceLobe::Transmitted);
    ASSERT_EQ(image.rgb.size(), slice.values.size() * 3);
    float largest = 0.0f;
    for (size_t i = 0; i < slice.values.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_FLOAT_EQ(image.rgb[i * 3 + size_t(c)], slice.values[i][c]) << i;
            largest = std::max(largest, image.rgb[i * 3 + size_t(c)]);
        }
    }
    EXPECT_GT(largest, 1.0f) << "the wall's peak straight through";
    EXPECT_EQ(run("slice --lobe through --out " + path("x.png").string()).exitCode, 2);
}

}  // namespace
}  // namespace patina
