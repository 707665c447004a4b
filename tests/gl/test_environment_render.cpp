// The environment on the GPU: the split sum in the shader against the same code on the CPU,
// the three render paths, the background, rotation, and a metal that looks like metal.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "environment/environment.h"
#include "gl/gpu_probe.h"
#include "reference/pixel_surfaces.h"
#include "shading/cpu_shading.h"
#include "test_support.h"

namespace patina {
namespace {

Light studio(float rotation = 0.0f) {
    Light light;
    light.type = LightType::Environment;
    light.source = "builtin:studio";
    light.rotationDegrees = rotation;
    return light;
}

std::vector<ProbeSample> randomProbes(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::vector<ProbeSample> samples;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 N = test::randomUnitVector(rng);
        glm::vec3 V = test::randomUnitVector(rng);
        if (glm::dot(N, V) < 0.05f) {
            V = glm::normalize(V + N * (0.05f - glm::dot(N, V) + 0.2f));
        }
        samples.push_back({glm::vec3(0.0f), N, V});
    }
    return samples;
}

TEST(EnvironmentRender, TheGpuSplitSumAgreesWithTheCpu) {
    // The same shared code; the GPU's trilinear, seamless cube-map filter is the only difference
    // allowed (issue 18: 1e-3 relative).
    test::glContext();
    GpuProbe probe;
    double worst = 0.0;
    for (float roughness : {0.0f, 0.15f, 0.4f, 0.8f, 1.0f}) {
        for (float metallic : {0.0f, 1.0f}) {
            Material material;
            material.baseColor = {0.9f, 0.5f, 0.2f};
            material.roughness = roughness;
            material.metallic = metallic;
            for (float rotation : {0.0f, 33.0f}) {
                const std::vector<Light> lights{studio(rotation)};
                const std::vector<ProbeSample> samples = randomProbes(256, 7);
                const auto environment = test::madeEnvironment(lights[0].source);
                const std::vector<glm::vec3> gpu = probe.evaluate(material, lights, samples, environment);
                const std::vector<glm::vec3> cpu = probeOnCpu(material, lights, samples, environment);
                std::vector<reference::Vec3> expected;
                for (const glm::vec3& c : cpu) {
                    expected.push_back(test::toReference(c));
                }
                worst = std::max(worst, test::maxRelativeError(gpu, expected, 1e-2));
            }
        }
    }
    RecordProperty("max_relative_error", std::to_string(worst));
    // Measured: 4e-6 with the irradiance map (2e-6 with SH; the CPU filter reproduces Mesa's seamless
    // corners); the issue asks 1e-3.
    EXPECT_LE(worst, 1e-4);
}

Scene environmentScene(RenderPath) {
    Scene scene;
    scene.material.baseColor = {0.95f, 0.64f, 0.54f};
    scene.material.metallic = 1.0f;
    scene.material.roughness = 0.3f;
    Light key;
    key.position = {1.0f, 2.0f, 2.0f};
    key.intensity = 4.0f;
    scene.lights = {key, studio(20.0f)};
    return scene;
}

double maxDifference(const HdrImage& a, const HdrImage& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        worst = std::max(worst, double(std::abs(a.rgb[i] - b.rgb[i])) / std::max(1.0, double(std::abs(b.rgb[i]))));
    }
    return worst;
}

TEST(EnvironmentRender, TheThreePathsAgree) {
    test::glContext();
    Renderer renderer;
    for (bool background : {false, true}) {
        Scene scene = environmentScene(RenderPath::Single);
        scene.display.backgroundFromEnvironment = background;
        scene.display.backgroundBlur = 0.2f;
        const HdrImage single = renderer.render(test::prepared(scene), test::renderSettings(96, 96, RenderPath::Single, 1)).hdr;
        const HdrImage multi = renderer.render(test::prepared(scene), test::renderSettings(96, 96, RenderPath::Multi, 1)).hdr;
        const HdrImage specialised =
            renderer.render(test::prepared(scene), test::renderSettings(96, 96, RenderPath::Specialised, 1)).hdr;
        EXPECT_LE(maxDifference(multi, single), 1e-5) << background;
        EXPECT_LE(maxDifference(specialised, single), 1e-5) << background;
        // And with MSAA, whose resolve must count the background as drawn.
        // (Only on average: MSAA changes the silhouette's pixels.)
        const HdrImage msaa = renderer.render(test::prepared(scene), test::renderSettings(96, 96, RenderPath::Single, 4)).hdr;
        double sum = 0.0;
        for (size_t i = 0; i < msaa.rgb.size(); ++i) {
            sum += std::abs(msaa.rgb[i] - single.rgb[i]);
        }
        EXPECT_LE(sum / double(msaa.rgb.size()), 0.02) << background;
    }
}

// Each pixel the mesh covers, rendered with `shading`, against the same shared code on the CPU
// at the surface the CPU rasteriser finds there; the fraction of values within `tolerance`
// (relative, over a floor) and the median relative difference.
std::pair<double, double> gpuAgainstCpu(const EnvironmentShading& shading, float roughness, float tolerance) {
    test::glContext();
    Scene scene;
    scene.material.baseColor = {0.95f, 0.64f, 0.54f};
    scene.material.metallic = 1.0f;
    scene.material.roughness = roughness;
    scene.lights = {studio(33.0f)};
    const int size = 64;
    RenderSettings settings = test::renderSettings(size, size, RenderPath::Single, 1);
    settings.environment = shading;
    Renderer renderer;
    const PreparedScene prepared = test::prepared(scene);
    const HdrImage image = renderer.render(prepared, settings).hdr;
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, size, size);
    const std::shared_ptr<const Environment> environment = prepared.environment;
    const CubeChain source = sourceMipChain(*environment);
    const shader::SurfaceMaterial material = surfaceMaterial(scene.material);
    std::vector<double> differences;
    int within = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const int32_t i = surfaces.sampleOfPixel[size_t(y * size + x)];
            if (i < 0) {
                continue;
            }
            const ProbeSample& p = surfaces.samples[size_t(i)];
            const glm::vec3 N = shader::safeNormalize(p.normal), V = p.toViewer;
            // gl_FragCoord counts rows from the bottom.
            const glm::vec3 cpu =
                shading.method == EnvironmentMethod::Stochastic
                    ? stochasticEnvironmentOnCpu(BrdfModelId::Epic, material, *environment, source, 1.0f, 33.0f, N, V,
                                                 unsigned(shading.samples),
                                                 shader::pixelJitter(unsigned(x), unsigned(size - 1 - y)))
                    : shadeEnvironmentOnCpu(BrdfModelId::Epic, material, *environment, 1.0f, 33.0f, N, V,
                                            shading.method == EnvironmentMethod::Dominant);
            const float* gpu = &image.rgb[size_t(y * size + x) * 3];
            for (int c = 0; c < 3; ++c) {
                const double d = std::abs(double(gpu[c]) - cpu[c]) / std::max(double(cpu[c]), 0.02);
                differences.push_back(d);
                within += d <= tolerance;
            }
        }
    }
    std::nth_element(differences.begin(), differences.begin() + std::ptrdiff_t(differences.size() / 2), differences.end());
    return {double(within) / double(differences.size()), differences[differences.size() / 2]};
}

TEST(EnvironmentRender, TheDominantDirectionAndTheStochasticModeAgreeWithTheCpu) {
    // The renderer's variants run the shared code the CPU runs: the split sum along the dominant
    // direction, and N filtered importance samples turned per pixel by the same hash. Interpolated
    // normals differ in their last bits between the two rasterisers, and a sample's lod near a
    // mip boundary can round apart, so most values, not all, agree to 1e-3.
    for (float roughness : {0.2f, 0.6f}) {
        const auto [dominantWithin, dominantMedian] =
            gpuAgainstCpu({EnvironmentMethod::Dominant, 16}, roughness, 1e-3f);
        EXPECT_GT(dominantWithin, 0.95) << roughness;
        EXPECT_LT(dominantMedian, 1e-4) << roughness;
        const auto [stochasticWithin, stochasticMedian] =
            gpuAgainstCpu({EnvironmentMethod::Stochastic, 8}, roughness, 1e-3f);
        EXPECT_GT(stochasticWithin, 0.9) << roughness;
        EXPECT_LT(stochasticMedian, 2e-4) << roughness;
    }
}

TEST(EnvironmentRender, TheVariantsDifferFromTheSplitSumWhereTheyShould) {
    // Not the same picture under another name: the dominant direction pulls a rough lobe towards
    // N, and the stochastic mode is the integral at the real V, noise and all.
    test::glContext();
    Scene scene;
    scene.material.metallic = 1.0f;
    scene.material.roughness = 0.7f;
    scene.lights = {studio()};
    Renderer renderer;
    auto renderWith = [&](EnvironmentMethod method) {
        RenderSettings settings = test::renderSettings(48, 48, RenderPath::Single, 1);
        settings.environment = {method, 8};
        return renderer.render(test::prepared(scene), settings).hdr;
    };
    const HdrImage split = renderWith(EnvironmentMethod::SplitSum);
    EXPECT_GT(maxDifference(renderWith(EnvironmentMethod::Dominant), split), 1e-2);
    EXPECT_GT(maxDifference(renderWith(EnvironmentMethod::Stochastic), split), 1e-2);
    EXPECT_EQ(maxDifference(renderWith(EnvironmentMethod::SplitSum), split), 0.0);   // and back again
}

TEST(EnvironmentRender, AMetalUnderTheStudioIsNotABlackBall) {
    test::glContext();
    Renderer renderer;
    Scene scene;
    scene.material.baseColor = {1.0f, 0.77f, 0.34f};
    scene.material.metallic = 1.0f;
    scene.material.roughness = 0.25f;
    scene.lights = {studio()};
    const HdrImage image = renderer.render(test::prepared(scene), test::renderSettings(64, 64, RenderPath::Single, 1)).hdr;
    // The centre of the sphere reflects the studio behind the camera: bright and gold.
    const float* centre = &image.rgb[(size_t(32) * 64 + 32) * 3];
    EXPECT_GT(centre[0], 0.1f);
    EXPECT_GT(centre[0], centre[2]);
    // Without the environment the same metal under no light is black.
    scene.lights.clear();
    const HdrImage dark = renderer.render(test::prepared(scene), test::renderSettings(64, 64, RenderPath::Single, 1)).hdr;
    EXPECT_EQ(dark.rgb[(size_t(32) * 64 + 32) * 3], 0.0f);
}

TEST(EnvironmentRender, TheBackgroundIsTheEnvironmentAndTurnsWithIt) {
    test::glContext();
    Renderer renderer;
    Scene scene;
    scene.lights = {studio()};
    scene.display.backgroundFromEnvironment = true;
    const HdrImage a = renderer.render(test::prepared(scene), test::renderSettings(64, 64, RenderPath::Single, 1)).hdr;
    // The corner shows the environment, not the clear colour.
    EXPECT_NE(a.rgb[0], scene.display.background.x);
    scene.lights[0].rotationDegrees = 360.0f;
    const HdrImage turnedRound = renderer.render(test::prepared(scene), test::renderSettings(64, 64, RenderPath::Single, 1)).hdr;
    EXPECT_LE(maxDifference(turnedRound, a), 1e-3);
    scene.lights[0].rotationDegrees = 90.0f;
    const HdrImage turned = renderer.render(test::prepared(scene), test::renderSettings(64, 64, RenderPath::Single, 1)).hdr;
    EXPECT_GT(maxDifference(turned, a), 0.05);
    // Without "environment" the background stays the colour.
    scene.display.backgroundFromEnvironment = false;
    const HdrImage plain = renderer.render(test::prepared(scene), test::renderSettings(64, 64, RenderPath::Single, 1)).hdr;
    EXPECT_FLOAT_EQ(plain.rgb[0], scene.display.background.x);
}

TEST(EnvironmentRender, AnEnvironmentNotPreparedIsAnErrorNotABlackImage) {
    // The renderer makes nothing itself, not even a built-in: what the prepared scene lacks
    // is the caller's mistake, said at once.
    test::glContext();
    Renderer renderer;
    Scene scene;
    Light file = studio();
    file.source = "/nowhere/sky.hdr";
    scene.lights = {file};
    const std::shared_ptr<const Mesh> sphere = builtinMesh(MeshKind::Sphere);
    const RenderSettings settings = test::renderSettings(16, 16, RenderPath::Single, 1);
    EXPECT_THROW(renderer.render({scene, sphere, nullptr}, settings), std::invalid_argument);
    scene.lights = {studio()};
    EXPECT_THROW(renderer.render({scene, sphere, nullptr}, settings), std::invalid_argument);
    // Another environment than the one the light names is not it either.
    EXPECT_THROW(renderer.render({scene, sphere, test::madeEnvironment("builtin:white")}, settings),
                 std::invalid_argument);
    EXPECT_THROW(renderer.render({scene, nullptr, test::madeEnvironment("builtin:studio")}, settings),
                 std::invalid_argument);
    EXPECT_NO_THROW(renderer.render({scene, sphere, test::madeEnvironment("builtin:studio")}, settings));
}

}  // namespace
}  // namespace patina
