// The ground truth converges to what is known exactly (spec section 3): the white furnace, an
// environment that depends only on height under rotation, and a linear environment's
// irradiance. Each within a few standard errors and inside the tolerance the spec names.
#include <cmath>

#include <gtest/gtest.h>

#include "environment/builtin_environments.h"
#include "environment/reference.h"
#include "scene/light_packing.h"
#include "shading/cpu_shading.h"
#include "shading/environment_brdf.h"
#include "test_support.h"

namespace patina {
namespace {

constexpr float kPi = 3.14159265358979f;


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
    // a + (2 / 3) b n.y (spec section 3).
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
        sum += distribution.pdf(test::randomUnitVector(rng)) * 4.0 * kPi;
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
