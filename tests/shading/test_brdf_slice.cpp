// BRDF Explorer's image slice (shading/brdf_slice.h): the half/difference angles give the
// directions they name, and the slice of a known lobe is its closed form.
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "shading/brdf_slice.h"
#include "shading/shading.h"

namespace patina {
namespace {

// H = normalize(L + V) is theta_h from N, L is theta_d from H, and phi_d turns L about H.
TEST(BrdfSlice, TheHalfAndDifferenceAnglesGiveTheirDirections) {
    for (float thetaH : {0.0f, 0.3f, 1.1f}) {
        for (float thetaD : {0.05f, 0.7f, 1.4f}) {
            for (float phiD : {0.0f, 0.8f, 1.5708f, 2.5f}) {
                const DirectionPair p = halfDifferenceDirections(thetaH, thetaD, phiD);
                EXPECT_NEAR(glm::length(p.L), 1.0f, 1e-5f);
                EXPECT_NEAR(glm::length(p.V), 1.0f, 1e-5f);
                const glm::vec3 H = glm::normalize(p.L + p.V);
                EXPECT_NEAR(std::acos(std::clamp(H.z, -1.0f, 1.0f)), thetaH, 1e-3f);
                EXPECT_NEAR(std::acos(std::clamp(glm::dot(H, p.L), -1.0f, 1.0f)), thetaD, 1e-3f);
                EXPECT_NEAR(H.y, 0.0f, 1e-5f);   // phi_h = 0
            }
        }
    }
    // At theta_h = 0, L and V mirror each other through the normal.
    const DirectionPair p = halfDifferenceDirections(0.0f, 0.6f, 0.4f);
    EXPECT_NEAR(p.L.z, p.V.z, 1e-6f);
    EXPECT_NEAR(p.L.x, -p.V.x, 1e-6f);
}

// A Lambert lobe is constant: the diffuse slice is c_diff / pi wherever L and V are above the
// horizon; below it there is no value (-1). The specular lobe of a rough dielectric peaks in the
// first column (theta_h = 0) of each row.
TEST(BrdfSlice, ALambertLobeIsConstantAndTheSpecularPeakIsAtThetaHZero) {
    MaterialParameters material;
    material.baseColor = glm::vec3(0.6f, 0.3f, 0.1f);
    material.metallic = 0.0f;
    material.roughness = 0.3f;
    const int size = 48;
    const BrdfSlice diffuse = brdfSlice(material, 0.0f, size, SliceLobe::Diffuse);
    const glm::vec3 expected = material.baseColor / std::numbers::pi_v<float>;
    int valued = 0, unvalued = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const glm::vec3 f = diffuse.at(x, y);
            if (f.x < 0.0f) {
                ++unvalued;
                continue;
            }
            ++valued;
            EXPECT_NEAR(f.x, expected.x, 1e-6f);
            EXPECT_NEAR(f.y, expected.y, 1e-6f);
            EXPECT_NEAR(f.z, expected.z, 1e-6f);
        }
    }
    EXPECT_GE(valued, size * size / 2 - size);   // the triangle theta_h + theta_d < 90
    // At phi_d = 0, L is at theta_h + theta_d: past 90 degrees it is below the horizon.
    EXPECT_GT(unvalued, size * size / 3);
    EXPECT_LT(diffuse.at(size - 1, 0).x, 0.0f);

    // At phi_d = 90 both directions stay above the horizon everywhere.
    const BrdfSlice specular = brdfSlice(material, 90.0f, size, SliceLobe::Specular);
    for (const glm::vec3& f : specular.values) {
        ASSERT_GE(f.x, 0.0f);
    }
    for (int y = 0; y < size; ++y) {
        for (int x = 1; x < size; ++x) {
            EXPECT_GE(specular.at(0, y).x, specular.at(x, y).x) << x << " " << y;
        }
    }
    const BrdfSlice total = brdfSlice(material, 0.0f, size, SliceLobe::Total);
    const BrdfSlice specular0 = brdfSlice(material, 0.0f, size, SliceLobe::Specular);
    EXPECT_NEAR(total.at(3, size - 5).x, diffuse.at(3, size - 5).x + specular0.at(3, size - 5).x, 1e-5f);
}

// The slice's display: a Lambert lobe's c / pi reads mid-scale in log (four decades from 0.01),
// exposure doubles per stop, and no value (below the horizon) is black.
TEST(BrdfSlice, TheSliceShowsValuesByExposureAndLogScale) {
    const glm::vec3 lambert(0.1f);
    EXPECT_NEAR(sliceShown(lambert, 0.0f, true).x, shader::srgbEncode(0.25f), 1e-6f);   // log10(0.1) = -1
    EXPECT_NEAR(sliceShown(lambert, 0.0f, false).x, shader::srgbEncode(0.1f), 1e-6f);
    EXPECT_NEAR(sliceShown(lambert, 1.0f, false).x, shader::srgbEncode(0.2f), 1e-6f);
    EXPECT_NEAR(sliceShown(glm::vec3(1000.0f), 0.0f, true).x, 1.0f, 1e-6f);   // clamped at the top
    EXPECT_EQ(sliceShown(glm::vec3(-1.0f), 0.0f, true), glm::vec3(0.0f));
}

}  // namespace
}  // namespace patina
