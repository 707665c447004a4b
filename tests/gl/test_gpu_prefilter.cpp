// The prefiltered chain made on the GPU (the same prefilterEnvironment, read through the GPU's
// filter) against the CPU's: equal but for texture filtering's rounding.
#include <algorithm>
#include <chrono>
#include <cmath>

#include <gtest/gtest.h>

#include "environment/builtin_environments.h"
#include "environment/equirect.h"
#include "gl/gpu_prefilter.h"
#include "test_support.h"

namespace patina {
namespace {

TEST(GpuPrefilter, AgreesWithTheCpuTexelByTexel) {
    test::glContext();
    const HdrImage studio = *builtinEnvironment("studio");
    const CubeChain source = cubeMipChain(equirectToCube(studio, cubeFaceSizeFor(studio.width)));
    const PrefilterSettings settings;
    const auto t0 = std::chrono::steady_clock::now();
    const CubeChain cpu = prefilterCube(source, settings);
    const auto t1 = std::chrono::steady_clock::now();
    const CubeChain gpu = prefilterCubeOnGpu(source, settings);
    const auto t2 = std::chrono::steady_clock::now();
    std::printf("prefilter of a %d face: cpu %.3f s, gpu %.3f s\n", source.front().size,
                std::chrono::duration<double>(t1 - t0).count(), std::chrono::duration<double>(t2 - t1).count());
    ASSERT_EQ(gpu.size(), cpu.size());
    EXPECT_EQ(gpu.front().faces, cpu.front().faces);   // mip 0 is the source itself
    double worst = 0.0, sum = 0.0;
    size_t count = 0;
    for (size_t level = 1; level < cpu.size(); ++level) {
        ASSERT_EQ(gpu[level].size, cpu[level].size);
        for (int face = 0; face < 6; ++face) {
            const std::vector<float>& a = gpu[level].faces[size_t(face)];
            const std::vector<float>& b = cpu[level].faces[size_t(face)];
            for (size_t i = 0; i < a.size(); ++i) {
                const double d = std::abs(double(a[i]) - double(b[i])) / std::max(double(b[i]), 1e-2);
                worst = std::max(worst, d);
                sum += d;
                ++count;
            }
        }
    }
    EXPECT_LT(sum / double(count), 1e-3);
    EXPECT_LT(worst, 2e-2);
    // A stop says so with an empty chain.
    EXPECT_TRUE(prefilterCubeOnGpu(source, settings, [](float) { return false; }).empty());
}

}  // namespace
}  // namespace patina
