// The diffuse ground truth without noise (reference/exact_irradiance.h): against closed forms,
// and the Monte Carlo reference converging to it; the irradiance map and the nine SH
// coefficients it replaced measured against it.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "accuracy/diffuse_accuracy.h"
#include "common/luminance.h"
#include "environment/environment.h"
#include "environment/spherical_harmonics.h"
#include "reference/environment_distribution.h"
#include "reference/exact_irradiance.h"
#include "reference/radiance.h"
#include "test_support.h"

namespace patina {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(ExactIrradiance, ALinearEnvironmentHasItsClosedForm) {
    // Env = a + b d.y: E(n) = pi a + (2 pi / 3) b n.y; only the pixels a horizon cuts, 0.7
    // degrees each, are approximate.
    const double a = 0.7, b = 0.4;
    const HdrImage image = test::equirectOf(512, 256, [&](glm::vec3 d) { return glm::vec3(float(a + b * d.y)); });
    const ExactIrradiance exact(image);
    std::mt19937 rng(11);
    for (int i = 0; i < 40; ++i) {
        const glm::vec3 n = test::randomUnitVector(rng);
        const double want = kPi * a + 2.0 * kPi / 3.0 * b * n.y;
        EXPECT_NEAR(exact.at(n).x, want, 2e-5 * want);
    }
}

TEST(ExactIrradiance, TheMonteCarloReferenceConvergesToIt) {
    // The reference's estimate of a white Lambert surface under a small sun 10^4 times its sky
    // is E / pi within its own noise: the two ground truths are the same integral (the estimate
    // reads the image bilinearly, the sum by pixels; the difference is far below the noise).
    const std::shared_ptr<const Environment> sun = prepareEnvironment(sunEnvironment(256), "generated:sun");
    const ExactIrradiance exact(sun->image);
    const EnvironmentDistribution distribution(sun->image);
    const ReferenceEnvironment reference{sun.get(), &distribution, 1.0f, 0.0f};
    const shader::SurfaceMaterial white = shader::deriveSurfaceMaterial(glm::vec3(1.0f), 1.0f, 0.0f, 0.0f);
    double chiSquare = 0.0;
    const std::vector<glm::vec3> normals = spreadNormals(24);
    for (size_t i = 0; i < normals.size(); ++i) {
        ReferenceOptions options;
        options.samples = 4096;
        options.seed = 31 + i;
        options.specular = false;
        const glm::vec3 n = normals[i];
        const ReferenceEstimate estimate =
            referenceRadiance(BrdfModelId::Epic, white, reference, {}, glm::vec3(0.0f), n, n, options);
        const double truth = luminance(glm::vec3(exact.at(normals[i]))) / kPi;
        const double difference = (luminance(estimate.value) - truth) / luminance(estimate.standardError);
        EXPECT_LT(std::abs(difference), 4.5) << i;
        chiSquare += difference * difference;
    }
    // The estimates scatter as their standard errors say (chi-square of 24 degrees of freedom).
    EXPECT_LT(chiSquare, 50.0);
}

TEST(ExactIrradiance, TheMapHoldsItWhereNineCoefficientsRing) {
    // Under the small sun the map is within 0.3% of the exact convolution on average and 3% at
    // worst (a texel's bilinear blend across the sun's terminator); the nine coefficients it
    // replaced are 2.6% off on average.
    const std::shared_ptr<const Environment> sun = prepareEnvironment(sunEnvironment(512), "generated:sun");
    const ExactIrradiance exact(sun->image);
    const ShCoefficients sh = projectSH(sun->image);
    double map = 0.0, nine = 0.0, worst = 0.0;
    const std::vector<glm::vec3> normals = spreadNormals(256);
    for (const glm::vec3& n : normals) {
        const double truth = luminance(glm::vec3(exact.at(n)));
        const double error = std::abs(luminance(sampleCubeLevel(sun->irradiance, n)) - truth) / truth;
        map += error / double(normals.size());
        worst = std::max(worst, error);
        nine += std::abs(luminance(glm::max(irradianceUnclamped(sh, n), glm::vec3(0.0f))) - truth) / truth /
                double(normals.size());
    }
    EXPECT_LT(map, 3e-3);
    EXPECT_LT(worst, 0.03);
    EXPECT_GT(nine, 0.02);
}

}  // namespace
}  // namespace patina
