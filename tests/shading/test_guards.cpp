// The guards of shaders/shared/brdf.glsl and lights.glsl (docs/SHADING.md S2): output is finite and
// non-negative everywhere, and where the formulas are well defined the guards change nothing.
#include <cmath>

#include <gtest/gtest.h>

#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "accuracy/edge_cases.h"
#include "scene/probe.h"
#include "shading/shading.h"
#include "shading/shading_f64.h"
#include "test_support.h"

namespace patina {
namespace {

void expectFiniteNonNegative(const std::vector<glm::vec3>& values, const std::string& name) {
    for (const glm::vec3& v : values) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(std::isfinite(v[c]) && v[c] >= 0.0f) << name << ": channel " << c << " = " << v[c];
        }
    }
}

TEST(Guards, EdgeSweepOnCpuIsFiniteAndNonNegative) {
    for (const EdgeCase& edge : edgeCases()) {
        expectFiniteNonNegative(probeOnCpu(edge.material, edge.lights, edge.samples), edge.name);
    }
}

TEST(Guards, AreaLightEdgesOnCpuAreFiniteAndNonNegative) {
    for (const EdgeCase& edge : areaLightEdgeCases()) {
        expectFiniteNonNegative(probeOnCpu(edge.material, edge.lights, edge.samples), edge.name);
    }
}

TEST(Guards, EveryTermStaysFiniteAtItsFailurePoint) {
    // r = 0 at NoH = 1: alpha floor keeps D finite (unguarded: 0/0).
    const shader::SurfaceMaterial smooth = shader::deriveSurfaceMaterial(glm::vec3(0.5f), 0.0f, 0.5f, 0.0f);
    EXPECT_TRUE(std::isfinite(shader::D_GGX(1.0f, glm::vec3(0.0f), smooth.alpha)));
    // NoV = NoL = 0: the visibility form has no division by NoL NoV.
    EXPECT_TRUE(std::isfinite(shader::V_SchlickGGX(0.0f, 0.0f, shader::k_Karis(0.045f))));
    // Attenuation with every coefficient 0 at t = 0.
    EXPECT_TRUE(std::isfinite(shader::pointLightAttenuation(0.0f, 0.0f, glm::vec3(0.0f))));
    // L = -V.
    const glm::vec3 N(0, 0, 1), V = glm::normalize(glm::vec3(0.3f, 0.0f, -1.0f));
    const shader::BrdfValue f = evaluateBrdf(BrdfModelId::Epic, smooth, N, V, -V);
    EXPECT_TRUE(std::isfinite(f.specular.x));
    EXPECT_EQ(f.specular.x, 0.0f);
}

TEST(Guards, RoughnessFloorIsBelowTheWellDefinedRange) {
    for (float r : {0.05f, 0.1f, 0.5f, 1.0f}) {
        const shader::SurfaceMaterial m = shader::deriveSurfaceMaterial(glm::vec3(0.5f), r, 0.5f, 0.0f);
        EXPECT_EQ(m.roughness, r);
        EXPECT_EQ(m.alpha, r * r);
    }
    EXPECT_EQ(shader::deriveSurfaceMaterial(glm::vec3(0.5f), 0.0f, 0.5f, 0.0f).roughness,
              shader::MIN_PERCEPTUAL_ROUGHNESS);
}

TEST(Guards, AttenuationDenominatorFloorOnlyActsBelowIt) {
    // a_c = 1 at t = 0: 1 / 1, the floor is not involved.
    EXPECT_FLOAT_EQ(shader::pointLightAttenuation(0.0f, 0.0f, glm::vec3(1, 0, 0)), 1.0f);
    // Inverse square at t = 2: 1 / 4.
    EXPECT_FLOAT_EQ(shader::pointLightAttenuation(2.0f, 0.0f, glm::vec3(0, 0, 1)), 0.25f);
    // All zero: clamped to 1 / 1e-4.
    EXPECT_FLOAT_EQ(shader::pointLightAttenuation(1.0f, 0.0f, glm::vec3(0.0f)),
                    1.0f / shader::MIN_ATTENUATION_DENOMINATOR);
}

TEST(Guards, ChangeNothingWhereTheFormulaIsWellDefined) {
    // The guarded code compiled in double against the unguarded double reference, over
    // r >= 0.05 and NoV, NoL >= 0.01, with half the samples near the mirror direction where D
    // peaks. Only float-rounded literal constants (about 3e-8) may differ; any active guard
    // (a clamp, a floor) would show as a far larger error.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const glm::dvec3 N(0.0, 0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < 40000; ++i) {
        // Parameters a Material holds (floats), the same numbers for both sides.
        const double roughness = float(i % 2 ? 0.05 + 0.01 * unit(rng) : 0.05 + 0.95 * unit(rng));
        const double metallic = float(unit(rng));
        const glm::dvec3 base(glm::vec3(unit(rng), unit(rng), unit(rng)));
        const glm::dvec3 V = test::vectorAtCosine(N, 0.01 + 0.99 * unit(rng), rng);
        glm::dvec3 L = test::vectorAtCosine(N, 0.01 + 0.99 * unit(rng), rng);
        if (i % 2) {
            L = glm::normalize(2.0 * glm::dot(N, V) * N - V + 0.004 * glm::dvec3(test::randomUnitVector(rng)));
        }
        if (glm::dot(N, L) < 0.01) {
            continue;
        }
        const MaterialParameters m{glm::vec3(base), float(roughness), 0.5f, float(metallic)};
        const BrdfValueF64 f = evaluateBrdfF64(BrdfModelId::Epic, m, N, V, L);
        const reference::Material rm{{base.x, base.y, base.z}, roughness, 0.5, metallic};
        const reference::Brdf expected =
            reference::brdf(rm, {N.x, N.y, N.z}, {V.x, V.y, V.z}, {L.x, L.y, L.z});
        const glm::dvec3 value = f.diffuse + f.specular;
        const reference::Vec3 e = expected.diffuse + expected.specular;
        for (int c = 0; c < 3; ++c) {
            const double want = c == 0 ? e.x : c == 1 ? e.y : e.z;
            worst = std::max(worst, std::abs(value[c] - want) / want);
        }
    }
    EXPECT_LT(worst, 1e-6);
}

TEST(Guards, LagrangeFormKeepsTheSharpestFp32PeakNearDouble) {
    // fp32 at r = 0.05 near the mirror direction, NoV and NoL >= 0.1. D's standard form loses
    // 1 - NoH^2 to cancellation there (2% at alpha = 0.0025, docs/SHADING.md S2); the |N x H|^2
    // form leaves only the rounding of L and V themselves: 3e-7 rad of H times dlnD/dtheta of
    // up to 1 / alpha = 400 gives a few 1e-4 (measured 4.5e-4).
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
        const Material material{{glm::vec3(0.7f), 0.05f, 0.5f, unit(rng)}, "m"};
        const glm::vec3 V = test::vectorAtCosine(N, 0.1f + 0.9f * unit(rng), rng);
        const glm::vec3 L = glm::normalize(2.0f * glm::dot(N, V) * N - V + 0.004f * test::randomUnitVector(rng));
        if (glm::dot(N, L) < 0.1f) {
            continue;
        }
        const shader::BrdfValue f = evaluateBrdf(BrdfModelId::Epic, surfaceMaterial(material), N, V, L);
        const reference::Brdf expected = reference::brdf(
            test::toReference(material), test::toReference(N), test::toReference(V), test::toReference(L));
        worst = std::max(worst, test::maxRelativeError({f.specular}, {expected.specular}, 1e-3));
    }
    EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace patina
