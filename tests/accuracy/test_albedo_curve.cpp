// BRDF Explorer's albedo view (accuracy/albedo_curve.h): the product's split sum under the white
// furnace against the ground truth's estimate of the same integral.
#include <cstdio>

#include <gtest/gtest.h>

#include "accuracy/albedo_curve.h"

namespace patina {
namespace {

// Under radiance 1 everywhere the split sum's only error is its tables', so it lands within a
// few hundredths of the truth at every angle, for a dielectric and metals rough and smooth; the
// truth's standard error is there and small; a white metal reflects no more than it receives.
TEST(AlbedoCurve, TheSplitSumFollowsTheTruthUnderTheWhiteFurnace) {
    MaterialParameters dielectric;
    dielectric.baseColor = glm::vec3(0.5f, 0.4f, 0.3f);
    dielectric.roughness = 0.5f;
    MaterialParameters roughMetal;
    roughMetal.baseColor = glm::vec3(1.0f);
    roughMetal.metallic = 1.0f;
    roughMetal.roughness = 0.8f;
    MaterialParameters smoothMetal = roughMetal;
    smoothMetal.roughness = 0.15f;
    for (const MaterialParameters& material : {dielectric, roughMetal, smoothMetal}) {
        const std::vector<AlbedoPoint> curve = albedoCurve(material, 7, 512);
        ASSERT_EQ(curve.size(), 7u);
        EXPECT_EQ(curve.front().thetaVDegrees, 0.0f);
        EXPECT_NEAR(curve.back().thetaVDegrees, 88.5f, 1e-4f);
        for (const AlbedoPoint& p : curve) {
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(p.product[c], p.truth[c], 0.03f + 3.0f * p.standardError[c])
                    << material.roughness << " at " << p.thetaVDegrees;
                EXPECT_GT(p.standardError[c], 0.0f);
                // Grazing a smooth metal, the estimator's variance grows: the bars say so.
                EXPECT_LT(p.standardError[c], p.thetaVDegrees < 80.0f ? 0.02f : 0.05f)
                    << material.roughness << " at " << p.thetaVDegrees;
            }
            if (material.metallic == 1.0f) {
                EXPECT_LE(p.truth.x, 1.0f + 3.0f * p.standardError.x);
            }
        }
    }
    // Lambert's share is its colour exactly: at normal incidence a rough dielectric reflects
    // c_diff (0.5) plus a few percent of specular.
    const AlbedoPoint normal = albedoCurve(dielectric, 2, 512).front();
    EXPECT_GT(normal.truth.x, 0.5f);
    EXPECT_LT(normal.truth.x, 0.6f);
}

// Issue 36: the albedo view draws a part's layers. A white dielectric under a full clear coat
// or a white sheen: the truth integrates the layered BRDF (coatedBrdf), the product is the CPU
// twin of shade.frag with its layers; they agree as the bare material's do, and each differs
// from the bare material's own curve by what the layer adds or takes.
TEST(AlbedoCurve, TheCurvesCarryTheLayers) {
    MaterialParameters bare;
    bare.model = BrdfModelId::Gltf;
    bare.baseColor = glm::vec3(0.2f);
    bare.roughness = 0.6f;
    MaterialParameters coated = bare;
    coated.clearcoat = 1.0f;
    coated.clearcoatRoughness = 0.1f;
    MaterialParameters sheened = bare;
    sheened.sheenColor = glm::vec3(1.0f);
    sheened.sheenRoughness = 0.5f;
    const std::vector<AlbedoPoint> plain = albedoCurve(bare, 4, 1024);
    for (const MaterialParameters& material : {coated, sheened}) {
        const std::vector<AlbedoPoint> curve = albedoCurve(material, 4, 1024);
        for (size_t i = 0; i < curve.size(); ++i) {
            const AlbedoPoint& p = curve[i];
            EXPECT_NEAR(p.product.x, p.truth.x, 0.03f + 3.0f * p.standardError.x)
                << material.clearcoat << " at " << p.thetaVDegrees;
            EXPECT_LE(p.truth.x, 1.0f + 3.0f * p.standardError.x);
        }
        // Grazing, over a dark base, the coat's and the fibres' own reflection add more than
        // they take, in the truth and the product alike (at normal view a sheen takes about
        // what it adds).
        const AlbedoPoint& grazing = curve.back();
        EXPECT_GT(grazing.truth.x, plain.back().truth.x + 3.0f * (grazing.standardError.x + plain.back().standardError.x));
        EXPECT_GT(grazing.product.x, plain.back().product.x + 0.02f);
    }
}

// A white thin-walled clear glass of the `gltf` model (KHR_materials_transmission 1).
MaterialParameters whiteGlass() {
    MaterialParameters glass;
    glass.model = BrdfModelId::Gltf;
    glass.baseColor = glm::vec3(1.0f);
    glass.roughness = 0.15f;
    glass.transmission = 1.0f;
    return glass;
}

// Issue 36: a thin-walled glass (KHR_materials_transmission 1, white) under the furnace sends
// most of its light through the wall. The curve splits off that transmitted albedo, the
// product's (the CPU twin's transmission) and the truth's (the BTDF sampled); reflected plus
// transmitted stays at or under 1 in both. The totals agree within the truth's noise up to
// 73.75 degrees (at 88.5 the single-scattering truth keeps 0.87), the transmitted shares up to
// 59 (further out the split sum's grazing reflection, a bare dielectric's too, takes more than
// the truth's: 0.65 against 0.77 through the wall at 73.75, docs/SHADING.md S7).
// The chart draws the transmitted share as its own dashed series.
TEST(AlbedoCurve, AGlassCurveCarriesItsTransmittedAlbedo) {
    MaterialParameters glass = whiteGlass();
    const std::vector<AlbedoPoint> curve = albedoCurve(glass, 7, 2048);
    for (const AlbedoPoint& p : curve) {
        EXPECT_LE(p.product.x, 1.005f) << p.thetaVDegrees;
        // The truth sits on the bound (at 29.5 degrees 300 seeds give 0.9990, spread 0.0033), and
        // at 2048 samples the estimate's standard error reads about a quarter low (its samples'
        // tails): 4 of them, about 3 real ones.
        EXPECT_LE(p.truth.x, 1.0f + 4.0f * p.standardError.x) << p.thetaVDegrees;
        EXPECT_GT(p.productTransmitted.x, 0.0f) << p.thetaVDegrees;
        EXPECT_LT(p.productTransmitted.x, p.product.x) << p.thetaVDegrees;
        if (p.thetaVDegrees < 80.0f) {
            EXPECT_NEAR(p.product.x, p.truth.x, 0.02f + 3.0f * p.standardError.x) << p.thetaVDegrees;
        }
        if (p.thetaVDegrees < 60.0f) {
            EXPECT_NEAR(p.productTransmitted.x, p.truthTransmitted.x, 0.02f + 3.0f * p.standardError.x)
                << p.thetaVDegrees;
        }
    }
    EXPECT_GT(curve.front().productTransmitted.x, 0.9f);   // 1 - F0 at normal incidence, about 0.96
    EXPECT_GT(curve.front().truthTransmitted.x, 0.9f);
    const Chart chart = albedoChart({{"glass", curve}});
    ASSERT_EQ(chart.panels[0].series.size(), 3u);
    EXPECT_EQ(chart.panels[0].series[2].label, "glass: transmitted (split sum)");
    EXPECT_TRUE(chart.panels[0].series[2].dashed);
    EXPECT_EQ(albedoChart({{"bare", albedoCurve(MaterialParameters{}, 2, 64)}}).panels[0].series.size(), 2u);
}

// Issue 36: KHR_materials_sheen's albedo scaling weighs everything beneath the fibres, the light
// through a glass's wall too. A white sheen over a white clear glass under the furnace: the
// sheen's own light plus what it leaves of the reflection and of the transmission stays at or
// under 1, in the product (the CPU twin) and the truth (the ground truth's sheened BRDF and
// BTDF) alike, which agree, their transmitted shares too (both after the sheen's weight);
// without the weight on the transmission both passed 1 by about the sheen's albedo.
TEST(AlbedoCurve, ASheenOverAGlassWeighsItsTransmittedLightToo) {
    MaterialParameters glass = whiteGlass();
    glass.sheenColor = glm::vec3(1.0f);
    glass.sheenRoughness = 0.5f;
    for (const AlbedoPoint& p : albedoCurve(glass, 5, 2048)) {
        EXPECT_LE(p.product.x, 1.005f) << p.thetaVDegrees;
        EXPECT_LE(p.truth.x, 1.0f + 3.0f * p.standardError.x) << p.thetaVDegrees;
        if (p.thetaVDegrees < 80.0f) {
            EXPECT_NEAR(p.product.x, p.truth.x, 0.03f + 3.0f * p.standardError.x) << p.thetaVDegrees;
        }
        if (p.thetaVDegrees < 60.0f) {
            EXPECT_NEAR(p.productTransmitted.x, p.truthTransmitted.x, 0.02f + 3.0f * p.standardError.x)
                << p.thetaVDegrees;
        }
    }
}

// A coat over a glass covers the light through the wall as it covers the base: the ground truth
// weighs it by 1 - clearcoat fr_c as shade.frag does (it used to add it outside the coat, and a
// coated glass's truth came out brighter than its render).
TEST(AlbedoCurve, ACoatOverAGlassCoversItsTransmittedLightToo) {
    MaterialParameters glass = whiteGlass();
    glass.clearcoat = 1.0f;
    glass.clearcoatRoughness = 0.1f;
    for (const AlbedoPoint& p : albedoCurve(glass, 5, 2048)) {
        EXPECT_LE(p.truth.x, 1.0f + 3.0f * p.standardError.x) << p.thetaVDegrees;
        if (p.thetaVDegrees < 60.0f) {
            EXPECT_NEAR(p.product.x, p.truth.x, 0.03f + 3.0f * p.standardError.x) << p.thetaVDegrees;
        }
    }
}

// The chart names each material's two series in full and carries the truth's errors as bars.
TEST(AlbedoCurve, TheChartCarriesTheTruthsErrorBars) {
    MaterialParameters gold;
    gold.baseColor = glm::vec3(1.0f, 0.78f, 0.34f);
    gold.metallic = 1.0f;
    const std::vector<AlbedoPoint> curve = albedoCurve(gold, 5, 128);
    const Chart chart = albedoChart({{"gold", curve}});
    ASSERT_EQ(chart.panels.size(), 1u);
    ASSERT_EQ(chart.panels[0].series.size(), 2u);
    EXPECT_EQ(chart.panels[0].series[0].label, "gold: split sum");
    EXPECT_TRUE(chart.panels[0].series[0].errors.empty());
    const ChartSeries& truth = chart.panels[0].series[1];
    ASSERT_EQ(truth.errors.size(), curve.size());
    for (size_t i = 0; i < curve.size(); ++i) {
        EXPECT_GT(truth.errors[i], 0.0);
        EXPECT_NEAR(truth.points[i].y, 0.2126 * curve[i].truth.r + 0.7152 * curve[i].truth.g + 0.0722 * curve[i].truth.b,
                    1e-5);
    }
}

// A white metal of roughness 0.3 brushed by KHR_materials_anisotropy at `strength`.
MaterialParameters brushedMetal(float strength) {
    MaterialParameters material;
    material.model = BrdfModelId::Gltf;
    material.baseColor = glm::vec3(1.0f);
    material.roughness = 0.3f;
    material.metallic = 1.0f;
    material.anisotropyStrength = strength;
    return material;
}

// The lobe panel's albedo curve under the white furnace integrates the stretched lobe: a brushed
// white metal's truth is below the round one's (the single scattering loses more along t), at
// or under 1; the curve was the round lobe's before.
TEST(AlbedoCurve, AnAnisotropicCurveIntegratesTheStretchedLobe) {
    for (const float thetaV : {0.0f, 60.0f}) {
        const AlbedoPoint round = albedoAt(brushedMetal(0.0f), thetaV, 4000, 7);
        const AlbedoPoint stretched = albedoAt(brushedMetal(1.0f), thetaV, 4000, 7);
        std::printf("theta_v %.0f: truth %.4f +- %.4f (round %.4f), split sum %.4f\n", double(thetaV),
                    double(stretched.truth.y), double(stretched.standardError.y), double(round.truth.y),
                    double(stretched.product.y));
        EXPECT_LT(stretched.truth.y, round.truth.y - 0.05f) << thetaV;
        EXPECT_LE(stretched.truth.y, 1.0f + 3.0f * stretched.standardError.y) << thetaV;
    }
}

}  // namespace
}  // namespace patina
