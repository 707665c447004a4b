// The transmitted lobe of the lobe views (issue 36): KHR_materials_transmission's thin-walled
// BTDF as the renderer adds it, beneath the sheen and the coat (shade.frag, the ground truth's
// reference/radiance.cpp), in the polar lobe and `patina lobe` (evaluateLobe) and in the slice
// (brdfSlice's Transmitted, by the mirrored direction's half vector).
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "reference/radiance.h"
#include "shading/brdf_slice.h"
#include "shading/cpu_shading.h"
#include "shading/lobe.h"
#include "shading/shading.h"

namespace patina {
namespace {

constexpr int kSamples = 181;   // one a degree: sample i at i - 90 degrees

MaterialParameters glass() {
    MaterialParameters material;
    material.model = BrdfModelId::Gltf;
    material.baseColor = {0.9f, 0.6f, 0.3f};
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
    ReferenceOptions options;
    options.clearcoat = material.clearcoat;
    options.clearcoatRoughness = material.clearcoatRoughness;
    options.sheenColor = material.sheenColor;
    options.sheenRoughness = material.sheenRoughness;
    options.transmission = material.transmission;
    options.transmissionAttenuation = volumeAttenuationOf(material);
    return referenceRadiance(material.model, surfaceMaterial(material), ReferenceEnvironment{}, {light},
                             glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f), V, options)
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
TEST(TransmittedLobe, UnderACoatAndASheenItIsWhatTheRendererAdds) {
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
TEST(TransmittedLobe, TheSlicesTransmittedImageIsTheWallsBtdfByTheMirroredHalfVector) {
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
