// Each BRDF term of shaders/shared/brdf.glsl (compiled as C++) against values computed by hand from
// docs/SHADING.md S1, and the whole BRDF against the double reference.
#include <numbers>

#include <gtest/gtest.h>

#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "shading/shading.h"
#include "test_support.h"

namespace patina {
namespace {

using shader::BrdfValue;
using shader::SurfaceMaterial;

TEST(MaterialModel, DielectricSpecularHalfGivesF0OfFourPercent) {
    const SurfaceMaterial m = shader::deriveSurfaceMaterial(glm::vec3(0.9f, 0.2f, 0.1f), 0.5f, 0.5f, 0.0f);
    EXPECT_FLOAT_EQ(m.f0.r, 0.04f);
    EXPECT_FLOAT_EQ(m.f0.g, 0.04f);
    EXPECT_FLOAT_EQ(m.f0.b, 0.04f);
    EXPECT_FLOAT_EQ(m.diffuseColor.r, 0.9f);
}

TEST(MaterialModel, MetalTakesBaseColourAsF0AndHasNoDiffuse) {
    const glm::vec3 gold(1.0f, 0.78f, 0.34f);
    const SurfaceMaterial m = shader::deriveSurfaceMaterial(gold, 0.3f, 0.5f, 1.0f);
    EXPECT_FLOAT_EQ(m.f0.g, 0.78f);
    EXPECT_FLOAT_EQ(m.diffuseColor.r, 0.0f);
    // Half metal: c_spec = mix(0.04, base, 0.5), c_diff = 0.5 base.
    const SurfaceMaterial half = shader::deriveSurfaceMaterial(gold, 0.3f, 0.5f, 0.5f);
    EXPECT_FLOAT_EQ(half.f0.b, 0.5f * 0.04f + 0.5f * 0.34f);
    EXPECT_FLOAT_EQ(half.diffuseColor.g, 0.39f);
}

TEST(MaterialModel, AlphaIsRoughnessSquared) {
    EXPECT_FLOAT_EQ(shader::deriveSurfaceMaterial(glm::vec3(0.5f), 0.5f, 0.5f, 0.0f).alpha, 0.25f);
    EXPECT_FLOAT_EQ(shader::deriveSurfaceMaterial(glm::vec3(0.5f), 1.0f, 0.5f, 0.0f).alpha, 1.0f);
}

TEST(LambertTerm, IsColourOverPi) {
    EXPECT_NEAR(shader::Fd_Lambert(glm::vec3(1.0f)).x, std::numbers::inv_pi, 1e-7);
}

TEST(GgxDistribution, PeakIsOneOverPiAlphaSquared) {
    // r = 0.5: alpha = 0.25, D(NoH = 1) = 1 / (pi 0.0625) = 5.09295818.
    EXPECT_NEAR(shader::D_GGX(1.0f, glm::vec3(0.0f), 0.25f), 5.09295818, 5e-6);
}

TEST(GgxDistribution, AtGrazingHalfVectorIsAlphaSquaredOverPi) {
    // NoH = 0, |N x H| = 1: D = alpha^2 / pi; alpha = 0.25: 0.0625 / pi = 0.01989437.
    EXPECT_NEAR(shader::D_GGX(0.0f, glm::vec3(1.0f, 0.0f, 0.0f), 0.25f), 0.01989437, 1e-8);
}

TEST(GgxDistribution, RoughnessOneIsUniform) {
    // alpha = 1: D = 1 / pi whatever NoH.
    for (float theta : {0.0f, 0.3f, 0.9f, 1.5f}) {
        const float c = std::cos(theta), s = std::sin(theta);
        EXPECT_NEAR(shader::D_GGX(c, glm::vec3(s, 0.0f, 0.0f), 1.0f), std::numbers::inv_pi, 1e-6);
    }
}

TEST(GgxDistribution, MatchesTheStandardFormAwayFromThePeak) {
    // r = 0.6, NoH = 0.8: alpha^2 = 0.1296; base = 0.64 (0.1296 - 1) + 1 = 0.442944;
    // D = 0.1296 / (pi 0.442944^2) = 0.2102604.
    EXPECT_NEAR(shader::D_GGX(0.8f, glm::vec3(0.6f, 0.0f, 0.0f), 0.36f), 0.2102604, 2e-7);
}

TEST(SchlickGgxVisibility, UsesKarisRemapOfRoughness) {
    // r = 1: k = 0.5. NoV = NoL = 1: G = 1, V = 1/4.
    EXPECT_FLOAT_EQ(shader::k_Karis(1.0f), 0.5f);
    EXPECT_FLOAT_EQ(shader::V_SchlickGGX(1.0f, 1.0f, shader::k_Karis(1.0f)), 0.25f);
    // NoV = NoL = 0.5: G1 = 0.5 / 0.75 = 2/3, G = 4/9, V = G / (4 * 0.25) = 4/9.
    EXPECT_NEAR(shader::V_SchlickGGX(0.5f, 0.5f, shader::k_Karis(1.0f)), 4.0 / 9.0, 1e-7);
    // r = 0.2: k = 1.44 / 8 = 0.18. NoV = 0.3, NoL = 0.7:
    // G1(0.3) = 0.3 / 0.426 = 0.704225, G1(0.7) = 0.7 / 0.754 = 0.928382,
    // V = 0.653789 / (4 * 0.21) = 0.778320.
    EXPECT_NEAR(shader::V_SchlickGGX(0.3f, 0.7f, shader::k_Karis(0.2f)), 0.778320, 2e-6);
}

TEST(SphericalGaussianFresnel, IsOneAtGrazingAndNearF0AtNormal) {
    const glm::vec3 f0(0.04f);
    EXPECT_FLOAT_EQ(shader::F_SchlickSphericalGaussian(f0, 0.0f).x, 1.0f);
    // VoH = 1: 2^(-12.53789) = 1.68158e-4; F = 0.04 + 0.96 * 1.68158e-4 = 0.04016143.
    EXPECT_NEAR(shader::F_SchlickSphericalGaussian(f0, 1.0f).x, 0.04016143, 1e-7);
    // VoH = 0.5: 2^((-2.777365 - 6.98316) 0.5) = 2^-4.8802625 = 0.033953;
    // F = 0.04 + 0.96 * 0.033954 = 0.0725961.
    EXPECT_NEAR(shader::F_SchlickSphericalGaussian(f0, 0.5f).x, 0.0725961, 2e-7);
}

TEST(EpicBrdf, MatchesTheDoubleReference) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
        const Material material{{{unit(rng), unit(rng), unit(rng)}, 0.05f + 0.95f * unit(rng), unit(rng), unit(rng)},
                                "m"};
        const glm::vec3 N = test::randomUnitVector(rng);
        const glm::vec3 V = test::vectorAtCosine(N, 0.01f + 0.99f * unit(rng), rng);
        const glm::vec3 L = test::vectorAtCosine(N, 0.01f + 0.99f * unit(rng), rng);
        const BrdfValue f = evaluateBrdf(BrdfModelId::Epic, surfaceMaterial(material), N, V, L);
        const reference::Brdf expected = reference::brdf(
            test::toReference(material), test::toReference(N), test::toReference(V), test::toReference(L));
        worst = std::max(worst, test::maxRelativeError({f.diffuse + f.specular},
                                                       {expected.diffuse + expected.specular}, 1e-3));
    }
    EXPECT_LT(worst, 1e-4);
}

TEST(EpicBrdf, IsReciprocal) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 2000; ++i) {
        const SurfaceMaterial m = shader::deriveSurfaceMaterial(
            glm::vec3(unit(rng)), 0.05f + 0.95f * unit(rng), unit(rng), unit(rng));
        const glm::vec3 N = test::randomUnitVector(rng);
        const glm::vec3 V = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        const glm::vec3 L = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        const BrdfValue a = evaluateBrdf(BrdfModelId::Epic, m, N, V, L);
        const BrdfValue b = evaluateBrdf(BrdfModelId::Epic, m, N, L, V);
        EXPECT_NEAR(a.specular.x, b.specular.x, 1e-5 * std::max(1.0f, a.specular.x));
    }
}

}  // namespace
}  // namespace patina
