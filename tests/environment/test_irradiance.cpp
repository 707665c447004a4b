// The irradiance map (environment/irradiance.h): each texel the cosine convolution of the
// environment at its centre, from the cells' first moments, against closed forms.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "environment/irradiance.h"
#include "test_support.h"

namespace patina {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// The largest |value - expected| / expected over every texel of `map`.
template <typename Expected>
double worstTexel(const CubeLevel& map, Expected expected) {
    double worst = 0.0;
    for (int face = 0; face < 6; ++face) {
        for (int t = 0; t < map.size; ++t) {
            for (int s = 0; s < map.size; ++s) {
                const glm::vec3 n = cubeTexelDirection(face, s, t, map.size);
                const double want = expected(n);
                worst = std::max(worst, std::abs(double(map.texel(face, s, t).x) - want) / want);
            }
        }
    }
    return worst;
}

TEST(IrradianceMap, APixelsMomentIsItsDirectionIntegratedOverIt) {
    // Against a fine midpoint quadrature of l sin(theta) over the pixel (ibl.glsl's convention).
    const int width = 64, height = 32;
    for (const glm::ivec2 pixel : {glm::ivec2(0, 0), glm::ivec2(17, 5), glm::ivec2(40, 16), glm::ivec2(63, 31)}) {
        glm::dvec3 sum(0.0);
        const int steps = 200;
        for (int j = 0; j < steps; ++j) {
            for (int i = 0; i < steps; ++i) {
                const double u = (pixel.x + (i + 0.5) / steps) / width, v = (pixel.y + (j + 0.5) / steps) / height;
                const glm::dvec3 d(shader::equirectToDirection(glm::vec2(u, v)));
                const double du = 2.0 * std::numbers::pi / width / steps, dv = std::numbers::pi / height / steps;
                const double solidAngle = du * dv * std::sin(v * std::numbers::pi);
                sum += d * solidAngle;
            }
        }
        const glm::dvec3 moment = pixelMoment(width, height, pixel.x, pixel.y);
        EXPECT_NEAR(glm::length(moment - sum), 0.0, 1e-6 * glm::length(sum)) << pixel.x << " " << pixel.y;
    }
}

TEST(IrradianceMap, AUniformEnvironmentGivesPiAtEveryTexel) {
    const HdrImage white = test::equirectOf(128, 64, [](glm::vec3) { return glm::vec3(1.0f); });
    const CubeLevel map = irradianceCube(white);
    EXPECT_EQ(map.size, kIrradianceFaceSize);
    // Short only by what the cells cut by a texel's horizon keep below it (h^2 / 4 of pi for
    // cells of h radians: 0.25% for cells of 16 texels a face).
    EXPECT_LT(worstTexel(map, [](glm::vec3) { return double(kPi); }), 3e-3);
}

TEST(IrradianceMap, ALinearEnvironmentHasItsClosedForm) {
    // Env = a + b d.y is SH bands 0 and 1: E(n) = pi a + (2 pi / 3) b n.y (docs/LIGHTING.md L3).
    const float a = 0.7f, b = 0.4f;
    const HdrImage image = test::equirectOf(256, 128, [&](glm::vec3 d) { return glm::vec3(a + b * d.y); });
    const CubeLevel map = irradianceCube(image);
    EXPECT_LT(worstTexel(map, [&](glm::vec3 n) { return kPi * a + 2.0f * kPi / 3.0f * b * n.y; }), 3e-3);
    // And between the texels, read as the GPU reads it (bilinear, seamless).
    std::mt19937 rng(5);
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 n = test::randomUnitVector(rng);
        const float exact = kPi * a + 2.0f * kPi / 3.0f * b * n.y;
        EXPECT_NEAR(sampleCubeLevel(map, n).x, exact, 4e-3f * exact);
    }
}

TEST(IrradianceMap, AOnePixelSunCountsAtItsOwnDirection) {
    // One bright pixel well inside a cell: every texel that sees the whole pixel gets L n.M_p
    // exactly, M_p its moment. A cell counted at its centre would move the sun by up to half a
    // cell (2.8 degrees here) and miss this by up to 5% of the sun's irradiance.
    const int width = 512, height = 256, sunX = 301, sunY = 77;
    HdrImage image{width, height, std::vector<float>(size_t(width) * size_t(height) * 3, 0.0f)};
    const float radiance = 1e5f;
    std::fill_n(&image.rgb[(size_t(sunY) * width + sunX) * 3], 3, radiance);
    const glm::dvec3 moment = pixelMoment(width, height, sunX, sunY);
    const CubeLevel map = irradianceCube(image);
    const glm::dvec3 sun = glm::normalize(moment);
    int lit = 0;
    for (int face = 0; face < 6; ++face) {
        for (int t = 0; t < map.size; ++t) {
            for (int s = 0; s < map.size; ++s) {
                const glm::dvec3 n(cubeTexelDirection(face, s, t, map.size));
                const double cosine = glm::dot(n, sun);
                const double value = map.texel(face, s, t).x;
                if (cosine > 0.01) {   // the pixel (0.7 degrees) wholly above the texel's horizon
                    EXPECT_NEAR(value, radiance * glm::dot(n, moment), 1e-5 * radiance * glm::length(moment));
                    ++lit;
                } else if (cosine < -0.01) {
                    EXPECT_EQ(value, 0.0);
                }
            }
        }
    }
    EXPECT_GT(lit, 6 * kIrradianceFaceSize * kIrradianceFaceSize / 3);
}

TEST(IrradianceMap, AnEmptyOrTinyImageGivesAMapAllTheSame) {
    // Fewer pixels than cells: most cells stay empty, and nothing is lost. Each cell is one
    // pixel of 45 degrees here, so a texel's horizon cuts cells far larger than a real image's.
    const HdrImage tiny = test::equirectOf(8, 4, [](glm::vec3) { return glm::vec3(2.0f); });
    EXPECT_LT(worstTexel(irradianceCube(tiny), [](glm::vec3) { return 2.0 * kPi; }), 0.1);
    const HdrImage black = test::equirectOf(64, 32, [](glm::vec3) { return glm::vec3(0.0f); });
    const CubeLevel dark = irradianceCube(black);
    for (const std::vector<float>& face : dark.faces) {
        for (float value : face) {
            ASSERT_EQ(value, 0.0f);
        }
    }
}

}  // namespace
}  // namespace patina
