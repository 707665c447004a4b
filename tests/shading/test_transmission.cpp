// KHR_materials_transmission and KHR_materials_volume, thin-walled (shaders/shared/transmission.glsl,
// docs/SHADING.md S7): the BTDF is glTF's reflection lobe mirrored through the surface, weighed by
// 1 - F and tinted; the volume is Beer-Lambert; under a white environment a white transmissive
// dielectric returns what arrives (about 1 at transmission 1, never above); and the GPU twin's
// light through the wall under an environment holds to the Monte Carlo ground truth, which
// samples the BTDF through the surface.
#include <cmath>
#include <cstdio>
#include <utility>
#include <numbers>

#include <gtest/gtest.h>

#include "environment/environment.h"
#include "reference/radiance.h"
#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "shading/environment_brdf.h"
#include "test_support.h"

namespace patina {
namespace {

glm::vec3 viewAt(float NoV) {
    return {std::sqrt(1.0f - NoV * NoV), 0.0f, NoV};
}

Material glass(glm::vec3 baseColor, float roughness, float transmission) {
    Material material;
    material.model = BrdfModelId::Gltf;
    material.baseColor = baseColor;
    material.roughness = roughness;
    material.metallic = 0.0f;
    material.transmission = transmission;
    return material;
}

TEST(Transmission, TheBtdfIsGltfsReflectionLobeMirroredThroughTheSurface) {
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    const Material m = glass({0.9f, 0.5f, 0.2f}, 0.4f, 0.75f);
    const shader::SurfaceMaterial surface = surfaceMaterial(m);
    const glm::vec3 V = viewAt(0.7f);
    const shader::Transmission t = shader::deriveTransmission(surface, m.transmission, glm::vec3(1.0f), N, V);
    // What passes: transmission (1 - metallic) baseColor.
    EXPECT_NEAR(t.color.x, 0.75f * 0.9f, 1e-6f);
    // A light behind the surface, 40 degrees off -N on V's side: mirrored, it lies in front.
    const double theta = 40.0 * std::numbers::pi / 180.0;
    const glm::dvec3 L(-std::sin(theta) * 0.3, std::sin(theta) * 0.954, -std::cos(theta));
    const glm::dvec3 Ld = glm::normalize(L), Nd(0, 0, 1), Vd = glm::normalize(glm::dvec3(V));
    const glm::dvec3 mirrored = Ld - 2.0 * glm::dot(Nd, Ld) * Nd;
    const glm::dvec3 H = glm::normalize(mirrored + Vd);
    const double alpha = double(surface.alpha), a2 = alpha * alpha;
    const double NoH = H.z, NoV = Vd.z, NoL = mirrored.z, VoH = glm::dot(Vd, H);
    // glTF 2.0 Appendix B: D, the height-correlated V, Schlick's F of F0 0.04.
    const double D = a2 / (std::numbers::pi * std::pow(NoH * NoH * (a2 - 1.0) + 1.0, 2.0));
    const double Vis = 0.5 / (NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2) + NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2));
    const double F = 0.04 + 0.96 * std::pow(1.0 - VoH, 5.0);
    const glm::vec3 f = shader::transmissionBtdf(t, N, V, glm::vec3(Ld));
    for (int c = 0; c < 3; ++c) {
        const double expected = double(t.color[c]) * (1.0 - F) * D * Vis;
        EXPECT_NEAR(f[c], expected, 1e-4 * expected) << c;
    }
    // Nothing from a light in front: that is the reflection's.
    EXPECT_EQ(shader::transmissionBtdf(t, N, V, glm::vec3(mirrored)), glm::vec3(0.0f));
    // The diffuse that stays is 1 - transmission of it.
    const shader::SurfaceMaterial kept = shader::transmissionDiffuse(surface, m.transmission);
    EXPECT_NEAR(kept.diffuseColor.x, 0.25f * surface.diffuseColor.x, 1e-7f);
    EXPECT_EQ(kept.f0, surface.f0);
}

TEST(Transmission, TheVolumeAttenuatesByBeerLambert) {
    const glm::vec3 color(0.5f, 0.25f, 1.0f);
    // T = c^(d / d_at): at d = 2 d_at, c^2.
    const glm::vec3 T = shader::volumeAttenuation(color, 0.5f, 1.0f);
    EXPECT_NEAR(T.x, 0.25f, 1e-6f);
    EXPECT_NEAR(T.y, 0.0625f, 1e-6f);
    EXPECT_NEAR(T.z, 1.0f, 1e-6f);
    // No attenuation at an infinite distance (0) or without a thickness; a black colour is finite.
    EXPECT_EQ(shader::volumeAttenuation(color, 0.0f, 1.0f), glm::vec3(1.0f));
    EXPECT_EQ(shader::volumeAttenuation(color, 0.5f, 0.0f), glm::vec3(1.0f));
    const glm::vec3 black = shader::volumeAttenuation(glm::vec3(0.0f), 1.0f, 0.1f);
    EXPECT_TRUE(std::isfinite(black.x));
    EXPECT_LT(black.x, 0.3f);
    // The node's scale: a uniform 2 doubles the thickness.
    EXPECT_NEAR(thicknessScaleOf(glm::mat4(glm::mat3(2.0f))), 2.0f, 1e-6f);
    MaterialParameters material;
    material.thickness = 1.0f;
    material.attenuationColor = color;
    material.attenuationDistance = 0.5f;
    EXPECT_EQ(volumeAttenuationOf(material), T);
}

// Under a uniform white environment of radiance 1, what the GPU twin shades (the split sum of
// the kept diffuse and the reflection, plus the light through the wall): at most 1 and, at
// transmission 1, about 1, at every roughness and view.
TEST(Transmission, WhiteFurnaceOfAWhiteTransmissiveDielectricIsAtMostOneAndAboutOneWhenClear) {
    const std::shared_ptr<const Environment> white = test::madeEnvironment("builtin:white");
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    for (float roughness : {0.05f, 0.3f, 0.6f, 1.0f}) {
        for (float NoV : {0.2f, 0.6f, 1.0f}) {
            const glm::vec3 V = viewAt(NoV);
            for (float transmission : {0.0f, 0.5f, 1.0f}) {
                const Material m = glass(glm::vec3(1.0f), roughness, transmission);
                const shader::SurfaceMaterial surface = surfaceMaterial(m);
                const shader::Transmission t = shader::deriveTransmission(surface, transmission, glm::vec3(1.0f), N, V);
                const glm::vec3 reflected = shadeEnvironmentOnCpu(BrdfModelId::Gltf,
                                                                  shader::transmissionDiffuse(surface, transmission),
                                                                  *white, 1.0f, 0.0f, N, V);
                const glm::vec3 through = transmissionEnvironmentOnCpu(BrdfModelId::Gltf, surface, t, *white, 1.0f, 0.0f, V);
                const float total = reflected.x + through.x;
                EXPECT_LE(total, 1.01f) << "r " << roughness << " NoV " << NoV << " t " << transmission;
                if (transmission == 1.0f) {
                    EXPECT_NEAR(total, 1.0f, 0.01f) << "r " << roughness << " NoV " << NoV;
                    EXPECT_GT(through.x, 0.4f);   // 0.44 at roughness 1, N.V 0.2
                }
            }
        }
    }
}

// The ground truth (engine/reference/radiance.cpp) samples the BTDF through the surface: the
// difference of a white and a black clear glass (the same seeds: the reflection cancels) is its
// light through the wall, which the GPU twin's prefiltered read along -V must match at roughness
// 0.1 and 0.3: within 4% under a uniform environment (the split's weight against the lobe's own
// 1 - F albedo; measured 0.972-1.011) and 15% under the studio (one read along -V against the
// lobe, as the split sum's own error; measured 0.870-1.074). Rougher, the twin keeps the
// multiple-scattered energy the single-scattering truth loses (1.106-1.163 at 0.5, white): not
// held here. The measured ratios are printed (docs/SHADING.md S7).
TEST(Transmission, UnderAnEnvironmentTheTwinHoldsToTheGroundTruth) {
    const glm::vec3 N = glm::normalize(glm::vec3(0.2f, 0.3f, 0.9f));
    ReferenceOptions options;
    options.samples = 20000;
    options.transmission = 1.0f;
    for (const auto& [source, tolerance] : {std::pair<const char*, float>{"builtin:white", 0.04f}, {"builtin:studio", 0.15f}}) {
        const std::shared_ptr<const Environment> environment = test::madeEnvironment(source);
        const EnvironmentDistribution distribution(environment->image);
        const ReferenceEnvironment reference{environment.get(), &distribution, 1.0f, 30.0f};
        std::mt19937 rng(7);
        for (float roughness : {0.1f, 0.3f}) {
            for (float NoV : {0.5f, 0.9f}) {
                const glm::vec3 V = test::vectorAtCosine(N, NoV, rng);
                const shader::SurfaceMaterial white = surfaceMaterial(glass(glm::vec3(1.0f), roughness, 1.0f));
                const shader::SurfaceMaterial black = surfaceMaterial(glass(glm::vec3(0.0f), roughness, 1.0f));
                const ReferenceEstimate a =
                    referenceRadiance(BrdfModelId::Gltf, white, reference, {}, glm::vec3(0.0f), N, V, options);
                const ReferenceEstimate b =
                    referenceRadiance(BrdfModelId::Gltf, black, reference, {}, glm::vec3(0.0f), N, V, options);
                const shader::Transmission t = shader::deriveTransmission(white, 1.0f, glm::vec3(1.0f), N, V);
                const glm::vec3 twin =
                    transmissionEnvironmentOnCpu(BrdfModelId::Gltf, white, t, *environment, 1.0f, 30.0f, V);
                const float truth = (a.value - b.value).y;
                EXPECT_GT(truth, 0.0f);
                std::printf("%s r %.1f N.V %.1f: twin %.4f truth %.4f (+-%.4f) twin/truth %.3f\n", source,
                            double(roughness), double(NoV), double(twin.y), double(truth),
                            double(a.standardError.y), double(twin.y / truth));
                EXPECT_NEAR(twin.y, truth, tolerance * truth + 3.0f * a.standardError.y)
                    << source << " r " << roughness << " NoV " << NoV;
            }
        }
    }
}

}  // namespace
}  // namespace patina
