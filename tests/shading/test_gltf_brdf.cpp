// The `gltf` model: glTF 2.0's Appendix B BRDF, term by term against the specification's own
// formulas written out here in double precision, and under a white furnace (the split sum with
// Fdez-Aguera's multiple scattering, and the exact integral of the BRDF) at or under 1.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "accuracy/albedo_curve.h"
#include "common/luminance.h"
#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "test_support.h"

namespace patina {
namespace {

// glTF 2.0, Appendix B (B.3.1-B.3.5), for unit N, V, L above the surface: the specular
// V * D with alpha = roughness^2, fresnel_mix of the dielectric (ior 1.5: F0 0.04) over
// Lambert, conductor_fresnel of the metal, mixed by metallic. With KHR_materials_specular (its
// "Implementation"): the dielectric's F0 is min(F0(ior) specularColor, 1) specular, its F90
// specular, and the diffuse keeps 1 - max_value of the dielectric's Fresnel; `f0Color` is
// F0(ior) specularColor before the clamp, `weight` the extension's specular.
struct AppendixB {
    glm::dvec3 diffuse, specular;
};
AppendixB appendixB(glm::dvec3 base, double roughness, double metallic, glm::dvec3 N, glm::dvec3 V, glm::dvec3 L,
                    glm::dvec3 f0Color = glm::dvec3(0.04), double weight = 1.0) {
    const double pi = std::numbers::pi;
    const glm::dvec3 H = glm::normalize(V + L);
    const double NoV = glm::dot(N, V), NoL = glm::dot(N, L), NoH = glm::dot(N, H), VoH = std::abs(glm::dot(V, H));
    const double a2 = std::pow(roughness * roughness, 2.0);
    const double D = a2 * (NoH > 0.0 ? 1.0 : 0.0) / (pi * std::pow(NoH * NoH * (a2 - 1.0) + 1.0, 2.0));
    const double Vis = 0.5 / (NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2) + NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2));
    const double fresnelWeight = std::pow(1.0 - VoH, 5.0);
    const glm::dvec3 dielectricF0 = glm::min(f0Color, glm::dvec3(1.0)) * weight;
    const glm::dvec3 fDielectric = dielectricF0 + (weight - dielectricF0) * fresnelWeight;
    const glm::dvec3 fMetal = base + (1.0 - base) * fresnelWeight;
    const double maxValue = std::max({fDielectric.r, fDielectric.g, fDielectric.b});
    const glm::dvec3 dielectricDiffuse = (1.0 - maxValue) * base / pi;
    const glm::dvec3 specular = ((1.0 - metallic) * fDielectric + metallic * fMetal) * (Vis * D);
    return {(1.0 - metallic) * dielectricDiffuse, specular};
}

double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-12); }

TEST(GltfBrdf, IsAppendixBTermByTermInEveryPrecision) {
    std::mt19937 rng(35);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    double worst32 = 0.0, worst64 = 0.0;
    for (int i = 0; i < 4000; ++i) {
        const glm::vec3 base(unit(rng), unit(rng), unit(rng));
        // Above the roughness floor (0.045, brdf.glsl), where the two are the same function.
        const float roughness = 0.05f + 0.95f * unit(rng), metallic = i % 4 == 0 ? 0.0f : i % 4 == 1 ? 1.0f : unit(rng);
        const glm::vec3 N = test::randomUnitVector(rng);
        const glm::vec3 V = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        const glm::vec3 L = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        // Unit in double: off by a float's rounding, 1 - NoH^2 and |N x H|^2 part near D's peak.
        const glm::dvec3 n = glm::normalize(glm::dvec3(N)), v = glm::normalize(glm::dvec3(V)), l = glm::normalize(glm::dvec3(L));
        const AppendixB expected = appendixB(base, roughness, metallic, n, v, l);
        const shader::SurfaceMaterial m = shader::deriveSurfaceMaterial(base, roughness, 0.5f, metallic);
        const shader::BrdfValue f32 = evaluateBrdf(BrdfModelId::Gltf, m, N, V, L);
        MaterialParameters parameters;
        parameters.baseColor = base;
        parameters.roughness = roughness;
        parameters.metallic = metallic;
        const BrdfValueF64 f64 = evaluateBrdfF64(BrdfModelId::Gltf, parameters, n, v, l);
        for (int c = 0; c < 3; ++c) {
            // The diffuse apart: fresnel_mix weighs it by the dielectric's F alone.
            if (expected.diffuse[c] > 1e-6) {
                worst32 = std::max(worst32, relative(f32.diffuse[c], expected.diffuse[c]));
                worst64 = std::max(worst64, relative(f64.diffuse[c], expected.diffuse[c]));
            }
            worst32 = std::max(worst32, relative(f32.specular[c], expected.specular[c]));
            worst64 = std::max(worst64, relative(f64.specular[c], expected.specular[c]));
        }
    }
    EXPECT_LT(worst32, 2e-4);   // fp32 rounding, amplified near the peak of D
    EXPECT_LT(worst64, 2e-7);   // the shared constants are float literals (pi, 0.08): ~3e-8 each
}

// KHR_materials_specular and _ior on the same BRDF: Patina's 0.08 specular tint is the
// extension's F0(ior) specularColor (gltf/material.h), its weight the extension's specular. A
// coloured F0, one past 0.08 (an ior of 2.4), one clamped at 1, a weight of 0 and between,
// on dielectrics, metals and their mix; fp32 and fp64.
TEST(GltfBrdf, IsKhrMaterialsSpecularsFresnelMixInEveryPrecision) {
    std::mt19937 rng(36);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const glm::vec3 tints[] = {glm::vec3(1.0f, 0.6f, 0.2f), glm::vec3(2.12f), glm::vec3(12.5f, 3.0f, 0.0f),
                               glm::vec3(0.3f, 1.0f, 0.7f)};
    double worst32 = 0.0, worst64 = 0.0;
    for (int i = 0; i < 4000; ++i) {
        MaterialParameters p;
        p.model = BrdfModelId::Gltf;
        p.baseColor = glm::vec3(unit(rng), unit(rng), unit(rng));
        p.roughness = 0.05f + 0.95f * unit(rng);
        p.metallic = i % 3 == 0 ? 0.0f : i % 3 == 1 ? 1.0f : unit(rng);
        p.specular = i % 2 == 0 ? 1.0f : unit(rng);
        p.specularTint = tints[size_t(i) % std::size(tints)];
        p.specularWeight = i % 5 == 0 ? 0.0f : i % 5 == 1 ? 1.0f : unit(rng);
        const glm::vec3 N = test::randomUnitVector(rng);
        const glm::vec3 V = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        const glm::vec3 L = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        const glm::dvec3 n = glm::normalize(glm::dvec3(N)), v = glm::normalize(glm::dvec3(V)), l = glm::normalize(glm::dvec3(L));
        const glm::dvec3 f0Color = 0.08 * double(p.specular) * glm::dvec3(p.specularTint);
        const AppendixB expected = appendixB(p.baseColor, p.roughness, p.metallic, n, v, l, f0Color, p.specularWeight);
        const shader::BrdfValue f32 = evaluateBrdf(BrdfModelId::Gltf, surfaceMaterial(p), N, V, L);
        const BrdfValueF64 f64 = evaluateBrdfF64(BrdfModelId::Gltf, p, n, v, l);
        for (int c = 0; c < 3; ++c) {
            // The diffuse against what it would be with nothing reflected: an F0 clamped at 1 leaves
            // it 0, where the fp32 literal 0.08f's 12.5-fold (0.99999998) leaves 4e-9.
            const double scale = std::max((1.0 - p.metallic) * p.baseColor[c] / std::numbers::pi, 1e-6);
            worst32 = std::max(worst32, std::abs(f32.diffuse[c] - expected.diffuse[c]) / scale);
            worst64 = std::max(worst64, std::abs(f64.diffuse[c] - expected.diffuse[c]) / scale);
            const double specularScale = std::max(expected.specular[c], 1e-6);
            worst32 = std::max(worst32, std::abs(f32.specular[c] - expected.specular[c]) / specularScale);
            worst64 = std::max(worst64, std::abs(f64.specular[c] - expected.specular[c]) / specularScale);
        }
    }
    EXPECT_LT(worst32, 2e-4);
    EXPECT_LT(worst64, 2e-7);
}

// The tint colours F0 channel by channel and the diffuse keeps 1 - the largest channel's F (the
// extension's max_value), not 1 - F per channel: a red-tinted reflection does not turn the
// diffuse cyan. The weight takes F90 down with F0: 0 leaves the bare diffuse.
TEST(GltfBrdf, ASpecularTintColoursTheReflectionAndTheDiffuseLosesItsLargestChannel) {
    const glm::vec3 N(0, 0, 1), V = glm::normalize(glm::vec3(0.6f, 0.0f, 0.8f)), L = glm::normalize(glm::vec3(-0.3f, 0.2f, 0.9f));
    MaterialParameters white;
    white.model = BrdfModelId::Gltf;
    white.baseColor = glm::vec3(1.0f);
    white.roughness = 0.5f;
    MaterialParameters red = white;
    red.specularTint = glm::vec3(1.0f, 0.2f, 0.2f);
    const shader::BrdfValue plain = evaluateBrdf(BrdfModelId::Gltf, surfaceMaterial(white), N, V, L);
    const shader::BrdfValue tinted = evaluateBrdf(BrdfModelId::Gltf, surfaceMaterial(red), N, V, L);
    EXPECT_FLOAT_EQ(tinted.specular.r, plain.specular.r);
    EXPECT_LT(tinted.specular.g, 0.9f * plain.specular.g);
    EXPECT_FLOAT_EQ(tinted.diffuse.g, tinted.diffuse.r);   // grey: 1 - max_value
    EXPECT_FLOAT_EQ(tinted.diffuse.r, plain.diffuse.r);
    MaterialParameters none = white;
    none.specularWeight = 0.0f;
    const shader::BrdfValue bare = evaluateBrdf(BrdfModelId::Gltf, surfaceMaterial(none), N, V, L);
    EXPECT_EQ(bare.specular, glm::vec3(0.0f));
    EXPECT_FLOAT_EQ(bare.diffuse.r, 1.0f / std::numbers::pi_v<float>);
}

TEST(GltfBrdf, DiffersFromEpicInEachOfItsThreeTerms) {
    // One configuration, every term of the two models: epic's diffuse takes nothing for the
    // specular, its V is Schlick-GGX and its F the spherical-Gaussian fit.
    const glm::vec3 N(0, 0, 1), V = glm::normalize(glm::vec3(0.6f, 0.0f, 0.8f)), L = glm::normalize(glm::vec3(-0.3f, 0.2f, 0.9f));
    const shader::SurfaceMaterial m = shader::deriveSurfaceMaterial(glm::vec3(0.5f), 0.5f, 0.5f, 0.0f);
    const shader::SpecularTerms gltf = specularTerms(BrdfModelId::Gltf, m, N, V, L);
    const shader::SpecularTerms epic = specularTerms(BrdfModelId::Epic, m, N, V, L);
    EXPECT_FLOAT_EQ(gltf.D, epic.D);
    EXPECT_GT(std::abs(gltf.Vis / epic.Vis - 1.0f), 1e-3f);
    EXPECT_GT(std::abs(gltf.F.x / epic.F.x - 1.0f), 1e-4f);
    const float diffuseRatio = evaluateBrdf(BrdfModelId::Gltf, m, N, V, L).diffuse.x /
                               evaluateBrdf(BrdfModelId::Epic, m, N, V, L).diffuse.x;
    EXPECT_NEAR(diffuseRatio, 1.0f - gltf.F.x, 1e-6f);   // 1 - F of the dielectric (metallic 0)
}

// Under a uniform white environment of radiance 1 (the albedo view's furnace): what the split
// sum shows stays at or under 1 for a white dielectric and a white metal at every roughness and
// view angle (a white metal 1, its multiple scattering added back by Fdez-Aguera 2019; a white
// dielectric 1, its diffuse getting what the specular's directional albedo leaves). The BRDF
// integrated exactly: the metal's single scattering under 1; the dielectric's fresnel_mix
// weighs the diffuse by 1 - F(VoH) light by light, which at a grazing view keeps almost all of
// it while the specular reflects F(NoV): Appendix B itself gives more than 1 there (1.2 at
// mu = 0.25, r = 0), and the ground truth shows it.
TEST(GltfBrdf, WhiteFurnaceOfTheSplitSumStaysAtOrUnderOne) {
    for (float metallic : {0.0f, 1.0f}) {
        for (int ri = 0; ri <= 10; ri += 2) {
            MaterialParameters white;
            white.model = BrdfModelId::Gltf;
            white.baseColor = glm::vec3(1.0f);
            white.metallic = metallic;
            white.roughness = float(ri) / 10.0f;
            for (const AlbedoPoint& p : albedoCurve(white, 7, 512)) {
                const std::string what = (metallic > 0.0f ? "metal" : "dielectric") + std::string(" r ") +
                                         std::to_string(white.roughness) + " theta " + std::to_string(p.thetaVDegrees);
                EXPECT_LE(luminance(p.product), 1.0f + 1e-3f) << what;
                EXPECT_GE(luminance(p.product), 0.99f) << what;
                if (metallic > 0.0f || p.thetaVDegrees < 30.0f) {
                    EXPECT_LE(luminance(p.truth), 1.0f + 4.0f * luminance(p.standardError) + 1e-3f) << what;
                }
            }
        }
    }
    // KHR_materials_specular's: a gem-bright tinted F0 (0.24, 0.08, 0.016) and a weight of 0.6
    // (the split sum's FssEss and F_avg both weighted), every channel at or under 1 and the
    // split sum on its truth up to the grazing angles where the dielectric's differs anyway.
    for (int ri = 0; ri <= 5; ri += 5) {   // at roughness 1 the truth lacks the multiple scattering
        MaterialParameters gem;
        gem.model = BrdfModelId::Gltf;
        gem.baseColor = glm::vec3(1.0f);
        gem.roughness = float(ri) / 10.0f;
        gem.specular = 1.0f;
        gem.specularTint = glm::vec3(3.0f, 1.0f, 0.2f);
        gem.specularWeight = 0.6f;
        for (const AlbedoPoint& p : albedoCurve(gem, 5, 1024)) {
            const std::string what = "gem r " + std::to_string(gem.roughness) + " theta " + std::to_string(p.thetaVDegrees);
            for (int c = 0; c < 3; ++c) {
                EXPECT_LE(p.product[c], 1.0f + 1e-3f) << what << " channel " << c;
                if (p.thetaVDegrees < 50.0f) {
                    EXPECT_LE(p.truth[c], 1.0f + 4.0f * p.standardError[c] + 1e-3f) << what << " channel " << c;
                    EXPECT_NEAR(p.product[c], p.truth[c], 0.02f + 4.0f * p.standardError[c]) << what << " channel " << c;
                }
            }
        }
    }
    MaterialParameters glossy;
    glossy.model = BrdfModelId::Gltf;
    glossy.baseColor = glm::vec3(1.0f);
    glossy.metallic = 0.0f;
    glossy.roughness = 0.0f;
    const AlbedoPoint grazing = albedoAt(glossy, 75.5f, 2048, 7);   // mu = 0.25
    EXPECT_GT(luminance(grazing.truth) - 4.0f * luminance(grazing.standardError), 1.1f);
}

}  // namespace
}  // namespace patina
