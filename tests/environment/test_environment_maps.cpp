// The environment layer's parts on their own: the cube-map layout and filter, the equirect
// convention, the roughness-to-mip mapping, the irradiance coefficients that the irradiance map
// replaced (test_irradiance.cpp has the map), the (A, B) table and the CPU split sum under a
// white environment.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "environment/builtin_environments.h"
#include "environment/cube_map.h"
#include "environment/environment.h"
#include "environment/equirect.h"
#include "environment/spherical_harmonics.h"
#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "shading/energy_table.h"
#include "shading/environment_brdf.h"
#include "test_support.h"

namespace patina {
namespace {



TEST(CubeMap, EveryFaceMapsBackToItself) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(-0.999f, 0.999f);
    for (int face = 0; face < 6; ++face) {
        for (int i = 0; i < 100; ++i) {
            const float sc = unit(rng), tc = unit(rng);
            const CubeCoordinate c = cubeCoordinate(cubeFaceDirection(face, sc, tc));
            EXPECT_EQ(c.face, face);
            EXPECT_NEAR(c.s, 0.5f * (sc + 1.0f), 1e-6f);
            EXPECT_NEAR(c.t, 0.5f * (tc + 1.0f), 1e-6f);
        }
    }
    // GL's table 8.19 at the face centres: +X, -X, +Y, -Y, +Z, -Z.
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int face = 0; face < 6; ++face) {
        EXPECT_EQ(cubeCoordinate(axes[face]).face, face);
        EXPECT_EQ(glm::normalize(cubeFaceDirection(face, 0.0f, 0.0f)), axes[face]);
    }
}

TEST(CubeMap, SeamlessFilteringReadsTheNeighbouringFace) {
    // Each face one colour: a direction on the edge between +X and +Z reads half of each
    // (a filter clamped to its face would read only one).
    CubeLevel level(8);
    for (int face = 0; face < 6; ++face) {
        for (int t = 0; t < 8; ++t) {
            for (int s = 0; s < 8; ++s) {
                level.setTexel(face, s, t, glm::vec3(float(face)));
            }
        }
    }
    const glm::vec3 edge = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));
    EXPECT_NEAR(sampleCubeLevel(level, edge).x, 0.5f * (0.0f + 4.0f), 1e-5f);
    EXPECT_FLOAT_EQ(sampleCubeLevel(level, {0, 0, 1}).x, 4.0f);
}

TEST(CubeMap, TrilinearBetweenLevelsAndClampedAtTheEnds) {
    CubeLevel base(4);
    for (float& v : base.faces[4]) {
        v = 2.0f;
    }
    const CubeChain chain = cubeMipChain(base);
    ASSERT_EQ(chain.size(), 3u);   // 4, 2, 1
    const glm::vec3 z(0.0f, 0.0f, 1.0f);
    EXPECT_FLOAT_EQ(sampleCube(chain, z, 0.0f).x, 2.0f);
    // The 1x1 level of face +Z still averages only +Z's texels.
    EXPECT_FLOAT_EQ(sampleCube(chain, z, 2.0f).x, 2.0f);
    EXPECT_FLOAT_EQ(sampleCube(chain, z, 7.0f).x, 2.0f);
}

TEST(Equirect, TheConventionOfTheSpec) {
    // Centre of the image along -Z, row 0 the zenith, +X a quarter turn to the right.
    EXPECT_NEAR(shader::directionToEquirect({0, 0, -1}).x, 0.5f, 1e-6f);
    EXPECT_NEAR(shader::directionToEquirect({0, 0, -1}).y, 0.5f, 1e-6f);
    EXPECT_NEAR(shader::directionToEquirect({0, 1, 0}).y, 0.0f, 1e-6f);
    EXPECT_NEAR(shader::directionToEquirect({1, 0, 0}).x, 0.75f, 1e-6f);
    EXPECT_NEAR(shader::directionToEquirect({-1, 0, 0}).x, 0.25f, 1e-6f);
    std::mt19937 rng(5);
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 d = test::randomUnitVector(rng);
        const glm::vec3 back = shader::equirectToDirection(shader::directionToEquirect(d));
        EXPECT_NEAR(glm::length(back - d), 0.0f, 2e-5f);
    }
}

TEST(Equirect, RotationTurnsAboutUpAndBackgroundMatchesLighting) {
    // rotationDegrees = 90 turns the environment's -Z (the image centre) to the world's -X... or
    // +X: whichever, toEnvironmentFrame and its inverse with -sin must agree, and up stays up.
    const float c = std::cos(glm::radians(90.0f)), s = std::sin(glm::radians(90.0f));
    const glm::vec3 world(0.3f, 0.5f, -0.8f);
    const glm::vec3 env = shader::toEnvironmentFrame(world, c, s);
    EXPECT_NEAR(glm::length(shader::toEnvironmentFrame(env, c, -s) - world), 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(env.y, world.y);
}

TEST(Equirect, InvalidPixelsAreReplacedAndCounted) {
    HdrImage image{2, 1, {1.0f, NAN, 2.0f, -1.0f, INFINITY, 3.0f}};
    EXPECT_EQ(replaceInvalidPixels(image), 2u);
    EXPECT_EQ(image.rgb, (std::vector<float>{1.0f, 0.0f, 2.0f, 0.0f, 0.0f, 3.0f}));
}

TEST(PrefilterMips, RoughnessAndLodAreInverses) {
    const float maxLod = 5.0f;
    const float floor = shader::MIN_PERCEPTUAL_ROUGHNESS;
    EXPECT_EQ(shader::roughnessToLod(0.0f, maxLod), 0.0f);     // r = 0 reads mip 0 alone,
    EXPECT_EQ(shader::roughnessToLod(floor, maxLod), 0.0f);    // as does the floor it shades with
    EXPECT_EQ(shader::roughnessToLod(1.0f, maxLod), maxLod);
    EXPECT_GT(shader::roughnessToLod(floor + 0.01f, maxLod), 0.0f);
    for (int i = 0; i <= 100; ++i) {
        const float r = std::max(float(i) / 100.0f, floor);
        EXPECT_NEAR(shader::lodToRoughness(shader::roughnessToLod(r, maxLod), maxLod), r, 2e-4f);
    }
    for (int lod = 0; lod <= 5; ++lod) {
        EXPECT_NEAR(shader::roughnessToLod(shader::lodToRoughness(float(lod), maxLod), maxLod), float(lod), 1e-5f);
    }
    EXPECT_FLOAT_EQ(shader::lodToRoughness(0.0f, maxLod), floor);
}

TEST(SplitSum, ASmoothMetalReadsMipZeroAlone) {
    // The shading floors r at 0.045; that floor must still read the unfiltered mip, not a blend
    // with mip 1 (docs/LIGHTING.md L5). The studio's mips differ, so a blend would show.
    const auto studio = prepareEnvironment(*builtinEnvironment("studio"), "builtin:studio");
    ASSERT_TRUE(studio);
    Material mirror;
    mirror.baseColor = glm::vec3(1.0f);
    mirror.metallic = 1.0f;
    bool mipsDiffer = false;
    for (float r : {0.0f, 0.02f, shader::MIN_PERCEPTUAL_ROUGHNESS}) {
        mirror.roughness = r;
        const shader::SurfaceMaterial m = surfaceMaterial(mirror);
        for (int i = 0; i < 32; ++i) {
            const float a = 0.7f * float(i), NoV = 0.15f + 0.8f * float(i % 8) / 8.0f;
            const glm::vec3 N = glm::normalize(glm::vec3(std::cos(a), 0.4f * std::sin(3.0f * a), std::sin(a)));
            const glm::vec3 T = glm::normalize(glm::cross(N, glm::vec3(0.0f, 1.0f, 0.1f)));
            const glm::vec3 V = NoV * N + std::sqrt(1.0f - NoV * NoV) * T;
            const glm::vec3 R = glm::reflect(-V, N);
            const glm::vec3 mip0 = sampleCubeLevel(studio->prefiltered[0], R);
            mipsDiffer |= glm::length(mip0 - sampleCubeLevel(studio->prefiltered[1], R)) > 1e-2f * glm::length(mip0);
            const glm::vec2 ab = environmentBrdf(BrdfModelId::Epic, NoV, m.roughness);
            const glm::vec3 expected = mip0 * (ab.x + ab.y);
            const glm::vec3 value = shadeEnvironmentOnCpu(BrdfModelId::Epic, m, *studio, 1.0f, 0.0f, N, V);
            EXPECT_NEAR(glm::length(value - expected), 0.0f, 1e-5f * glm::length(expected)) << r << " " << i;
        }
    }
    EXPECT_TRUE(mipsDiffer);
}

TEST(SphericalHarmonics, ALinearEnvironmentHasItsExactIrradiance) {
    // Env = a + b d.y is exactly bands 0 and 1: E(n) = pi a + (2 pi / 3) b n.y (docs/LIGHTING.md L3).
    const float a = 0.7f, b = 0.4f;
    const HdrImage image = test::equirectOf(256, 128, [&](glm::vec3 d) { return glm::vec3(a + b * d.y); });
    const ShCoefficients sh = projectSH(image);
    std::mt19937 rng(9);
    for (int i = 0; i < 50; ++i) {
        const glm::vec3 n = test::randomUnitVector(rng);
        const float exact = std::numbers::pi_v<float> * a + 2.0f * std::numbers::pi_v<float> / 3.0f * b * n.y;
        EXPECT_NEAR(irradianceUnclamped(sh, n).x, exact, 1e-3f * exact);
    }
}

TEST(SphericalHarmonics, ASunsFarSideGoesNegative) {
    // A small bright sun: nine terms ring, and the far side goes negative (why the irradiance
    // map replaced them; docs/LIGHTING.md).
    const HdrImage image = test::equirectOf(256, 128, [](glm::vec3 d) {
        return glm::vec3(glm::dot(d, glm::vec3(0, 1, 0)) > 0.999f ? 5000.0f : 0.0f);
    });
    const ShCoefficients sh = projectSH(image);
    // For a delta at the zenith, E(cos) is proportional to 1 + 2 cos + (5/8)(3 cos^2 - 1), whose
    // minimum, at cos = -8/15, is negative.
    const glm::vec3 down = glm::normalize(glm::vec3(std::sqrt(1.0f - 0.2844f), -0.5333f, 0.0f));
    EXPECT_LT(irradianceUnclamped(sh, down).x, 0.0f);
    // The window lowers the ringing it is there for: the far side is less negative.
    EXPECT_GT(irradianceUnclamped(windowSH(sh), down).x, irradianceUnclamped(sh, down).x);
}

TEST(EnvironmentBrdf, ABIsTheDirectionalAlbedoWithFSplitOut) {
    // With F = 1, F0 A + B = A + B is the lobe's directional albedo E(NoV, r): for a model whose
    // visibility is the same under analytic lights and environments, the energy table's.
    for (float NoV : {0.1f, 0.5f, 0.9f}) {
        for (float r : {0.2f, 0.5f, 0.9f}) {
            const glm::vec2 ab = integrateEnvironmentBrdf(BrdfModelId::SmithCorrelated, NoV, r, 65536);
            // The table's sampler runs in fp32 (as on the GPU), the energy table's in double.
            EXPECT_NEAR(ab.x + ab.y, directionalAlbedo(BrdfModelId::SmithCorrelated, NoV, r, 65536), 2e-3)
                << NoV << " " << r;
            EXPECT_GE(ab.x, 0.0f);
            EXPECT_GE(ab.y, 0.0f);
        }
    }
    // Karis's remap k = (r+1)^2/8 is left out under environments: epic's table is k = alpha/2's.
    EXPECT_EQ(environmentBrdfTable(BrdfModelId::Epic), environmentBrdfTable(BrdfModelId::SchlickAlphaHalf));
    // A smooth surface seen head on reflects F0 alone: A = 1, B = 0.
    const glm::vec2 smooth = environmentBrdf(BrdfModelId::Epic, 1.0f, 0.0f);
    EXPECT_NEAR(smooth.x, 1.0f, 2e-2f);
    EXPECT_NEAR(smooth.y, 0.0f, 2e-2f);
}

TEST(EnvironmentBrdf, TheTableInterpolatesTheIntegral) {
    for (float NoV : {0.23f, 0.61f, 0.97f}) {
        for (float r : {0.13f, 0.55f, 0.88f}) {
            const glm::vec2 direct = integrateEnvironmentBrdf(BrdfModelId::Epic, NoV, r, 4096);
            const glm::vec2 table = environmentBrdf(BrdfModelId::Epic, NoV, r);
            EXPECT_NEAR(table.x, direct.x, 5e-3f);
            EXPECT_NEAR(table.y, direct.y, 5e-3f);
        }
    }
}

TEST(SplitSum, AWhiteEnvironmentGivesTheTablesAlbedo) {
    // LD of a uniform environment is 1 at every mip, E is pi: a metal reflects F0 A + B.
    const auto white = prepareEnvironment(*builtinEnvironment("white"), "builtin:white");
    ASSERT_TRUE(white);
    Material metal;
    metal.baseColor = {0.9f, 0.6f, 0.3f};
    metal.metallic = 1.0f;
    for (float r : {0.0f, 0.3f, 0.7f, 1.0f}) {
        metal.roughness = r;
        const shader::SurfaceMaterial m = surfaceMaterial(metal);
        for (float NoV : {0.2f, 0.6f, 1.0f}) {
            const glm::vec3 N(0, 0, 1), V(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
            const glm::vec3 value = shadeEnvironmentOnCpu(BrdfModelId::Epic, m, *white, 1.0f, 0.0f, N, V);
            const glm::vec2 ab = environmentBrdf(BrdfModelId::Epic, NoV, m.roughness);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(value[c], m.f0[c] * ab.x + ab.y, 1e-4f) << r << " " << NoV;
            }
        }
    }
    // A white Lambert surface: c_diff / pi * pi = 1, plus the dielectric's specular.
    Material chalk;
    chalk.baseColor = glm::vec3(1.0f);
    chalk.specular = 0.0f;
    chalk.roughness = 1.0f;
    const shader::SurfaceMaterial m = surfaceMaterial(chalk);
    const glm::vec3 value = shadeEnvironmentOnCpu(BrdfModelId::Epic, m, *white, 1.0f, 0.0f, {0, 1, 0}, {0, 1, 0});
    const glm::vec2 ab = environmentBrdf(BrdfModelId::Epic, 1.0f, 1.0f);
    EXPECT_NEAR(value.x, 1.0f + ab.y, 2e-3f);
}

TEST(BuiltinEnvironments, StudioIsNeutralAndBrightAboveTheHorizon) {
    const auto studio = builtinEnvironment("studio");
    ASSERT_TRUE(studio);
    const ShCoefficients sh = projectSH(*studio);
    EXPECT_EQ(sh[0].x, sh[0].y);   // grey
    EXPECT_GT(irradianceUnclamped(sh, {0, 1, 0}).x, irradianceUnclamped(sh, {0, -1, 0}).x);
    EXPECT_FALSE(builtinEnvironment("nope"));
}

}  // namespace
}  // namespace patina
