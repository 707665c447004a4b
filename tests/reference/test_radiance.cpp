// The ground truth converges to what is known exactly (docs/LIGHTING.md L3): the white furnace, an
// environment that depends only on height under rotation, and a linear environment's
// irradiance. Each within a few standard errors and inside the tolerance docs/LIGHTING.md L3 names.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "environment/builtin_environments.h"
#include "reference/radiance.h"
#include "scene/light_packing.h"
#include "shading/cpu_shading.h"
#include "shading/environment_brdf.h"
#include "test_support.h"

namespace patina {
namespace {



struct Fixture {
    std::shared_ptr<const Environment> environment;
    EnvironmentDistribution distribution;
    explicit Fixture(HdrImage image)
        : environment(prepareEnvironment(image, "test", {{2, 8}})), distribution(environment->image) {}
    ReferenceEnvironment reference(float rotation = 0.0f) const {
        return {environment.get(), &distribution, 1.0f, rotation};
    }
};

glm::vec3 viewAt(float NoV) {
    return {std::sqrt(1.0f - NoV * NoV), 0.0f, NoV};
}

// A dim sky and a sun of one pixel holding most of the energy, as real HDRIs have (128 x 64),
// and the direction to the sun's pixel centre.
struct SunnySky {
    HdrImage image;
    glm::vec3 sun;
};
SunnySky sunnySky() {
    const int width = 128, height = 64, sunX = 40, sunY = 20;
    HdrImage image = test::equirectOf(width, height, [](glm::vec3 d) { return glm::vec3(0.2f + 0.1f * d.y); });
    for (int c = 0; c < 3; ++c) {
        image.rgb[(size_t(sunY) * width + sunX) * 3 + size_t(c)] = 5000.0f;
    }
    return {image, shader::equirectToDirection(glm::vec2((float(sunX) + 0.5f) / width, (float(sunY) + 0.5f) / height))};
}

// Red's sum over every pixel of `image`: its radiance times weight(L) (the integrand's f |N.L|)
// times the pixel's solid angle.
template <typename Weight>
double pixelSum(const HdrImage& image, Weight weight) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
        const double dOmega = (std::cos(double(y) / image.height * std::numbers::pi) -
                               std::cos(double(y + 1) / image.height * std::numbers::pi)) *
                              2.0 * std::numbers::pi / image.width;
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 L = shader::equirectToDirection(
                glm::vec2((float(x) + 0.5f) / image.width, (float(y) + 0.5f) / image.height));
            sum += double(image.rgb[(size_t(y) * size_t(image.width) + size_t(x)) * 3] * weight(L)) * dOmega;
        }
    }
    return sum;
}

TEST(Reference, UnderASunItMatchesAQuadratureOfThePixelsWithASmallError) {
    // The estimate must agree with a sum over every pixel (radiance x f x NoL x the pixel's solid
    // angle) and its standard error must be small: the distribution has to follow the bilinear
    // image around the sun, not the sun's pixel alone (then this error was 25%).
    const SunnySky sky = sunnySky();
    const Fixture fixture(sky.image);
    for (const float roughness : {0.5f, 1.0f}) {
        const shader::SurfaceMaterial metal = shader::deriveSurfaceMaterial(glm::vec3(0.9f), roughness, 0.5f, 1.0f);
        const glm::vec3 N = glm::normalize(sky.sun + glm::vec3(0.0f, 0.3f, 0.0f)), V = N;
        const double sum = pixelSum(sky.image, [&](glm::vec3 L) {
            const float NoL = glm::dot(N, L);
            if (!(NoL > 0.0f)) {
                return 0.0f;
            }
            const shader::BrdfValue f = evaluateBrdfUnderEnvironment(BrdfModelId::Epic, metal, N, V, L);
            return (f.diffuse.x + f.specular.x) * NoL;
        });
        ReferenceOptions options;
        options.samples = 20000;
        const ReferenceEstimate estimate =
            referenceRadiance(BrdfModelId::Epic, metal, fixture.reference(), {}, glm::vec3(0.0f), N, V, options);
        EXPECT_LT(estimate.standardError.x, 0.02 * sum) << roughness;
        // The estimate integrates the bilinear image, the sum the pixels: a few per cent apart.
        EXPECT_NEAR(estimate.value.x, sum, 0.03 * sum + 4.0 * estimate.standardError.x) << roughness;
    }
}

// The light through a rough glass's wall from a sun behind it (KHR_materials_transmission 1,
// roughness 0.4, the sun's pixel off the line of sight): the estimate agrees with a sum over
// every pixel behind the wall (radiance x f_t x |N.L| x the pixel's solid angle), and its
// standard error is small: 2.7% of the value at these samples, where f_t's samples alone met
// the sun rarely (18%, and fireflies in a rough glass under an HDRI).
TEST(Reference, UnderASunBehindARoughGlassItMatchesAQuadratureOfThePixels) {
    const SunnySky sky = sunnySky();
    const Fixture fixture(sky.image);
    const glm::vec3 N = -glm::normalize(sky.sun + glm::vec3(0.0f, 0.3f, 0.0f)), V = N;
    const shader::SurfaceMaterial glass = shader::deriveSurfaceMaterial(glm::vec3(1.0f), 0.4f, 0.5f, 0.0f);
    const shader::Transmission t = shader::deriveTransmission(glass, 1.0f, glm::vec3(1.0f), N, V);
    const double sum = pixelSum(sky.image, [&](glm::vec3 L) {
        const float NoL = glm::dot(N, L);
        return NoL < 0.0f ? shader::transmissionBtdf(t, N, V, L).x * -NoL : 0.0f;
    });
    ReferenceOptions options;
    options.samples = 4096;
    options.transmission = 1.0f;
    const ReferenceEstimate estimate =
        referenceRadiance(BrdfModelId::Gltf, glass, fixture.reference(), {}, glm::vec3(0.0f), N, V, options);
    EXPECT_LT(estimate.standardError.x, 0.05 * sum);
    // The estimate integrates the bilinear image, the sum the pixels: a few per cent apart.
    EXPECT_NEAR(estimate.transmitted.x, sum, 0.05 * sum + 4.0 * estimate.standardError.x);
}

TEST(Reference, WhiteFurnaceGivesTheModelsDirectionalAlbedo) {
    const Fixture white(*builtinEnvironment("white"));
    Material metal;
    metal.baseColor = {0.95f, 0.64f, 0.54f};
    metal.metallic = 1.0f;
    ReferenceOptions options;
    options.samples = 100000;
    for (float r : {0.1f, 0.5f, 1.0f}) {
        metal.roughness = r;
        const shader::SurfaceMaterial m = surfaceMaterial(metal);
        for (float NoV : {0.3f, 0.8f}) {
            const ReferenceEstimate e = referenceRadiance(BrdfModelId::Epic, m, white.reference(), {}, glm::vec3(0),
                                                         {0, 0, 1}, viewAt(NoV), options);
            const glm::vec2 ab = integrateEnvironmentBrdf(BrdfModelId::Epic, NoV, m.roughness, 65536);
            for (int c = 0; c < 3; ++c) {
                const float expected = m.f0[c] * ab.x + ab.y;
                // Within 1e-3 of it, give or take the estimate's own noise (3 standard errors).
                EXPECT_NEAR(e.value[c], expected, 1e-3f + 3.0f * e.standardError[c]) << "r " << r << " NoV " << NoV;
                EXPECT_LT(e.standardError[c], 2e-3f * expected);
            }
        }
    }
}

TEST(Reference, AnEnvironmentOfHeightAloneIsInvariantUnderRotation) {
    const Fixture sky(test::equirectOf(128, 64, [](glm::vec3 d) {
        return glm::vec3(0.2f + std::max(d.y, 0.0f) * 3.0f, 0.5f, 0.1f + d.y * d.y);
    }));
    Material material;
    material.baseColor = {0.5f, 0.4f, 0.3f};
    material.roughness = 0.4f;
    const shader::SurfaceMaterial m = surfaceMaterial(material);
    ReferenceOptions options;
    options.samples = 8000;
    const glm::vec3 N = glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f)), V = glm::normalize(glm::vec3(-0.2f, 0.6f, 0.7f));
    const ReferenceEstimate a = referenceRadiance(BrdfModelId::Epic, m, sky.reference(0.0f), {}, {}, N, V, options);
    options.seed = 2;
    const ReferenceEstimate b = referenceRadiance(BrdfModelId::Epic, m, sky.reference(77.0f), {}, {}, N, V, options);
    for (int c = 0; c < 3; ++c) {
        const float se = std::hypot(a.standardError[c], b.standardError[c]);
        EXPECT_NEAR(a.value[c], b.value[c], 4.0f * se + 1e-6f);
    }
}

TEST(Reference, ALinearEnvironmentHasTheExactDiffuseIrradiance) {
    // Env = a + b d.y: E(n) = pi a + (2 pi / 3) b n.y, so a white Lambert surface returns
    // a + (2 / 3) b n.y (docs/LIGHTING.md L3).
    const float a = 0.6f, b = 0.35f;
    const Fixture linear(test::equirectOf(256, 128, [&](glm::vec3 d) { return glm::vec3(a + b * d.y); }));
    Material white;
    white.baseColor = glm::vec3(1.0f);
    white.roughness = 0.7f;
    const shader::SurfaceMaterial m = surfaceMaterial(white);
    ReferenceOptions options;
    options.samples = 64000;
    options.specular = false;
    for (const glm::vec3 n : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(1, 1, 0)), glm::vec3(0, 0, 1),
                              glm::normalize(glm::vec3(0.2f, -0.9f, 0.3f))}) {
        const glm::vec3 V = n;
        const ReferenceEstimate e = referenceRadiance(BrdfModelId::Epic, m, linear.reference(), {}, {}, n, V, options);
        const float exact = a + 2.0f / 3.0f * b * n.y;
        EXPECT_NEAR(e.value.x, exact, 1e-3f * exact + 3.0f * e.standardError.x) << n.y;
        EXPECT_LT(e.standardError.x, 2e-3f * exact);
    }
}

TEST(Reference, AnalyticLightsAreAddedExactly) {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.0f, -1.0f, -0.3f};
    const std::vector<shader::PackedLight> lights = packEnabledLights({sun});
    Material material;
    const shader::SurfaceMaterial m = surfaceMaterial(material);
    const ReferenceEstimate e =
        referenceRadiance(BrdfModelId::Epic, m, {}, lights, glm::vec3(0), {0, 1, 0}, {0, 0.6f, 0.8f}, {});
    EXPECT_EQ(e.value, shadePoint(BrdfModelId::Epic, m, lights, glm::vec3(0), {0, 1, 0}, {0, 0.6f, 0.8f}));
    EXPECT_EQ(e.standardError, glm::vec3(0.0f));
}

TEST(EnvironmentDistribution, ThePdfIntegratesToOneAndMatchesTheSamples) {
    const HdrImage image = test::equirectOf(64, 32, [](glm::vec3 d) { return glm::vec3(1.0f + 10.0f * std::max(d.x, 0.0f)); });
    const EnvironmentDistribution distribution(image);
    // Monte Carlo over uniform directions: the mean of pdf / (1 / 4 pi) is 1.
    std::mt19937 rng(11);
    double sum = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        sum += distribution.pdf(test::randomUnitVector(rng)) * 4.0 * std::numbers::pi_v<float>;
    }
    EXPECT_NEAR(sum / n, 1.0, 0.01);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int bright = 0;
    for (int i = 0; i < 10000; ++i) {
        const auto s = distribution.sample(unit(rng), unit(rng));
        EXPECT_NEAR(s.pdf, distribution.pdf(s.direction), 1e-3f * s.pdf + 1e-6f);
        bright += s.direction.x > 0.0f ? 1 : 0;
    }
    EXPECT_GT(bright, 8000);   // where the light is
}

}  // namespace
}  // namespace patina
