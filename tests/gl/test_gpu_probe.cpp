// shaders/stages/shade.frag on the GPU (Mesa llvmpipe here) against the double reference and against
// the same code compiled as C++.
#include <cmath>

#include <gtest/gtest.h>

#include "accuracy/edge_cases.h"
#include "gl/gpu_probe.h"
#include "test_support.h"

namespace patina {
namespace {

struct ProbeBatch {
    Material material;
    std::vector<Light> lights;
    std::vector<ProbeSample> samples;
};

// Random probes in the well-defined region: r in [0.05, 1], NoV and NoL >= 0.01 for the
// directional light, a point light and a hemisphere light on top.
std::vector<ProbeBatch> randomBatches(int batches, int perBatch, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<ProbeBatch> result;
    for (int b = 0; b < batches; ++b) {
        ProbeBatch batch;
        batch.material = {{{unit(rng), unit(rng), unit(rng)}, 0.05f + 0.95f * unit(rng), unit(rng), unit(rng)},
                          "random"};
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = test::randomUnitVector(rng);
        sun.color = {unit(rng), unit(rng), unit(rng)};
        sun.intensity = 3.0f;
        Light lamp;
        lamp.type = LightType::Point;
        lamp.position = 3.0f * test::randomUnitVector(rng);
        lamp.range = 6.0f;
        lamp.attenuation = {1.0f, 0.1f, 1.0f};
        lamp.intensity = 8.0f;
        Light sky;
        sky.type = LightType::Hemisphere;
        sky.sky = {0.3f, 0.4f, 0.5f};
        sky.ground = {0.1f, 0.1f, 0.05f};
        batch.lights = {sun, lamp, sky};
        const glm::vec3 L = -glm::normalize(sun.direction);
        for (int i = 0; i < perBatch; ++i) {
            const glm::vec3 N = test::vectorAtCosine(L, 0.01f + 0.99f * unit(rng), rng);
            const glm::vec3 V = test::vectorAtCosine(N, 0.01f + 0.99f * unit(rng), rng);
            batch.samples.push_back({test::randomUnitVector(rng), N, V});
        }
        result.push_back(batch);
    }
    return result;
}

// The largest relative difference of the GPU from the CPU on a batch, where the CPU's value
// is above 1e-4.
double gpuAgainstCpu(GpuProbe& probe, const ProbeBatch& batch) {
    const std::vector<glm::vec3> gpu = probe.evaluate(batch.material, batch.lights, batch.samples);
    const std::vector<glm::vec3> cpu = probeOnCpu(batch.material, batch.lights, batch.samples);
    EXPECT_EQ(gpu.size(), cpu.size());
    std::vector<reference::Vec3> cpuAsReference;
    for (const glm::vec3& c : cpu) {
        cpuAsReference.push_back(test::toReference(c));
    }
    return test::maxRelativeError(gpu, cpuAsReference, 1e-4);
}

TEST(GpuProbe, MatchesTheDoubleReferenceOnTenThousandProbes) {
    test::glContext();
    GpuProbe probe;
    double worst = 0.0;
    size_t count = 0;
    for (const ProbeBatch& batch : randomBatches(40, 256, 2024)) {
        const std::vector<glm::vec3> gpu = probe.evaluate(batch.material, batch.lights, batch.samples);
        std::vector<reference::Vec3> expected;
        for (const ProbeSample& s : batch.samples) {
            expected.push_back(reference::shadeAll(test::toReference(batch.material),
                                                   test::toReference(batch.lights),
                                                   test::toReference(s.position),
                                                   test::toReference(s.normal),
                                                   test::toReference(s.toViewer)));
        }
        worst = std::max(worst, test::maxRelativeError(gpu, expected, 1e-3));
        count += gpu.size();
    }
    EXPECT_GE(count, 10000u);
    EXPECT_LE(worst, 1e-4);
    RecordProperty("max_relative_error", std::to_string(worst));
}

TEST(GpuProbe, AgreesWithTheSameCodeOnTheCpu) {
    test::glContext();
    GpuProbe probe;
    for (const ProbeBatch& batch : randomBatches(4, 512, 99)) {
        EXPECT_LE(gpuAgainstCpu(probe, batch), 1e-5);
    }
}

TEST(GpuProbe, EdgeSweepIsFiniteAndNonNegative) {
    test::glContext();
    GpuProbe probe;
    std::vector<EdgeCase> edges = edgeCases();
    for (const EdgeCase& edge : areaLightEdgeCases()) {
        edges.push_back(edge);
    }
    for (const EdgeCase& edge : edges) {
        for (const glm::vec3& v : probe.evaluate(edge.material, edge.lights, edge.samples)) {
            for (int c = 0; c < 3; ++c) {
                EXPECT_TRUE(std::isfinite(v[c]) && v[c] >= 0.0f) << edge.name << ": " << v[c];
            }
        }
    }
}

// Sphere and tube lights, next to the other types: the GPU runs the same code as the CPU, to
// 1e-4, over the well-defined region and lights above, across and below the horizon.
TEST(GpuProbe, AreaLightsAgreeWithTheSameCodeOnTheCpu) {
    test::glContext();
    GpuProbe probe;
    std::mt19937 rng(321);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const ProbeBatch& base : randomBatches(6, 512, 77)) {
        ProbeBatch batch = base;
        Light sphere;
        sphere.type = LightType::Sphere;
        sphere.position = 1.5f * test::randomUnitVector(rng);
        sphere.sourceRadius = 0.05f + 0.8f * unit(rng);
        sphere.range = 8.0f;
        sphere.intensity = 6.0f;
        sphere.color = {unit(rng), unit(rng), unit(rng)};
        Light tube = sphere;
        tube.type = LightType::Tube;
        tube.start = 1.5f * test::randomUnitVector(rng);
        tube.end = tube.start + 2.0f * test::randomUnitVector(rng);
        tube.sourceRadius = 0.02f + 0.3f * unit(rng);
        tube.attenuation = {0.0f, 0.2f, 1.0f};
        batch.lights.push_back(sphere);
        batch.lights.push_back(tube);
        EXPECT_LE(gpuAgainstCpu(probe, batch), 1e-4);
    }
}

TEST(GpuProbe, KeepsRowOrderAcrossTargetRows) {
    // 3000 rows span three rows of the 1024-wide target; each row is distinct by position,
    // so a wrong pixel mapping shows against the CPU row by row.
    test::glContext();
    GpuProbe probe;
    Light lamp;
    lamp.position = {0.0f, 0.0f, 4.0f};
    lamp.attenuation = {0.0f, 0.0f, 1.0f};
    std::vector<ProbeSample> samples;
    for (int i = 0; i < 3000; ++i) {
        samples.push_back({{0.0f, 0.0f, float(i) * 1e-3f}, {0, 0, 1}, {0, 0, 1}});
    }
    const std::vector<glm::vec3> gpu = probe.evaluate(Material{}, {lamp}, samples);
    const std::vector<glm::vec3> cpu = probeOnCpu(Material{}, {lamp}, samples);
    for (size_t i = 0; i < samples.size(); i += 97) {
        EXPECT_NEAR(gpu[i].r, cpu[i].r, 1e-5f * cpu[i].r) << "row " << i;
    }
}

}  // namespace
}  // namespace patina
