// The ground truth of sphere and tube lights (reference/area_lights.h) converges to what is
// known exactly: the point light far away, a sphere's illuminance I cos / d^2 above the horizon
// and Frostbite's closed form across it, the whole hemisphere inside the sphere, a thin line's
// irradiance, and a mirror-like lobe inside a large sphere. Each within a few standard errors.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "reference/area_lights.h"
#include "reference/probe_reference.h"
#include "scene/light_packing.h"
#include "scene/probe.h"
#include "shading/cpu_shading.h"
#include "shading/energy_table.h"
#include "test_support.h"

namespace patina {
namespace {


// A physical light: inverse square, no window, so the radiance is exactly I / (pi s^2).
Light physicalSphere(glm::vec3 centre, float radius, float intensity) {
    Light light;
    light.type = LightType::Sphere;
    light.position = centre;
    light.sourceRadius = radius;
    light.range = 0.0f;
    light.attenuation = {0.0f, 0.0f, 1.0f};
    light.intensity = intensity;
    return light;
}

// White Lambert with no specular lobe at all: radiance out = E / pi.
Material whiteLambert() {
    Material m;
    m.baseColor = glm::vec3(1.0f);
    m.specular = 0.0f;
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    return m;
}

ReferenceEstimate diffuseOnly(const Light& light, glm::vec3 P, glm::vec3 N, int samples) {
    ReferenceOptions options;
    options.samples = samples;
    options.specular = false;
    return areaLightReference(BrdfModelId::Epic, surfaceMaterial(whiteLambert()), {packLight(light)}, P, N, N,
                              options);
}

TEST(AreaReference, SphereFarAwayConvergesToThePointLight) {
    // s / d = 1e-3, far below the lobes' widths (alpha >= 0.04).
    for (float r : {0.2f, 0.5f, 1.0f}) {
        Material m;
        m.baseColor = {0.7f, 0.5f, 0.3f};
        m.roughness = r;
        Light sphere = physicalSphere(20.0f * glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f)), 0.02f, 400.0f);
        sphere.attenuation = {1.0f, 0.0f, 1.0f};   // the default falloff too
        Light point = sphere;
        point.type = LightType::Point;
        const glm::vec3 N(0.0f, 0.0f, 1.0f), V = glm::normalize(glm::vec3(-0.35f, -0.1f, 1.0f));
        const ReferenceRow row = probeReference(m, {sphere}, {{glm::vec3(0.0f), N, V}}, nullptr, 20000)[0];
        const glm::vec3 expected = probeOnCpu(m, {point}, {{glm::vec3(0.0f), N, V}})[0];
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(row.value[c], expected[c], 4.0f * row.standardError[c] + 2e-3f * expected[c]) << "r " << r;
        }
    }
}

TEST(AreaReference, SphereOfRadiusZeroIsThePointLightExactly) {
    Material m;
    m.roughness = 0.3f;
    const Light sphere = physicalSphere({0.5f, 0.5f, 2.0f}, 0.0f, 5.0f);
    Light point = sphere;
    point.type = LightType::Point;
    const std::vector<ProbeSample> samples = {{glm::vec3(0.0f), {0, 0, 1}, glm::normalize(glm::vec3(-0.2f, 0.0f, 1.0f))}};
    const ReferenceRow row = probeReference(m, {sphere}, samples, nullptr, 64)[0];
    EXPECT_EQ(row.value, probeOnCpu(m, {point}, samples)[0]);
    EXPECT_EQ(row.standardError, glm::vec3(0.0f));
}

TEST(AreaReference, DiffuseIlluminanceAboveTheHorizonIsIntensityTimesCosineOverDistanceSquared) {
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    for (float sinSigma : {0.1f, 0.5f, 0.8f}) {
        for (float thetaDegrees : {0.0f, 20.0f}) {
            const float theta = glm::radians(thetaDegrees), d = 2.0f;
            const Light light = physicalSphere(d * glm::vec3(std::sin(theta), 0.0f, std::cos(theta)), sinSigma * d, 7.0f);
            const ReferenceEstimate e = diffuseOnly(light, glm::vec3(0.0f), N, 20000);
            const double expected = light.intensity * std::cos(theta) / (d * d);
            EXPECT_NEAR(std::numbers::pi * e.value.r, expected, std::numbers::pi * 4.0 * e.standardError.r + 1e-3 * expected)
                << "sin sigma " << sinSigma << ", theta " << thetaDegrees;
        }
    }
}

TEST(AreaReference, DiffuseMatchesFrostbitesClosedFormAcrossTheHorizon) {
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    for (float sinSigma : {0.3f, 0.7f}) {
        const float sigma = std::asin(sinSigma), d = 1.5f;
        // From above the horizon, through the band where it crosses, to below it.
        for (float t : {0.0f, 0.2f, 0.4f, 0.5f, 0.6f, 0.8f, 0.95f}) {
            const float theta = glm::radians(90.0f) - sigma + t * 2.0f * sigma;
            const Light light = physicalSphere(d * glm::vec3(std::sin(theta), 0.0f, std::cos(theta)), sinSigma * d, 3.0f);
            const ReferenceEstimate e = diffuseOnly(light, glm::vec3(0.0f), N, 20000);
            const double closedForm =
                light.intensity / (d * d) * shader::sphereIlluminance_Frostbite(std::cos(theta), sinSigma * sinSigma);
            EXPECT_NEAR(std::numbers::pi * e.value.r, closedForm,
                        std::numbers::pi * 4.0 * e.standardError.r + 2e-3 * light.intensity / (d * d))
                << "sin sigma " << sinSigma << ", theta " << glm::degrees(theta);
        }
    }
}

TEST(AreaReference, InsideTheSphereTheWholeHemisphereIsLit) {
    // E = pi Le = I / s^2, by area sampling of the sphere.
    const Light light = physicalSphere({0.1f, -0.2f, 0.3f}, 1.0f, 2.0f);
    const ReferenceEstimate e = diffuseOnly(light, glm::vec3(0.0f), glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f)), 20000);
    EXPECT_NEAR(std::numbers::pi * e.value.r, 2.0, std::numbers::pi * 4.0 * e.standardError.r + 2e-3);
}

TEST(AreaReference, ThinTubeGivesTheLineIrradiance) {
    // A tube of radius s << its length 2 along x, at height h = 1 above the point, the normal
    // towards it: E = 2 s Le h^2 integral of dz / (h^2 + z^2)^2 over [-1, 1] = 2 s Le (1/2 + pi/4),
    // Le = I / (pi s (s + l / 2)); the caps add O(s / l).
    const float s = 0.002f, intensity = 3.0f;
    Light tube = physicalSphere(glm::vec3(0.0f), s, intensity);
    tube.type = LightType::Tube;
    tube.start = {-1.0f, 0.0f, 1.0f};
    tube.end = {1.0f, 0.0f, 1.0f};
    const ReferenceEstimate e = diffuseOnly(tube, glm::vec3(0.0f), {0, 0, 1}, 40000);
    const double radiance = intensity / (std::numbers::pi * s * (s + 1.0));
    const double expected = 2.0 * s * radiance * (0.5 + std::numbers::pi / 4.0);
    EXPECT_NEAR(std::numbers::pi * e.value.r, expected, std::numbers::pi * 4.0 * e.standardError.r + 5e-3 * expected);
    // Its radiance is the header's convention.
    EXPECT_NEAR(areaLightRadiance(packLight(tube), glm::vec3(0.0f)).r, radiance, 1e-5 * radiance);
}

TEST(AreaReference, SmoothLobeInsideALargeSphereReflectsItsRadianceTimesTheAlbedo) {
    // A white metal (F = 1) at r = 0.05 whose whole lobe lies inside the sphere: Lo = Le E(NoV, r),
    // the directional albedo. The cone alone would take forever at this roughness; the GGX rays
    // that hit the sphere carry it.
    Material metal;
    metal.baseColor = glm::vec3(1.0f);
    metal.metallic = 1.0f;
    metal.roughness = 0.05f;
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    for (float NoV : {0.5f, 0.9f}) {
        const glm::vec3 V(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
        const glm::vec3 mirror = 2.0f * NoV * N - V;
        const Light light = physicalSphere(3.0f * mirror, 0.6f, 5.0f);
        ReferenceOptions options;
        options.samples = 20000;
        const ReferenceEstimate e =
            areaLightReference(BrdfModelId::Epic, surfaceMaterial(metal), {packLight(light)}, glm::vec3(0.0f), N, V, options);
        const double expected = light.intensity / (std::numbers::pi * 0.36) * directionalAlbedo(BrdfModelId::Epic, NoV, 0.05, 16384);
        EXPECT_NEAR(e.value.r, expected, 4.0 * e.standardError.r + 5e-3 * expected) << "NoV " << NoV;
    }
}

}  // namespace
}  // namespace patina
