// Sphere and tube lights of shaders/shared/brdf_model.glsl and lights.glsl (Karis 2013, "Area
// lights"), compiled as C++: their limits are the lights they generalise, their terms are what
// the papers say, and their guards keep every edge finite and non-negative.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "scene/light_packing.h"
#include "scene/probe.h"
#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "shading/energy_table.h"
#include "epic_instance.h"
#include "test_support.h"


namespace patina {
namespace {


Light sphereLight(glm::vec3 centre, float radius) {
    Light light;
    light.type = LightType::Sphere;
    light.position = centre;
    light.sourceRadius = radius;
    light.range = 12.0f;
    light.attenuation = {0.5f, 0.25f, 1.0f};
    light.intensity = 10.0f;
    light.color = {1.0f, 0.5f, 0.25f};
    return light;
}

Light tubeLight(glm::vec3 start, glm::vec3 end, float radius) {
    Light light = sphereLight(start, radius);
    light.type = LightType::Tube;
    light.start = start;
    light.end = end;
    return light;
}

// Random shading configurations on the lit side, from the mirror direction to grazing.
struct Configuration {
    Material material;
    glm::vec3 P, N, V;
};

std::vector<Configuration> configurations(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Configuration> result;
    for (int i = 0; i < count; ++i) {
        Material m;
        m.baseColor = {unit(rng), unit(rng), unit(rng)};
        m.roughness = 0.05f + 0.95f * unit(rng);
        m.metallic = unit(rng);
        const glm::vec3 N = test::randomUnitVector(rng);
        result.push_back({m, 0.5f * test::randomUnitVector(rng), N, test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng)});
    }
    return result;
}

double relativeDifference(glm::vec3 a, glm::vec3 b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double scale = std::max(std::abs(double(b[c])), 1e-12);
        worst = std::max(worst, std::abs(double(a[c]) - double(b[c])) / scale);
    }
    return worst;
}

TEST(SphereLight, OfRadiusZeroIsThePointLight) {
    // The shared code itself reduces to the point light (to rounding: the diffuse and specular
    // lobes are weighted apart)...
    const Light sphere = sphereLight({0.3f, 2.0f, 1.0f}, 0.0f);
    Light point = sphere;
    point.type = LightType::Point;
    shader::PackedLight packedSphere = packLight(point);
    packedSphere.type = shader::LIGHT_SPHERE;
    double worst = 0.0;
    for (const Configuration& c : configurations(2000, 11)) {
        const shader::SurfaceMaterial m = surfaceMaterial(c.material);
        for (bool exact : {false, true}) {
            for (float widening : {shader::WIDENING_UE4, shader::WIDENING_THIRD}) {
                const glm::vec3 value = shader::model_Epic::shadeSphereLightWith(
                    packedSphere, true, false, shader::AreaLightMethod(widening, exact), m, c.P, c.N, c.V);
                const glm::vec3 expected = shader::model_Epic::shadePointLight(packLight(point), true, false, m, c.P, c.N, c.V);
                worst = std::max(worst, relativeDifference(value, expected));
            }
        }
    }
    EXPECT_LT(worst, 1e-6);
    // ...and a scene's sphere of radius 0 is packed as that point light: bit for bit.
    EXPECT_EQ(packLight(sphere).type, shader::LIGHT_POINT);
    for (const Configuration& c : configurations(200, 12)) {
        EXPECT_EQ(probeOnCpu(c.material, {sphere}, {{c.P, c.N, c.V}})[0],
                  probeOnCpu(c.material, {point}, {{c.P, c.N, c.V}})[0]);
    }
}

TEST(TubeLight, OfLengthZeroIsTheSphereLight) {
    const Light sphere = sphereLight({0.3f, 2.0f, 1.0f}, 0.2f);
    const Light tube = tubeLight(sphere.position, sphere.position, sphere.sourceRadius);
    shader::PackedLight packedTube = packLight(sphere);
    packedTube.type = shader::LIGHT_TUBE;
    packedTube.tubeEnd = packedTube.position;
    double worst = 0.0;
    for (const Configuration& c : configurations(2000, 13)) {
        // Where the formulas are well defined (NoL >= 0.01): at grazing light, the cosine taken
        // as dot(N, L) / |L| (the tube's ends) or dot(N, L / |L|) (the sphere's centre) differs
        // by a rounding step that is a large part of a tiny NoL.
        if (glm::dot(c.N, glm::normalize(sphere.position - c.P)) < 0.01f) {
            continue;
        }
        const shader::SurfaceMaterial m = surfaceMaterial(c.material);
        const glm::vec3 value = shader::model_Epic::shadeTubeLight(packedTube, true, false, m, c.P, c.N, c.V);
        const glm::vec3 expected = shader::model_Epic::shadeSphereLight(packLight(sphere), true, false, m, c.P, c.N, c.V);
        worst = std::max(worst, relativeDifference(value, expected));
    }
    EXPECT_LT(worst, 1e-5);
    EXPECT_EQ(packLight(tube).type, shader::LIGHT_SPHERE);
    for (const Configuration& c : configurations(200, 14)) {
        EXPECT_EQ(probeOnCpu(c.material, {tube}, {{c.P, c.N, c.V}})[0],
                  probeOnCpu(c.material, {sphere}, {{c.P, c.N, c.V}})[0]);
    }
    // With radius 0 as well: the point light.
    EXPECT_EQ(packLight(tubeLight(sphere.position, sphere.position, 0.0f)).type, shader::LIGHT_POINT);
}

TEST(SphereLight, FarAwayIsThePointLight) {
    // At d = 4000 s the normalisation (alpha / alpha')^2 differs from 1 by 1e-3 at r = 0.5.
    Light point = sphereLight({0.0f, 0.0f, 0.0f}, 0.0f);
    point.type = LightType::Point;
    point.range = 0.0f;
    std::mt19937 rng(7);
    for (const Configuration& c : configurations(500, 15)) {
        Material m = c.material;
        m.roughness = 0.5f;
        point.position = c.P + 20.0f * test::vectorAtCosine(c.N, 0.6f, rng);
        Light sphere = point;
        sphere.type = LightType::Sphere;
        sphere.sourceRadius = 0.005f;
        const glm::vec3 expected = probeOnCpu(m, {point}, {{c.P, c.N, c.V}})[0];
        const glm::vec3 value = probeOnCpu(m, {sphere}, {{c.P, c.N, c.V}})[0];
        EXPECT_LT(relativeDifference(value, expected), 2e-3);
    }
}

TEST(SphereLight, RepresentativePointIsTheSpherePointClosestToTheRay) {
    // Karis 2013 eq. 11 by its geometry: the point lies on the sphere (or is the ray's own
    // closest point inside it), and no point of the sphere lies closer to the ray.
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto distanceToRay = [](glm::vec3 p, glm::vec3 R) { return glm::length(p - glm::dot(p, R) * R); };
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 L = (1.0f + 4.0f * unit(rng)) * test::randomUnitVector(rng);
        const glm::vec3 R = test::randomUnitVector(rng);
        const float s = 0.9f * unit(rng);
        const glm::vec3 p = shader::sphereRepresentativePoint(L, R, s);
        EXPECT_LE(glm::length(p - L), s * (1.0f + 1e-5f) + 1e-6f);
        for (int k = 0; k < 20; ++k) {
            const glm::vec3 q = L + s * test::randomUnitVector(rng);
            EXPECT_LE(distanceToRay(p, R), distanceToRay(q, R) + 1e-5f);
        }
    }
}

TEST(TubeLight, ClosestPointIsTheSegmentPointClosestToTheRay) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto distanceToRay = [](glm::vec3 p, glm::vec3 R) { return glm::length(p - glm::dot(p, R) * R); };
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 L0 = 3.0f * test::randomUnitVector(rng);
        const glm::vec3 Ld = 2.0f * unit(rng) * test::randomUnitVector(rng);
        const glm::vec3 R = test::randomUnitVector(rng);
        const glm::vec3 p = shader::tubeClosestPoint(L0, Ld, R);
        for (int k = 0; k <= 20; ++k) {
            const glm::vec3 q = L0 + (float(k) / 20.0f) * Ld;
            // The ray's line (Karis's segment-to-line distance), to rounding.
            EXPECT_LE(distanceToRay(p, R), distanceToRay(q, R) + 2e-5f);
        }
    }
}

TEST(SphereLight, NormalisationFollowsKarisEquationsTenAndFourteen) {
    const float alpha = 0.25f;
    // alpha' = saturate(alpha + s / (w d)) for both readings of w; (alpha / alpha')^2.
    EXPECT_FLOAT_EQ(shader::widenedAlpha(alpha, 0.2f, 2.0f, shader::WIDENING_UE4), 0.25f + 0.05f);
    EXPECT_FLOAT_EQ(shader::widenedAlpha(alpha, 0.3f, 2.0f, shader::WIDENING_THIRD), 0.25f + 0.05f);
    EXPECT_FLOAT_EQ(shader::widenedAlpha(alpha, 4.0f, 1.0f, shader::WIDENING_UE4), 1.0f);
    EXPECT_FLOAT_EQ(shader::sphereNormalization(alpha, 0.5f), 0.25f);
    EXPECT_FLOAT_EQ(shader::lineNormalization(alpha, 0.5f), 0.5f);
    // Source on the shaded point: finite, alpha' = 1.
    EXPECT_FLOAT_EQ(shader::widenedAlpha(alpha, 0.1f, 0.0f, shader::WIDENING_UE4), 1.0f);
    EXPECT_FLOAT_EQ(shader::widenedAlpha(alpha, 0.0f, 0.0f, shader::WIDENING_UE4), alpha);
}

TEST(SphereLight, FrostbiteIlluminanceIsTheCosineAboveTheHorizonAndContinuousAcrossIt) {
    for (float sinSigma : {0.01f, 0.1f, 0.3f, 0.6f, 0.9f}) {
        const float s2 = sinSigma * sinSigma;
        // Above the horizon: exactly the point light's cosine.
        for (float cosine : {1.0f, 0.95f, sinSigma + 0.01f}) {
            if (cosine * cosine >= s2) {
                EXPECT_EQ(shader::sphereIlluminance_Frostbite(cosine, s2), cosine);
            }
        }
        // The band's formula meets the cosine at the band's top and 0 at its bottom.
        EXPECT_NEAR(shader::sphereIlluminance_Frostbite(sinSigma * 0.99999f, s2), sinSigma, 2e-3f * sinSigma + 1e-6f);
        EXPECT_NEAR(shader::sphereIlluminance_Frostbite(-sinSigma * 0.99999f, s2), 0.0f, 1e-3f * sinSigma);
        // Falls monotonically through the band.
        float previous = 2.0f;
        for (int i = 0; i <= 100; ++i) {
            const float cosine = sinSigma * (1.0f - 2.0f * float(i) / 100.0f) * 0.9999f;
            const float value = shader::sphereIlluminance_Frostbite(cosine, s2);
            EXPECT_GE(value, 0.0f);
            EXPECT_LE(value, previous + 1e-6f) << "sin sigma " << sinSigma << " cos " << cosine;
            previous = value;
        }
        // Half the sphere above the horizon at theta = 90 degrees gives a positive illuminance
        // a point light would not.
        EXPECT_GT(shader::sphereIlluminance_Frostbite(0.0f, s2), 0.0f);
    }
    // Inside the sphere: the whole hemisphere, pi Le, over pi Le sin^2 sigma.
    EXPECT_FLOAT_EQ(shader::sphereIlluminance_Frostbite(0.3f, 4.0f), 0.25f);
    // A point (sigma = 0): the clamped cosine, nothing divided by 0.
    EXPECT_EQ(shader::sphereIlluminance_Frostbite(0.0f, 0.0f), 0.0f);
    EXPECT_EQ(shader::sphereIlluminance_Frostbite(-0.5f, 0.0f), 0.0f);
}

TEST(TubeLight, LineIrradianceIsThePointLightsAtItsEnds) {
    // Karis's line irradiance: for a short segment, the point light at its centre; in general
    // 2 / (|L0||L1| + L0.L1) of the segment's I cos.
    const glm::vec3 L0(-0.5f, 0.0f, 2.0f), L1(0.5f, 0.0f, 2.0f);
    const float t2 = shader::lineIrradianceDistanceSquared(L0, L1);
    EXPECT_FLOAT_EQ(2.0f / (2.0f * t2), 2.0f / (glm::length(L0) * glm::length(L1) + glm::dot(L0, L1)));
    const glm::vec3 near(0.0f, 0.0f, 2.0f);
    EXPECT_NEAR(shader::lineIrradianceDistanceSquared(near, near + glm::vec3(1e-3f, 0, 0)), 4.0f, 1e-5f);
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    EXPECT_FLOAT_EQ(shader::lineIrradianceCosine(N, L0, L1), 2.0f / glm::length(L0));
    EXPECT_EQ(shader::lineIrradianceCosine(-N, L0, L1), 0.0f);
}

// A sphere's intensity keeps the point light's meaning: I = pi s^2 Le, its illuminance above the
// horizon I cos / d^2 whatever its size (Karis's diffuse is exact there).
TEST(SphereLight, DiffuseAboveTheHorizonIsThePointLightsWhateverTheRadius) {
    Material m;
    m.baseColor = {0.8f, 0.8f, 0.8f};
    m.specular = 0.0f;
    m.roughness = 1.0f;
    const glm::vec3 N(0.0f, 0.0f, 1.0f), V = N;
    const shader::SurfaceMaterial surface = surfaceMaterial(m);
    for (float radius : {0.0f, 0.1f, 0.5f, 0.9f}) {
        Light light = sphereLight({0.0f, 0.0f, 1.0f}, radius);
        light.range = 0.0f;
        light.attenuation = {0.0f, 0.0f, 1.0f};
        shader::PackedLight packed = packLight(light);
        for (bool exact : {false, true}) {
            const glm::vec3 diffuse = shader::model_Epic::shadeSphereLightWith(
                packed, true, false, shader::AreaLightMethod(shader::WIDENING_UE4, exact), surface, glm::vec3(0.0f), N, V);
            // Specular 0 leaves F0 = 0: only the Fresnel tail, far below the diffuse.
            EXPECT_NEAR(diffuse.r, light.intensity * 0.8f / std::numbers::pi_v<float>, 2e-3f * light.intensity) << radius;
        }
    }
}

// The guards (the habit of docs/SHADING.md S2, for area lights): every edge finite and non-negative, on
// the shared code directly, where the packing would otherwise turn a degenerate light into a
// point or a sphere.
TEST(AreaLights, DegenerateLightsAndPointsStayFiniteAndNonNegative) {
    const glm::vec3 up(0.0f, 0.0f, 1.0f);
    struct Case {
        const char* name;
        shader::PackedLight light;
        glm::vec3 P;
    };
    auto packed = [](const Light& light, int type) {
        shader::PackedLight p = packLight(light);
        p.type = type;
        p.sourceRadius = light.sourceRadius;
        p.tubeEnd = light.end;
        p.position = type == shader::LIGHT_TUBE ? light.start : light.position;
        return p;
    };
    Light bigSphere = sphereLight({0.0f, 0.0f, 1.0f}, 20.0f);   // radius above the range 12
    Light zeroSphere = sphereLight({0.0f, 0.0f, 1.0f}, 0.0f);
    Light zeroTube = tubeLight({0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f}, 0.3f);
    Light pointTube = tubeLight({0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f}, 0.0f);
    Light crossing = tubeLight({-1.0f, 0.0f, -1.0f}, {1.0f, 0.0f, 1.0f}, 0.2f);   // through the surface
    Light behind = sphereLight({0.0f, 0.0f, -2.0f}, 0.5f);
    Light lying = tubeLight({-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.1f);   // through P, in its plane
    const Case cases[] = {
        {"radius above the range", packed(bigSphere, shader::LIGHT_SPHERE), glm::vec3(0.0f)},
        {"radius 0", packed(zeroSphere, shader::LIGHT_SPHERE), glm::vec3(0.0f)},
        {"radius 0 at the point", packed(zeroSphere, shader::LIGHT_SPHERE), glm::vec3(0.0f, 0.0f, 1.0f)},
        {"inside the sphere", packed(sphereLight({0.0f, 0.0f, 0.1f}, 0.5f), shader::LIGHT_SPHERE), glm::vec3(0.0f)},
        {"centre on the point", packed(sphereLight({0.0f, 0.0f, 0.0f}, 0.5f), shader::LIGHT_SPHERE), glm::vec3(0.0f)},
        {"sphere behind", packed(behind, shader::LIGHT_SPHERE), glm::vec3(0.0f)},
        {"sphere through", packed(sphereLight({0.0f, 0.0f, -0.2f}, 0.5f), shader::LIGHT_SPHERE), glm::vec3(0.0f)},
        {"zero-length tube", packed(zeroTube, shader::LIGHT_TUBE), glm::vec3(0.0f)},
        {"coincident ends, radius 0", packed(pointTube, shader::LIGHT_TUBE), glm::vec3(0.0f)},
        {"coincident ends on the point", packed(zeroTube, shader::LIGHT_TUBE), glm::vec3(0.0f, 0.0f, 1.0f)},
        {"tube through the surface", packed(crossing, shader::LIGHT_TUBE), glm::vec3(0.0f)},
        {"tube through the point", packed(lying, shader::LIGHT_TUBE), glm::vec3(0.0f)},
        {"tube end on the point", packed(tubeLight({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 0.1f), shader::LIGHT_TUBE),
         glm::vec3(0.0f)},
    };
    const glm::vec3 views[] = {up, glm::normalize(glm::vec3(1.0f, 0.0f, 1e-4f)), glm::vec3(0.0f),
                               glm::normalize(glm::vec3(0.3f, 0.0f, -1.0f))};
    for (const Case& c : cases) {
        for (float roughness : {0.0f, 0.05f, 0.5f, 1.0f}) {
            for (const glm::vec3& V : views) {
                for (const glm::vec3& N : {up, glm::vec3(0.0f)}) {
                    for (bool exact : {false, true}) {
                        Material m;
                        m.roughness = roughness;
                        const glm::vec3 value = shadeAreaLight(BrdfModelId::Epic, c.light,
                                                               shader::AreaLightMethod(shader::WIDENING_UE4, exact),
                                                               surfaceMaterial(m), c.P, N, V);
                        for (int k = 0; k < 3; ++k) {
                            EXPECT_TRUE(std::isfinite(value[k]) && value[k] >= 0.0f)
                                << c.name << ", r " << roughness << ": " << value[k];
                        }
                    }
                }
            }
        }
    }
}

TEST(LightPacking, AreaLightsComeLastAndKeepTheirShape) {
    Light point = sphereLight({1.0f, 2.0f, 3.0f}, 0.0f);
    point.type = LightType::Point;
    const Light sphere = sphereLight({1.0f, 2.0f, 3.0f}, 0.25f);
    const Light tube = tubeLight({1.0f, 2.0f, 3.0f}, {2.0f, 2.0f, 3.0f}, 0.1f);
    Light sun;
    sun.type = LightType::Directional;
    const std::vector<shader::PackedLight> packed = packEnabledLights({tube, sphere, point, sun});
    ASSERT_EQ(packed.size(), 4u);
    EXPECT_EQ(packed[0].type, shader::LIGHT_POINT);
    EXPECT_EQ(packed[1].type, shader::LIGHT_DIRECTIONAL);
    EXPECT_EQ(packed[2].type, shader::LIGHT_SPHERE);
    EXPECT_EQ(packed[2].sourceRadius, 0.25f);
    EXPECT_EQ(packed[3].type, shader::LIGHT_TUBE);
    EXPECT_EQ(packed[3].position, tube.start);
    EXPECT_EQ(packed[3].tubeEnd, tube.end);
    EXPECT_EQ(packedLightCounts(packed), glm::ivec4(4, 1, 1, 0));
    EXPECT_EQ(packedAreaLightCounts(packed), glm::ivec4(1, 1, 0, 0));
    // Karis's coefficients are known for area lights too (the shaders' constant).
    EXPECT_FALSE(hasKarisAttenuation(packLight(sphere)));
    Light karis = sphere;
    karis.attenuation = {1.0f, 0.0f, 1.0f};
    EXPECT_TRUE(hasKarisAttenuation(packLight(karis)));
}

// The constant stands in for the coefficients exactly where they are Karis's.
TEST(AreaLights, KarisConstantMatchesReadingKarisCoefficients) {
    const shader::SurfaceMaterial material = surfaceMaterial(Material{});
    const glm::vec3 P(0.3f, 0.1f, 0.2f), N(0.0f, 1.0f, 0.0f), V = glm::normalize(glm::vec3(0.3f, 1.0f, 0.4f));
    Light sphere = sphereLight({1.0f, 2.0f, 0.5f}, 0.3f);
    sphere.attenuation = {1.0f, 0.0f, 1.0f};
    Light tube = tubeLight({1.0f, 2.0f, 0.5f}, {-1.0f, 2.0f, 0.5f}, 0.3f);
    tube.attenuation = {1.0f, 0.0f, 1.0f};
    EXPECT_EQ(shader::model_Epic::shadeSphereLight(packLight(sphere), true, true, material, P, N, V),
              shader::model_Epic::shadeSphereLight(packLight(sphere), true, false, material, P, N, V));
    EXPECT_EQ(shader::model_Epic::shadeTubeLight(packLight(tube), true, true, material, P, N, V),
              shader::model_Epic::shadeTubeLight(packLight(tube), true, false, material, P, N, V));
    // And the window switch: range 0 packs as no window.
    sphere.range = 0.0f;
    EXPECT_EQ(shader::model_Epic::shadeSphereLight(packLight(sphere), false, false, material, P, N, V),
              shader::model_Epic::shadeSphereLight(packLight(sphere), true, false, material, P, N, V));
}

}  // namespace
}  // namespace patina
