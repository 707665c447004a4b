// The lobe views with layers (issue 36): evaluateLobe's samples under a clear coat and a sheen
// (shading/layered_brdf.h), the same composition the ground truth integrates; a transmission's
// lobe through the wall beneath them as the renderer adds it, in the polar lobe and the slice.
// A bare material's lobe and its CSV are what they always were.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "reference/radiance.h"
#include "shading/brdf_models.h"
#include "shading/brdf_slice.h"
#include "shading/cpu_shading.h"
#include "shading/layered_brdf.h"
#include "shading/lobe.h"

namespace patina {
namespace {

constexpr int kSamples = 181;   // one a degree: sample i at i - 90 degrees

MaterialParameters gltfBase() {
    MaterialParameters material;
    material.model = BrdfModelId::Gltf;
    material.baseColor = {0.5f, 0.1f, 0.1f};
    material.roughness = 0.5f;
    return material;
}

TEST(LayeredLobe, ABareMaterialHasNoLayersAndItsCsvIsUnchanged) {
    const MaterialParameters bare = gltfBase();
    const std::vector<LobeSample> lobe = evaluateLobe(bare, 30.0f, kSamples);
    const shader::SurfaceMaterial surface = surfaceMaterial(bare);
    for (const LobeSample& sample : lobe) {
        EXPECT_EQ(sample.layers, glm::vec3(0.0f));
        const float t = glm::radians(sample.thetaOutDegrees);
        const shader::BrdfValue f = evaluateBrdf(bare.model, surface, {0, 0, 1}, {std::sin(t), 0, std::cos(t)},
                                                 {std::sin(glm::radians(30.0f)), 0, std::cos(glm::radians(30.0f))});
        EXPECT_EQ(sample.diffuse, f.diffuse);
        EXPECT_EQ(sample.specular, f.specular);
    }
    EXPECT_EQ(formatLobeCsv(lobe).substr(0, formatLobeCsv(lobe).find('\n')),
              "theta_out_deg,diffuse_r,diffuse_g,diffuse_b,specular_r,specular_g,specular_b,total_r,total_g,total_b");
}

// KHR_materials_clearcoat: the base's lobes are what 1 - clearcoat fr_c(N.V) lets through, and
// the coat's own lobe peaks at the mirror direction, over the rough base's there.
TEST(LayeredLobe, ACoatWeighsTheBaseByItsFresnelAndAddsItsMirrorLobe) {
    const MaterialParameters bare = gltfBase();
    MaterialParameters coated = bare;
    coated.clearcoat = 1.0f;
    coated.clearcoatRoughness = 0.05f;
    const std::vector<LobeSample> under = evaluateLobe(bare, 30.0f, kSamples);
    const std::vector<LobeSample> lobe = evaluateLobe(coated, 30.0f, kSamples);
    for (size_t i = 10; i + 10 < lobe.size(); ++i) {
        const float NoV = std::cos(glm::radians(lobe[i].thetaOutDegrees));
        const float through = 1.0f - shader::clearcoatFresnel(NoV);
        EXPECT_NEAR(lobe[i].diffuse.r, under[i].diffuse.r * through, 1e-6f * under[i].diffuse.r) << i;
        EXPECT_NEAR(lobe[i].specular.r, under[i].specular.r * through, 1e-5f * under[i].specular.r + 1e-9f) << i;
        EXPECT_EQ(lobe[i].total(), lobe[i].diffuse + lobe[i].specular + lobe[i].layers);
    }
    const LobeSample& mirror = lobe[60];   // -30 degrees
    ASSERT_EQ(mirror.thetaOutDegrees, -30.0f);
    EXPECT_GT(mirror.layers.r, 10.0f * mirror.specular.r);
    EXPECT_GT(mirror.layers.r, 100.0f * lobe[120].layers.r) << "the coat's lobe is narrow";
    const std::string csv = formatLobeCsv(lobe);
    EXPECT_NE(csv.find("layers_r,layers_g,layers_b,total_r"), std::string::npos);
}

// KHR_materials_sheen: the fibres' lobe grows towards grazing, and takes from the base there.
TEST(LayeredLobe, ASheenGrowsTowardsGrazingAndTakesFromTheBase) {
    const MaterialParameters bare = gltfBase();
    MaterialParameters sheened = bare;
    sheened.sheenColor = glm::vec3(1.0f);
    sheened.sheenRoughness = 0.4f;
    const std::vector<LobeSample> under = evaluateLobe(bare, 30.0f, kSamples);
    const std::vector<LobeSample> lobe = evaluateLobe(sheened, 30.0f, kSamples);
    EXPECT_GT(lobe[175].layers.r, 5.0f * lobe[90].layers.r) << "85 degrees against normal";
    for (size_t i = 1; i + 1 < lobe.size(); ++i) {
        EXPECT_LE(lobe[i].diffuse.r, under[i].diffuse.r) << i;
        EXPECT_GE(lobe[i].layers.r, 0.0f) << i;
    }
    EXPECT_LT(lobe[175].diffuse.r, under[175].diffuse.r);
}

// BRDF Explorer's slice of a coated material: the coat's narrow lobe at theta_h = 0 in the
// specular and total slices, the diffuse slice the base's through the coat (a bare material's
// slices are unchanged: ALambertLobe... in test_brdf_slice.cpp).
TEST(LayeredLobe, TheSliceShowsTheCoatsLobeAtThetaHZero) {
    MaterialParameters coated = gltfBase();
    coated.roughness = 0.7f;
    MaterialParameters bare = coated;
    coated.clearcoat = 1.0f;
    coated.clearcoatRoughness = 0.15f;
    const int size = 32;
    const BrdfSlice plain = brdfSlice(bare, 90.0f, size, SliceLobe::Specular);
    const BrdfSlice layered = brdfSlice(coated, 90.0f, size, SliceLobe::Specular);
    const BrdfSlice diffuse = brdfSlice(coated, 90.0f, size, SliceLobe::Diffuse);
    const BrdfSlice plainDiffuse = brdfSlice(bare, 90.0f, size, SliceLobe::Diffuse);
    float layeredPeak = 0.0f, plainPeak = 0.0f;
    for (size_t i = 0; i < layered.values.size(); ++i) {
        layeredPeak = std::max(layeredPeak, layered.values[i].g);
        plainPeak = std::max(plainPeak, plain.values[i].g);
        if (plainDiffuse.values[i].r > 0.0f) {   // above the horizon
            EXPECT_LT(diffuse.values[i].r, plainDiffuse.values[i].r) << i;
        }
    }
    EXPECT_GT(layeredPeak, 10.0f * plainPeak);
    // The peak lies in the first column, theta_h = 0.
    size_t peak = 0;
    for (size_t i = 0; i < layered.values.size(); ++i) {
        peak = layered.values[i].g > layered.values[peak].g ? i : peak;
    }
    EXPECT_EQ(peak % size_t(size), 0u);
}

// KHR_materials_transmission, thin-walled (issue 36): the lobe below the surface is
// transmission.glsl's f_t from L towards (sin t_out, 0, -cos t_out), peaking straight through
// (at -L: t_out = -theta_in) with the reflection's mirrored shape, tinted by the base colour;
// the reflected diffuse keeps 1 - t of itself, the specular is untouched; the CSV carries the
// transmitted columns after total. A bare material's lobe has none (the test above).
TEST(LayeredLobe, AGlassHasItsTransmittedLobeBelowTheSurface) {
    MaterialParameters bare = gltfBase();
    bare.roughness = 0.2f;
    MaterialParameters glass = bare;
    glass.transmission = 0.75f;
    const std::vector<LobeSample> under = evaluateLobe(bare, 30.0f, kSamples);
    const std::vector<LobeSample> lobe = evaluateLobe(glass, 30.0f, kSamples);
    const glm::vec3 N(0, 0, 1), L(std::sin(glm::radians(30.0f)), 0, std::cos(glm::radians(30.0f)));
    const shader::Transmission t =
        shader::deriveTransmission(surfaceMaterial(glass), 0.75f, glm::vec3(1.0f), N, L);
    for (size_t i = 0; i < lobe.size(); ++i) {
        const float o = glm::radians(lobe[i].thetaOutDegrees);
        EXPECT_EQ(lobe[i].transmitted, shader::transmissionBtdf(t, N, L, {std::sin(o), 0, -std::cos(o)})) << i;
        EXPECT_NEAR(lobe[i].diffuse.r, 0.25f * under[i].diffuse.r, 1e-6f) << i;
        EXPECT_EQ(lobe[i].specular, under[i].specular) << i;
        EXPECT_EQ(under[i].transmitted, glm::vec3(0.0f)) << i;
    }
    const auto peak = std::max_element(lobe.begin(), lobe.end(), [](const LobeSample& a, const LobeSample& b) {
        return a.transmitted.r < b.transmitted.r;
    });
    EXPECT_NEAR(peak->thetaOutDegrees, -30.0f, 2.0f);   // the off-peak shift of Vis, at most a degree or two
    EXPECT_NEAR(peak->transmitted.r / peak->transmitted.g, 5.0f, 1e-4f);   // tinted by the base colour, 0.5 / 0.1
    const std::string csv = formatLobeCsv(lobe);
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "theta_out_deg,diffuse_r,diffuse_g,diffuse_b,specular_r,specular_g,specular_b,total_r,total_g,total_b,"
              "transmitted_r,transmitted_g,transmitted_b");
}

// The transmitted lobe of the lobe views beneath the layers, and in the slice (issue 36).
MaterialParameters glass() {
    MaterialParameters material = gltfBase();
    material.roughness = 0.3f;
    material.transmission = 0.8f;
    return material;
}

MaterialParameters coated(MaterialParameters material) {
    material.clearcoat = 1.0f;
    material.clearcoatRoughness = 0.1f;
    return material;
}

MaterialParameters sheened(MaterialParameters material) {
    material.sheenColor = {0.9f, 0.7f, 0.5f};
    material.sheenRoughness = 0.5f;
    return material;
}

// The ground truth's radiance towards V of a directional light of radiance 1 arriving along
// `fromBehind` (below the surface, N = z), nothing else lighting the point: the light through the
// wall alone (the reflected lobes and the layers' own take nothing from behind), under the layers
// as the renderer puts it there.
glm::vec3 truthThroughTheWall(const MaterialParameters& material, glm::vec3 V, glm::vec3 fromBehind) {
    shader::PackedLight light{};
    light.type = shader::LIGHT_DIRECTIONAL;
    light.radiance = glm::vec3(1.0f);
    light.directionToLight = fromBehind;
    return referenceRadiance(material.model, surfaceMaterial(material), ReferenceEnvironment{}, {light},
                             glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f), V, withLayersOf({}, material))
        .value;
}

void expectRelativelyNear(glm::vec3 got, glm::vec3 want, const std::string& what) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], want[c], 1e-5f * want[c] + 1e-9f) << what << ", channel " << c;
    }
}

// A coated and a sheened glass's lobe below the surface is the bare glass's weighed by what the
// renderer weighs it by: the polar lobe's transmitted value at each t_out, lit by the light
// behind at that direction with its back-side cosine, is the ground truth's radiance there; the
// coat and the sheen lower it by the truth's own factor. Before, the lobe was the bare BTDF under
// any layer.
TEST(LayeredLobe, ATransmittedLobeUnderACoatAndASheenIsWhatTheRendererAdds) {
    const float thetaIn = 30.0f;
    const glm::vec3 L(std::sin(glm::radians(thetaIn)), 0.0f, std::cos(glm::radians(thetaIn)));
    const std::vector<LobeSample> bare = evaluateLobe(glass(), thetaIn, kSamples);
    for (const MaterialParameters& layered : {coated(glass()), sheened(glass()), coated(sheened(glass()))}) {
        const std::vector<LobeSample> lobe = evaluateLobe(layered, thetaIn, kSamples);
        for (size_t i = 5; i + 5 < lobe.size(); i += 5) {
            const float o = glm::radians(lobe[i].thetaOutDegrees);
            const glm::vec3 below(std::sin(o), 0.0f, -std::cos(o));
            const std::string what = "t_out " + std::to_string(lobe[i].thetaOutDegrees) + ", coat " +
                                     std::to_string(layered.clearcoat) + ", sheen " + std::to_string(layered.sheenRoughness);
            const glm::vec3 truth = truthThroughTheWall(layered, L, below);
            const glm::vec3 bareTruth = truthThroughTheWall(glass(), L, below);
            ASSERT_GT(bareTruth.r, 0.0f) << what;
            expectRelativelyNear(lobe[i].transmitted * std::cos(o), truth, what);
            // The factor the layers take: the truth's, less than 1.
            const float factor = truth.g / bareTruth.g;
            EXPECT_LT(factor, 0.99f) << what;
            expectRelativelyNear(lobe[i].transmitted, bare[i].transmitted * factor, what);
        }
    }
}

// The slice's transmitted image (the BTDF by the mirrored direction's half vector): at each pixel
// the wall's BTDF seen from L with the light at V mirrored below, the ground truth's under the
// layers; its peak up the left edge (theta_h = 0, straight through), as the reflection's is; 0
// without a transmission. The reflected slices read the diffuse the transmission leaves, as the
// polar lobe does (before, the whole diffuse).
TEST(LayeredLobe, TheSlicesTransmittedImageIsTheWallsBtdfByTheMirroredHalfVector) {
    const int size = 24;
    const MaterialParameters material = coated(sheened(glass()));
    const BrdfSlice slice = brdfSlice(material, 90.0f, size, SliceLobe::Transmitted);
    for (int y = 1; y < size; y += 4) {
        for (int x = 0; x < size; x += 5) {
            const glm::vec2 angles = glm::radians(sliceAngles(x, y, size));
            const DirectionPair pair = halfDifferenceDirections(angles.x, angles.y, glm::radians(90.0f));
            const glm::vec3 L = glm::normalize(pair.L), V = glm::normalize(pair.V);
            const glm::vec3 below(V.x, V.y, -V.z);
            expectRelativelyNear(slice.at(x, y) * V.z, truthThroughTheWall(material, L, below),
                                 "pixel " + std::to_string(x) + ", " + std::to_string(y));
        }
    }
    for (int y = 0; y < size; ++y) {
        int peak = 0;
        for (int x = 0; x < size; ++x) {
            peak = slice.at(x, y).g > slice.at(peak, y).g ? x : peak;
        }
        EXPECT_EQ(peak, 0) << "row " << y;
    }
    MaterialParameters opaque = glass();
    opaque.transmission = 0.0f;
    const BrdfSlice none = brdfSlice(opaque, 90.0f, size, SliceLobe::Transmitted);
    EXPECT_TRUE(std::all_of(none.values.begin(), none.values.end(), [](glm::vec3 f) { return f == glm::vec3(0.0f); }));
    const BrdfSlice diffuse = brdfSlice(glass(), 90.0f, size, SliceLobe::Diffuse);
    const BrdfSlice opaqueDiffuse = brdfSlice(opaque, 90.0f, size, SliceLobe::Diffuse);
    for (size_t i = 0; i < diffuse.values.size(); ++i) {
        EXPECT_NEAR(diffuse.values[i].r, (1.0f - glass().transmission) * opaqueDiffuse.values[i].r, 1e-6f) << i;
    }
}

}  // namespace
}  // namespace patina
