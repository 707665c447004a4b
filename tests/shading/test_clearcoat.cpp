// KHR_materials_clearcoat, the `gltf` model's coat (shaders/shared/clearcoat.glsl): term by term
// against the extension's formulas written out here in double precision, in fp32 and fp64, and
// under a white furnace (a coat over a white base reflects at most what arrives, and the base
// gets 1 - clearcoat fr_c of it).
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "common/luminance.h"
#include "shading/brdf_models.h"
#include "shading/environment_brdf.h"
#include "shading/shading.h"
#include "shading/shading_f64.h"
#include "test_support.h"

namespace patina {
namespace {

// The extension's fresnel_coat for unit N_c, V, L above the coat: the layer's term
// clearcoat fr_c D V (specular_brdf with alpha_c = roughness^2 on N_c, glTF 2.0 Appendix B.3.2)
// and the base's weight 1 - clearcoat fr_c, fr_c = 0.04 + 0.96 (1 - |V.N_c|)^5.
struct Coat {
    double layer, baseWeight, fresnel;
};
Coat extensionCoat(double factor, double roughness, glm::dvec3 N, glm::dvec3 V, glm::dvec3 L) {
    const double pi = std::numbers::pi;
    const glm::dvec3 H = glm::normalize(V + L);
    const double NoV = glm::dot(N, V), NoL = glm::dot(N, L), NoH = glm::dot(N, H);
    const double a2 = std::pow(roughness * roughness, 2.0);
    const double D = a2 / (pi * std::pow(NoH * NoH * (a2 - 1.0) + 1.0, 2.0));
    const double Vis = 0.5 / (NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2) + NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2));
    const double fresnel = 0.04 + 0.96 * std::pow(1.0 - std::abs(NoV), 5.0);
    return {factor * fresnel * D * Vis, 1.0 - factor * fresnel, fresnel};
}

double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-12); }

TEST(Clearcoat, IsTheExtensionsLayerTermByTermInFp32AndFp64) {
    std::mt19937 rng(36);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    double worst32 = 0.0, worst64 = 0.0, worstWeight32 = 0.0;
    for (int i = 0; i < 4000; ++i) {
        const float factor = unit(rng);
        const float roughness = 0.05f + 0.95f * unit(rng);   // above the floor (0.045)
        const glm::vec3 N = test::randomUnitVector(rng);
        const glm::vec3 V = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        const glm::vec3 L = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        const glm::dvec3 n = glm::normalize(glm::dvec3(N)), v = glm::normalize(glm::dvec3(V)), l = glm::normalize(glm::dvec3(L));
        const Coat expected = extensionCoat(factor, roughness, n, v, l);
        const shader::Clearcoat coat32 = shader::deriveClearcoat(factor, roughness, N, V);
        const shader_f64::Clearcoat coat64 = shader_f64::deriveClearcoat(factor, roughness, n, v);
        if (expected.layer > 1e-9) {
            worst32 = std::max(worst32, relative(shader::clearcoatBrdf(coat32, V, L), expected.layer));
            worst64 = std::max(worst64, relative(shader_f64::clearcoatBrdf(coat64, v, l), expected.layer));
        }
        worstWeight32 = std::max(worstWeight32, std::abs(double(shader::clearcoatBaseWeight(coat32)) - expected.baseWeight));
        EXPECT_NEAR(shader_f64::clearcoatBaseWeight(coat64), expected.baseWeight, 1e-7);
        // With the cosine N_c.L, from a light of radiance 1.
        EXPECT_NEAR(shader::clearcoatFromDirection(glm::vec3(1.0f), L, coat32, V).x, expected.layer * glm::dot(n, l),
                    2e-4 * expected.layer + 1e-7);
    }
    EXPECT_LT(worst32, 2e-4);   // fp32 rounding, amplified near the peak of D
    EXPECT_LT(worst64, 2e-7);   // the shared constants are float literals
    EXPECT_LT(worstWeight32, 1e-6);
}

// coated = mix(material, coat_brdf, clearcoat fr_c) under one light, the coat on the same normal:
// the base's Appendix B value (the model's evaluateBrdf) weighed, the coat's lobe added.
TEST(Clearcoat, CoatsTheGltfMaterialAsTheExtensionMixesIt) {
    const glm::vec3 N(0, 0, 1), V = glm::normalize(glm::vec3(0.6f, 0.0f, 0.8f)), L = glm::normalize(glm::vec3(-0.5f, 0.1f, 0.86f));
    const shader::SurfaceMaterial base = shader::deriveSurfaceMaterial(glm::vec3(0.5f, 0.02f, 0.01f), 0.44f, 0.5f, 0.0f);
    const shader::Clearcoat coat = shader::deriveClearcoat(1.0f, 0.03f, N, V);
    const shader::BrdfValue f = evaluateBrdf(BrdfModelId::Gltf, base, N, V, L);
    const glm::vec3 material = f.diffuse + f.specular;
    const float fr = shader::clearcoatFresnel(glm::dot(N, V));
    const glm::vec3 expected = glm::mix(material, glm::vec3(shader::clearcoatBrdf(coat, V, L) / fr), fr) * glm::dot(N, L);
    const glm::vec3 coated = shader::clearcoatOver(material * glm::dot(N, L), shader::clearcoatFromDirection(glm::vec3(1.0f), L, coat, V), coat);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(coated[c], expected[c], 1e-6f * (1.0f + expected[c]));
    }
    EXPECT_NEAR(fr, 0.04f + 0.96f * std::pow(1.0f - 0.8f, 5.0f), 1e-6f);
}

// The directional albedo of a lobe, E(V) = integral of f N.L over the hemisphere, by GGX
// importance sampling of `alpha` (f N.L / pdf, pdf = D N.H / (4 V.H)) on a Hammersley set.
template <typename F>
double albedo(F brdf, float alpha, glm::vec3 N, glm::vec3 V, unsigned samples = 1u << 14) {
    double sum = 0.0;
    for (unsigned i = 0; i < samples; ++i) {
        const glm::vec3 H = shader::importanceSampleGGX(shader::hammersley(i, samples), alpha, N);
        const float VoH = glm::dot(V, H);
        const glm::vec3 L = 2.0f * VoH * H - V;
        const float NoL = glm::dot(N, L), NoH = glm::dot(N, H);
        if (NoL <= 0.0f || VoH <= 0.0f || NoH <= 0.0f) {
            continue;
        }
        const double pdf = double(shader::D_GGX(NoH, glm::cross(N, H), alpha)) * NoH / (4.0 * VoH);
        sum += double(brdf(L)) * std::min(NoL, 1.0f) / pdf;
    }
    return sum / double(samples);
}

// A white furnace: a coat of factor 1 over a white metal (whose single scattering stays under 1,
// docs/SHADING.md S4) reflects at most what arrives, at every coat roughness and view angle:
// the coat reflects fr_c times its lobe's albedo (at most fr_c), and the base, weighed by
// 1 - fr_c, gets what the coat does not reflect.
TEST(Clearcoat, WhiteFurnaceOfACoatOverAWhiteBaseStaysAtOrUnderOne) {
    const glm::vec3 N(0, 0, 1);
    const shader::SurfaceMaterial white = shader::deriveSurfaceMaterial(glm::vec3(1.0f), 0.3f, 0.5f, 1.0f);
    for (float mu : {1.0f, 0.7f, 0.4f, 0.2f}) {
        const glm::vec3 V(std::sqrt(1.0f - mu * mu), 0.0f, mu);
        const double base = albedo([&](glm::vec3 L) { return luminance(evaluateBrdf(BrdfModelId::Gltf, white, N, V, L).specular); },
                                   white.alpha, N, V);
        for (float roughness : {0.05f, 0.3f, 0.6f, 1.0f}) {
            const shader::Clearcoat coat = shader::deriveClearcoat(1.0f, roughness, N, V);
            const double layer = albedo([&](glm::vec3 L) { return shader::clearcoatBrdf(coat, V, L); }, coat.alpha, N, V);
            const std::string what = "mu " + std::to_string(mu) + " coat roughness " + std::to_string(roughness);
            EXPECT_LE(layer, coat.fresnel * (1.0 + 1e-3)) << what;
            EXPECT_GT(layer, 0.3 * coat.fresnel) << what;
            // The base gets 1 - clearcoat fr_c of the light: the coated albedo is the sum.
            const double coated = base * shader::clearcoatBaseWeight(coat) + layer;
            EXPECT_NEAR(shader::clearcoatBaseWeight(coat), 1.0f - coat.fresnel, 1e-7f) << what;
            EXPECT_LE(base, 1.0 + 1e-3) << what;
            EXPECT_LE(coated, 1.0 + 1e-3) << what;
        }
    }
}

// Under an environment, the Khronos viewer's split sum: LD(R_c, r_c) (0.04 A + B) times the
// factor, with the model's own (A, B) at (N_c.V, r_c). A uniform white environment of
// radiance 1 gives the table's value itself.
TEST(Clearcoat, UnderAnEnvironmentIsTheSplitSumOfTheCoat) {
    const glm::vec3 N(0, 0, 1);
    const auto white = [](glm::vec3, float) { return glm::vec3(1.0f); };
    for (float mu : {1.0f, 0.5f, 0.1f}) {
        const glm::vec3 V(std::sqrt(1.0f - mu * mu), 0.0f, mu);
        for (float roughness : {0.1f, 0.5f, 0.9f}) {
            const shader::Clearcoat coat = shader::deriveClearcoat(0.5f, roughness, N, V);
            const glm::vec2 ab = environmentBrdf(BrdfModelId::Gltf, mu, roughness);
            const glm::vec3 shown = clearcoatEnvironment(BrdfModelId::Gltf, white, 5.0f, 2.0f, 30.0f, coat, V);
            EXPECT_NEAR(shown.x, 2.0f * 0.5f * (0.04f * ab.x + ab.y), 1e-5f);
            EXPECT_LE(shown.x / 2.0f, 0.5f);
        }
    }
}

}  // namespace
}  // namespace patina
