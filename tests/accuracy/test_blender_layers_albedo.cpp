// The white furnace of each material of Blender 3.4's layer grid (tests/data/layers/layers.glb;
// issue 36, item 6), as the file is read: the product's split sum (the CPU twin of shade.frag)
// against the ground truth's Monte Carlo integral of the same layered BRDF, within the
// tolerances of the hand-made layers' curves (test_albedo_curve.cpp) but for the product's known
// approximations, measured apart, and each layer's curve apart from its twin's where it shows.
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "accuracy/albedo_curve.h"
#include "gltf/blender_layers.h"
#include "gltf/model_import.h"
#include "shading/shading.h"

namespace patina {
namespace {

using test::BlenderLayer;

constexpr int kPoints = 7, kSamples = 2048;

class BlenderLayersAlbedo : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        model_ = new Model(importGltfModel(test::blenderLayersFile()));
        curves_ = new std::map<int, std::vector<AlbedoPoint>>();
        for (size_t i = 0; i < model_->materials.size(); ++i) {
            (*curves_)[int(i)] = albedoCurve(model_->materials[i].factors, kPoints, kSamples);
        }
    }
    static void TearDownTestSuite() {
        delete curves_;
        delete model_;
    }
    static const std::vector<AlbedoPoint>& curve(BlenderLayer layer) { return curves_->at(layer); }
    static const MaterialParameters& factors(BlenderLayer layer) { return model_->materials[size_t(layer)].factors; }
    static inline Model* model_ = nullptr;
    static inline std::map<int, std::vector<AlbedoPoint>>* curves_ = nullptr;
};

// What the environment's simplified sheen scaling, 1 - max3(c) E(N.V) for every direction
// (docs/SHADING.md S6; the extension's and the Khronos viewer's), keeps of a Lambertian base of
// albedo `base` beyond the extension's min(1 - max3(c) E(N.V), 1 - max3(c) E(N.L)) light by
// light, under the white furnace: base max3(c) 2 integral_0^1 max(0, E(mu) - E(N.V)) mu dmu
// (E capped at 1 as sheen.glsl caps it), by the midpoint rule.
float sheenScalingExcess(float base, glm::vec3 sheenColor, float roughness, float NoV) {
    auto albedo = [&](float mu) { return std::min(shader::sheenAlbedo(mu, roughness), 1.0f); };
    const float atV = albedo(NoV);
    constexpr int kSteps = 400;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const float mu = (float(i) + 0.5f) / float(kSteps);
        sum += std::max(0.0f, albedo(mu) - atV) * mu;
    }
    const float strongest = std::max({sheenColor.r, sheenColor.g, sheenColor.b});
    return base * strongest * float(2.0 * sum / kSteps);
}

// Every sphere's split sum within 0.03 + 3 standard errors of its truth in each channel, and
// reflected plus transmitted at or under 1, from head-on to 44 degrees (the first four of seven
// angles); the glasses' transmitted shares within 0.02 + 3 standard errors, as the hand-made
// glass's. Two departures are the product's own approximations, measured and checked apart:
// the sheen keeps more of its bright red base than the truth by the environment's simplified
// scaling (sheenScalingExcess, about 0.1 head-on), and the rough glass (roughness 0.4) passes
// about 0.03 more than its truth head-on and about 0.05 at 44 degrees, whose single-scattering
// rough BTDF loses that energy (its total checked to 30 degrees only, its share apart). Further out the split sum's grazing reflection, Fdez-Aguera's
// roughness-dependent Fresnel, takes more than the truth (docs/SHADING.md, "Blender's layers").
TEST_F(BlenderLayersAlbedo, EverySpheresSplitSumFollowsItsTruth) {
    for (int layer = test::kPlain; layer <= test::kVolume; ++layer) {
        SCOPED_TRACE(test::kBlenderLayerNames[layer]);
        const MaterialParameters& m = factors(BlenderLayer(layer));
        ASSERT_EQ(curve(BlenderLayer(layer)).size(), size_t(kPoints));
        for (const AlbedoPoint& p : curve(BlenderLayer(layer))) {
            const float NoV = std::cos(glm::radians(p.thetaVDegrees));
            for (int c = 0; c < 3; ++c) {
                EXPECT_LE(p.truth[c], 1.0f + 3.0f * p.standardError[c]) << p.thetaVDegrees;
                EXPECT_LE(p.product[c], 1.005f) << p.thetaVDegrees;
                if (p.thetaVDegrees > 45.0f) {
                    continue;
                }
                if (layer == test::kRoughTransmission && p.thetaVDegrees > 30.0f) {
                    continue;   // its single-scattering loss grows past the tolerance (below)
                }
                const float excess = layer == test::kSheen
                                         ? sheenScalingExcess(m.baseColor[c], m.sheenColor, m.sheenRoughness, NoV)
                                         : 0.0f;
                EXPECT_NEAR(p.product[c] - excess, p.truth[c], 0.03f + 3.0f * p.standardError[c])
                    << c << " at " << p.thetaVDegrees;
                if (m.transmission > 0.0f && layer != test::kRoughTransmission) {
                    EXPECT_NEAR(p.productTransmitted[c], p.truthTransmitted[c], 0.02f + 3.0f * p.standardError[c])
                        << c << " at " << p.thetaVDegrees;
                }
            }
        }
    }
}

// The rough glass's departure goes one way: the product passes more than the single-scattering
// truth (whose rough BTDF loses energy a split sum's 1 - F keeps), the more the rougher and the
// further from the normal: the smooth clear glass (0.1) agrees head-on where the rough one (0.4)
// is about 0.03 above (a quadrature of its f_t: 0.929 x its base 0.95 = 0.883, against the
// product's 0.913), and more at 44 degrees. At 16384 samples, a standard error of about 0.002.
TEST_F(BlenderLayersAlbedo, ARoughGlassPassesMoreThanItsSingleScatteringTruth) {
    const AlbedoPoint smooth = albedoAt(factors(test::kTransmission), 0.0f, 16384, 1);
    EXPECT_NEAR(smooth.productTransmitted.g, smooth.truthTransmitted.g, 0.005f + 3.0f * smooth.standardError.g);
    float below = 0.0f;
    for (float theta : {0.0f, 44.25f}) {
        const AlbedoPoint rough = albedoAt(factors(test::kRoughTransmission), theta, 16384, 1);
        const float gap = rough.productTransmitted.g - rough.truthTransmitted.g;
        EXPECT_GT(gap, 0.02f + 3.0f * rough.standardError.g) << theta;
        EXPECT_GT(gap, below) << theta;
        below = gap;
    }
}

// Where each layer shows in the furnace, in the truth and the product alike: grazing, the coat
// and the sheen add more white than they take from the red base (green, which the base has
// little of); the specular's red-tinted F0 reflects more red than the twin's 0.04 head on.
TEST_F(BlenderLayersAlbedo, EachOpaqueLayerShowsInTheFurnace) {
    const AlbedoPoint& plainGrazing = curve(test::kPlain).back();
    for (BlenderLayer layer : {test::kClearcoat, test::kSheen}) {
        SCOPED_TRACE(test::kBlenderLayerNames[layer]);
        const AlbedoPoint& p = curve(layer).back();
        EXPECT_GT(p.truth.g, plainGrazing.truth.g + 3.0f * (p.standardError.g + plainGrazing.standardError.g));
        EXPECT_GT(p.product.g, plainGrazing.product.g + 0.02f);
    }
    const AlbedoPoint& plain = curve(test::kPlain).front();
    const AlbedoPoint& specular = curve(test::kSpecular).front();
    // The specular's F0 (0.134, 0.058, 0.052) against 0.04: red head on rises (the split sum
    // +0.018, the truth +0.010, deterministic streams), green far less (its F0 rises, its diffuse
    // keeps 1 - the red channel's F: +0.003 and +0.002).
    EXPECT_GT(specular.product.r - plain.product.r, 0.01f);
    EXPECT_GT(specular.product.r - plain.product.r, 3.0f * std::abs(specular.product.g - plain.product.g));
    EXPECT_GT(specular.truth.r, plain.truth.r);
}

// The glasses: most of the light passes the wall head on (1 - F0, less the volume's
// absorption); IOR 2.4 (F0 0.17) passes less than glTF's 1.5 (0.04); the
// volume's attenuation colour (1, 0.6, 0.2) over its thickness passes red, then green, then
// blue.
TEST_F(BlenderLayersAlbedo, EachGlassPassesWhatItsLayersLeave) {
    const AlbedoPoint& clear = curve(test::kTransmission).front();
    EXPECT_GT(clear.truthTransmitted.g, 0.9f);
    EXPECT_GT(clear.productTransmitted.g, 0.9f);
    const AlbedoPoint& ior = curve(test::kIor).front();
    EXPECT_LT(ior.truthTransmitted.g, clear.truthTransmitted.g - 3.0f * (ior.standardError.g + clear.standardError.g));
    EXPECT_LT(ior.productTransmitted.g, clear.productTransmitted.g - 0.02f);
    const AlbedoPoint& volume = curve(test::kVolume).front();
    for (const glm::vec3& t : {volume.truthTransmitted, volume.productTransmitted}) {
        EXPECT_GT(t.r, t.g + 0.1f);
        EXPECT_GT(t.g, t.b + 0.1f);
    }
}

}  // namespace
}  // namespace patina
