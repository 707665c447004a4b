// KHR_materials_sheen, the `gltf` model's sheen (shaders/shared/sheen.glsl): term by term against
// the extension's formulas written out here in double precision, in fp32 and fp64; its albedo
// table against a fresh integral by another method; under a white furnace (a sheen over a white
// base reflects at most what arrives); under an environment (the irradiance times its albedo).
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "shading/shading.h"
#include "shading/shading_f64.h"
#include "shading/sheen_table.h"
#include "test_support.h"

namespace patina {
namespace {

constexpr double kPi = std::numbers::pi;

// The extension's f_sheen for unit N, V, L above the surface, sheenColor 1: the Charlie
// distribution (Estevez & Kulla 2017 eq. 2) at alpha = roughness^2 and the visibility
// 1 / (4 (N.L + N.V - N.L N.V)) (Neubelt & Pettineo 2013).
double extensionLobe(double roughness, glm::dvec3 N, glm::dvec3 V, glm::dvec3 L) {
    const double alpha = roughness * roughness;
    const glm::dvec3 H = glm::normalize(V + L);
    const double NoV = glm::dot(N, V), NoL = glm::dot(N, L), NoH = glm::dot(N, H);
    const double sinH = std::sqrt(std::max(0.0, 1.0 - NoH * NoH));
    const double D = (2.0 + 1.0 / alpha) * std::pow(sinH, 1.0 / alpha) / (2.0 * kPi);
    return D / (4.0 * (NoL + NoV - NoL * NoV));
}

// E(mu, r) by midpoint quadrature over the hemisphere of L (theta_L uniform, so that the grazing
// band where a smooth sheen lives is resolved; phi over [0, pi], the lobe being symmetric):
// another method than the table's importance sampling, with the same floors.
double quadratureAlbedo(double mu, double roughness, int thetaSteps = 3000, int phiSteps = 600) {
    const double r = std::max(roughness, double(shader::MIN_PERCEPTUAL_ROUGHNESS));
    mu = std::max(mu, double(shader::MIN_N_DOT_V));
    const glm::dvec3 N(0.0, 0.0, 1.0), V(std::sqrt(1.0 - mu * mu), 0.0, mu);
    const double dTheta = 0.5 * kPi / thetaSteps, dPhi = kPi / phiSteps;
    double sum = 0.0;
    for (int i = 0; i < thetaSteps; ++i) {
        const double theta = (i + 0.5) * dTheta;
        const double cosT = std::cos(theta), sinT = std::sin(theta);
        for (int j = 0; j < phiSteps; ++j) {
            const double phi = (j + 0.5) * dPhi;
            const glm::dvec3 L(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
            sum += extensionLobe(r, N, V, L) * cosT * sinT;
        }
    }
    return 2.0 * sum * dTheta * dPhi;
}

double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-12); }

TEST(Sheen, IsTheExtensionsLobeTermByTermInFp32AndFp64) {
    std::mt19937 rng(36);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    double worst32 = 0.0, worst64 = 0.0;
    int compared = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::vec3 color(unit(rng), unit(rng), unit(rng));
        const float roughness = 0.3f + 0.7f * unit(rng);   // D's peak well inside fp32
        const glm::vec3 N = test::randomUnitVector(rng);
        const glm::vec3 V = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        const glm::vec3 L = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        const glm::dvec3 n = glm::normalize(glm::dvec3(N)), v = glm::normalize(glm::dvec3(V)), l = glm::normalize(glm::dvec3(L));
        const shader::Sheen sheen32 = shader::deriveSheen(color, roughness, N, V);
        const shader_f64::Sheen sheen64 = shader_f64::deriveSheen(glm::dvec3(color), roughness, n, v);
        // The lobe is the extension's, scaled down only where its albedo would pass 1.
        const double expected = extensionLobe(roughness, n, v, l) * color.g;
        if (expected > 1e-9) {
            worst32 = std::max(worst32, relative(shader::sheenBrdf(sheen32, N, V, L).y, expected * sheen32.lobeScale));
            worst64 = std::max(worst64, relative(shader_f64::sheenBrdf(sheen64, n, v, l).y, expected * sheen64.lobeScale));
            ++compared;
        }
        // The albedo scaling: min(1 - max3(c) E(N.V), 1 - max3(c) E(N.L)), E capped at 1.
        const double strength = std::max({color.r, color.g, color.b});
        const double eV = std::min(double(shader::sheenAlbedo(sheen32.NoV, sheen32.roughness)), 1.0);
        const double eL = std::min(double(shader::sheenAlbedo(glm::dot(N, L), sheen32.roughness)), 1.0);
        EXPECT_NEAR(shader::sheenBaseWeight(sheen32, glm::dot(N, L)), std::min(1.0 - strength * eV, 1.0 - strength * eL), 1e-6);
        EXPECT_NEAR(shader_f64::sheenBaseWeight(sheen64, glm::dot(n, l)), std::min(1.0 - strength * eV, 1.0 - strength * eL), 1e-6);
        EXPECT_EQ(sheen32.lobeScale == 1.0f, shader::sheenAlbedo(sheen32.NoV, sheen32.roughness) <= 1.0f);
    }
    EXPECT_GT(compared, 3000);
    // fp32: 1 - N.H^2 cancels near N.H = 1, the lobe's minimum, and pow raises its rounding to
    // 0.5 / alpha (up to 5.6 here): 1.0e-3 measured (D_GGX's |N x H|^2 form would avoid it).
    EXPECT_LT(worst32, 2e-3);
    EXPECT_LT(worst64, 2e-7);   // the shared constants are float literals
}

// Roughness 0 is the extension's default: the floor keeps every term finite in fp32, at every
// angle down to the grazing ones, and the lobe 0 away from the horizon.
TEST(Sheen, RoughnessZeroIsFiniteEverywhere) {
    const glm::vec3 N(0, 0, 1);
    for (float mu : {1.0f, 0.5f, 0.05f, 1e-3f, 0.0f}) {
        const glm::vec3 V(std::sqrt(1.0f - mu * mu), 0.0f, mu);
        const shader::Sheen sheen = shader::deriveSheen(glm::vec3(1.0f), 0.0f, N, V);
        EXPECT_EQ(sheen.alpha, shader::MIN_PERCEPTUAL_ROUGHNESS * shader::MIN_PERCEPTUAL_ROUGHNESS);
        for (float nu : {1.0f, 0.5f, 0.05f, 1e-3f}) {
            for (float phi : {0.0f, 1.5f, 3.1f}) {
                const float s = std::sqrt(1.0f - nu * nu);
                const glm::vec3 L(s * std::cos(phi), s * std::sin(phi), nu);
                const glm::vec3 f = shader::sheenBrdf(sheen, N, V, L);
                EXPECT_TRUE(std::isfinite(f.x) && f.x >= 0.0f) << mu << " " << nu << " " << phi;
                EXPECT_TRUE(std::isfinite(shader::sheenBaseWeight(sheen, nu)));
            }
        }
    }
    EXPECT_EQ(shader::sheenDistribution(1.0f, 0.002f), 0.0f);
}

// The table (sheen_table.cpp's importance sampling of the Charlie half vectors) against a fresh
// quadrature over L at nodes from the smoothest sheen to the roughest and from grazing to
// head-on views; and its interpolation at a node is the node.
TEST(Sheen, TheAlbedoTableIsAFreshIntegral) {
    const std::vector<float>& table = sheenAlbedoTable();
    ASSERT_EQ(table.size(), size_t(kSheenTableSize * kSheenTableSize));
    const int n = kSheenTableSize - 1;
    for (int y : {0, 3, 9, 16, n}) {
        for (int x : {2, 6, 15, n}) {
            const double mu = double(x) / n, r = double(y) / n;
            const double fresh = quadratureAlbedo(mu, r);
            const float stored = table[size_t(y * kSheenTableSize + x)];
            EXPECT_NEAR(stored, fresh, 0.01 * fresh + 2e-4) << "N.V " << mu << " r " << r;
            EXPECT_NEAR(shader::sheenAlbedo(float(mu), float(r)), stored, 1e-6f * (1.0f + stored));
        }
    }
    // Known shape: the roughest sheen reflects about 0.3 at N.V = 0.48, nothing of a smooth sheen
    // reaches a head-on view, and a smooth sheen's grazing albedo passes 1 (the visibility is not
    // energy conserving there: deriveSheen caps it).
    EXPECT_NEAR(table[size_t(n * kSheenTableSize + 15)], 0.30, 0.05);
    EXPECT_LT(table[size_t(3 * kSheenTableSize + n)], 1e-3f);
    EXPECT_GT(table[size_t(0 * kSheenTableSize + 1)], 1.0f);
}

// Directional albedo of the layered BRDF (f_sheen + f_base sheenAlbedoScaling) by midpoint
// quadrature over L, for a white Lambertian base (albedo exactly 1, the hardest base to keep
// under 1) and sheenColor 1.
struct LayeredAlbedo {
    double sheen, total;
};
LayeredAlbedo layeredAlbedo(const shader::Sheen& sheen, glm::vec3 N, glm::vec3 V) {
    const int thetaSteps = 1500, phiSteps = 300;
    const double dTheta = 0.5 * kPi / thetaSteps, dPhi = kPi / phiSteps;
    LayeredAlbedo a{0.0, 0.0};
    for (int i = 0; i < thetaSteps; ++i) {
        const double theta = (i + 0.5) * dTheta;
        const float cosT = float(std::cos(theta)), sinT = float(std::sin(theta));
        for (int j = 0; j < phiSteps; ++j) {
            const float phi = float((j + 0.5) * dPhi);
            const glm::vec3 L(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
            const double lobe = shader::sheenBrdf(sheen, N, V, L).x;
            const double base = shader::sheenBaseWeight(sheen, cosT) / kPi;
            const double weight = 2.0 * cosT * sinT * dTheta * dPhi;
            a.sheen += lobe * weight;
            a.total += (lobe + base) * weight;
        }
    }
    return a;
}

// A white furnace: at each node's view and roughness the sheen reflects its capped albedo
// min(E, 1) (the table's), and with the white base beneath the whole reflects at most what
// arrives: the base keeps at most 1 - E of the light and the sheen takes E. (Without the cap,
// the smooth sheens' grazing views would reflect up to 5.7 times what arrives.)
TEST(Sheen, WhiteFurnaceOfASheenOverAWhiteBaseStaysAtOrUnderOne) {
    const glm::vec3 N(0, 0, 1);
    const int n = kSheenTableSize - 1;
    for (int x : {n, 22, 12, 6, 2}) {
        const float mu = float(x) / float(n);
        const glm::vec3 V(std::sqrt(1.0f - mu * mu), 0.0f, mu);
        for (int y : {2, 9, 19, n}) {
            const float r = float(y) / float(n);
            const shader::Sheen sheen = shader::deriveSheen(glm::vec3(1.0f), r, N, V);
            const LayeredAlbedo a = layeredAlbedo(sheen, N, V);
            const std::string what = "N.V " + std::to_string(mu) + " sheen roughness " + std::to_string(r);
            EXPECT_NEAR(a.sheen, sheen.albedo, 0.01 * sheen.albedo + 1e-3) << what;
            EXPECT_LE(a.total, 1.0 + 0.01) << what;   // to the table's and this quadrature's 1%
            EXPECT_GT(a.total, 0.5) << what;
        }
    }
}

// Under light without one direction (an environment's, a hemisphere light's) the sheen gives
// its albedo E(N.V) times sheenColor times irradiance / pi, and the base keeps 1 - max3(c) E:
// a uniform white environment of radiance 1 (irradiance pi) over a white Lambertian base
// reflects exactly 1.
TEST(Sheen, UnderLightFromEverywhereItIsTheIrradianceTimesItsAlbedo) {
    const glm::vec3 N(0, 0, 1);
    for (float mu : {1.0f, 0.5f, 0.1f}) {
        const glm::vec3 V(std::sqrt(1.0f - mu * mu), 0.0f, mu);
        for (float r : {0.1f, 0.5f, 0.9f}) {
            const shader::Sheen sheen = shader::deriveSheen(glm::vec3(0.5f, 1.0f, 0.25f), r, N, V);
            const shader::SheenShare share = shader::sheenIrradianceShare(sheen, glm::vec3(kPi));
            const float E = std::min(shader::sheenAlbedo(std::max(mu, shader::MIN_N_DOT_V), sheen.roughness), 1.0f);
            EXPECT_NEAR(share.sheen.x, 0.5f * E, 1e-6f);
            EXPECT_NEAR(share.sheen.y, E, 1e-6f);
            EXPECT_NEAR(share.baseWeight, 1.0f - E, 1e-6f);
            EXPECT_NEAR(shader::sheenOver(glm::vec3(1.0f), share).y, 1.0f, 1e-6f);
        }
    }
}

}  // namespace
}  // namespace patina
