// The ground-truth render: the CPU rasteriser sees what the GPU draws, the analytic lights are
// exact (so a render and the reference agree where the environment is absent), the background
// is the renderer's, and the passes are independent estimates that a stop keeps.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "picture/display_image.h"
#include "reference/pixel_surfaces.h"
#include "reference/reference_render.h"
#include "test_support.h"

namespace patina {
namespace {

constexpr int kSize = 96;

TEST(PixelSurfaces, TheSphereIsSeenWhereItIs) {
    const Scene scene = defaultScene();
    const PixelSurfaces surfaces = rasterizeSurfaces(test::prepared(scene), kSize, kSize);
    ASSERT_EQ(surfaces.sampleOfPixel.size(), size_t(kSize * kSize));
    int covered = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const int32_t i = surfaces.sampleOfPixel[size_t(y * kSize + x)];
            // The ray through the pixel centre against the unit sphere the mesh approximates.
            const glm::vec3 d = pixelRayDirection(scene.camera, kSize, kSize, x, y);
            const glm::vec3 o = scene.camera.position;
            const float b = glm::dot(o, d), c = glm::dot(o, o) - 1.0f, disc = b * b - c;
            if (i < 0) {
                EXPECT_LT(disc, 0.02f) << x << " " << y;   // a miss, or a graze of a facet's edge
                continue;
            }
            ++covered;
            ASSERT_GT(disc, -0.02f) << x << " " << y;
            const ProbeSample& s = surfaces.samples[size_t(i)];
            EXPECT_NEAR(glm::length(s.position), 1.0f, 2e-3f);
            EXPECT_NEAR(glm::length(glm::cross(s.position - o, d)), 0.0f, 1e-4f * glm::length(s.position - o));
            EXPECT_GT(glm::dot(glm::normalize(s.normal), -d), 0.0f);
            EXPECT_NEAR(glm::length(s.toViewer + d), 0.0f, 1e-5f);
        }
    }
    EXPECT_GT(covered, kSize * kSize / 5);
}

Scene analyticScene(bool environmentBackground) {
    Scene scene = defaultScene();
    scene.material.roughness = 0.35f;
    for (Light& light : scene.lights) {
        light.enabled = light.type != LightType::Environment || environmentBackground;
        if (light.type == LightType::Environment) {
            light.intensity = 0.0f;   // shows as background, adds no light
            light.rotationDegrees = 40.0f;
        }
    }
    scene.display.backgroundFromEnvironment = environmentBackground;
    scene.display.backgroundBlur = 0.3f;
    return scene;
}

// The scene rendered by the GPU without MSAA, and its ground truth at one iteration a pixel.
struct RenderAndReference {
    HdrImage render;
    PixelSurfaces surfaces;
    ReferenceImage reference;
};
RenderAndReference renderAndReference(const Scene& scene) {
    test::glContext();
    Renderer renderer;
    RenderAndReference both;
    both.render = renderer.render(test::prepared(scene), test::renderSettings(kSize, kSize, RenderPath::Single, 1)).hdr;
    both.surfaces = rasterizeSurfaces(test::prepared(scene), kSize, kSize);
    ReferenceRenderOptions options;
    options.samplesPerPixel = 1;
    both.reference = renderReference(test::prepared(scene), both.surfaces, options);
    return both;
}

TEST(ReferenceRender, AnalyticLightsAreExactAndMatchTheRender) {
    // No environment light: the reference adds each light exactly, so it equals the GPU's render
    // pixel for pixel wherever both see the mesh, and the background is the renderer's colour.
    const Scene scene = analyticScene(false);
    const auto [render, surfaces, reference] = renderAndReference(scene);
    int compared = 0;
    for (size_t pixel = 0; pixel < surfaces.sampleOfPixel.size(); ++pixel) {
        for (int c = 0; c < 3; ++c) {
            const float r = reference.value.rgb[pixel * 3 + size_t(c)], g = render.rgb[pixel * 3 + size_t(c)];
            EXPECT_EQ(reference.standardError.rgb[pixel * 3 + size_t(c)], 0.0f);
            if (surfaces.sampleOfPixel[pixel] < 0) {
                EXPECT_EQ(r, scene.display.background[c]);
            } else if (std::abs(r - g) < 2e-3f * std::max(g, 0.05f)) {
                ++compared;
            }
        }
    }
    // Edge pixels may be covered on one side only (fill rules); everything else agrees.
    EXPECT_GT(compared, int(surfaces.samples.size()) * 3 * 97 / 100);
}

TEST(ReferenceRender, TheEnvironmentBackgroundIsTheRenderers) {
    const auto [render, surfaces, reference] = renderAndReference(analyticScene(true));
    double largest = 0.0;
    int background = 0;
    for (size_t pixel = 0; pixel < surfaces.sampleOfPixel.size(); ++pixel) {
        if (surfaces.sampleOfPixel[pixel] >= 0) {
            continue;
        }
        ++background;
        for (int c = 0; c < 3; ++c) {
            const float r = reference.value.rgb[pixel * 3 + size_t(c)], g = render.rgb[pixel * 3 + size_t(c)];
            largest = std::max(largest, double(std::abs(r - g)) / std::max(double(g), 1e-3));
        }
    }
    EXPECT_GT(background, kSize * kSize / 3);
    EXPECT_LT(largest, 1e-3);   // texture filtering's rounding only
}

TEST(ReferenceRender, PassesAreIndependentAndAStopKeepsWhatIsDone) {
    Scene scene = defaultScene();
    scene.material.metallic = 1.0f;
    scene.material.roughness = 0.5f;
    const PixelSurfaces surfaces = rasterizeSurfaces(test::prepared(scene), 24, 24);
    ReferenceRenderOptions options;
    options.samplesPerPixel = 64;
    options.samplesPerPass = 16;
    std::vector<int> reported;
    const ReferenceImage stopped = renderReference(test::prepared(scene), surfaces, options, [&](const ReferenceImage& partial) {
        reported.push_back(partial.samplesPerPixel);
        return partial.samplesPerPixel < 32;
    });
    EXPECT_EQ(reported, (std::vector<int>{16, 32}));
    EXPECT_EQ(stopped.samplesPerPixel, 32);
    const ReferenceImage full = renderReference(test::prepared(scene), surfaces, options);
    EXPECT_EQ(full.samplesPerPixel, 64);
    // Twice the samples: the standard error about 1/sqrt(2) of it; the two agree within it.
    double errorStopped = 0.0, errorFull = 0.0, outside = 0.0, values = 0.0;
    for (size_t pixel = 0; pixel < surfaces.sampleOfPixel.size(); ++pixel) {
        if (surfaces.sampleOfPixel[pixel] < 0) {
            continue;
        }
        for (size_t c = 0; c < 3; ++c) {
            const size_t k = pixel * 3 + c;
            errorStopped += stopped.standardError.rgb[k];
            errorFull += full.standardError.rgb[k];
            values += 1.0;
            outside += std::abs(stopped.value.rgb[k] - full.value.rgb[k]) >
                       4.0f * std::hypot(stopped.standardError.rgb[k], full.standardError.rgb[k]) + 1e-6f;
        }
    }
    ASSERT_GT(errorFull, 0.0);
    EXPECT_NEAR(errorFull / errorStopped, std::sqrt(0.5), 0.15);
    EXPECT_LT(outside / values, 0.01);
}

TEST(DisplayImage, IsTheRenderersDisplayTransform) {
    test::glContext();
    Scene scene = analyticScene(false);
    scene.display.exposure = 0.7f;
    scene.display.tonemap = Tonemap::PbrNeutral;
    Renderer renderer;
    const RenderOutput render = renderer.render(test::prepared(scene), test::renderSettings(kSize, kSize, RenderPath::Single, 1));
    // The ground truth's backdrop: where the renderer shows the flat background as its swatch.
    ReferenceRenderOptions options;
    options.samplesPerPixel = 1;
    const PixelSurfaces surfaces = rasterizeSurfaces(test::prepared(scene), kSize, kSize);
    const ReferenceImage reference = renderReference(test::prepared(scene), surfaces, options);
    ASSERT_GT(std::count(reference.backdrop.begin(), reference.backdrop.end(), 1), kSize);
    const LdrImage shown = displayImage(render.hdr, scene.display, reference.backdrop);
    ASSERT_EQ(shown.rgba.size(), render.ldr.rgba.size());
    int off = 0;
    for (size_t i = 0; i < shown.rgba.size(); ++i) {
        off += std::abs(int(shown.rgba[i]) - int(render.ldr.rgba[i])) > 1;
    }
    EXPECT_EQ(off, 0);
    // Without the backdrop the background is tone-mapped, which the renderer does not do.
    EXPECT_NE(displayImage(render.hdr, scene.display).rgba, render.ldr.rgba);
}

}  // namespace
}  // namespace patina
