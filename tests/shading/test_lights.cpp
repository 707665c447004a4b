// The three light types of shaders/shared/lights.glsl, compiled as C++.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "shading/cpu_shading.h"
#include "scene/light_packing.h"
#include "scene/probe.h"
#include "shading/energy_table.h"
#include "epic_instance.h"
#include "test_support.h"


namespace patina {
namespace {

Light hemisphereLight() {
    Light light;
    light.type = LightType::Hemisphere;
    light.sky = {0.2f, 0.4f, 0.8f};
    light.ground = {0.5f, 0.3f, 0.1f};
    light.intensity = 2.0f;
    return light;
}

Light pointLight(float range) {
    Light light;
    light.type = LightType::Point;
    light.position = {0.0f, 0.0f, 0.0f};
    light.range = range;
    light.attenuation = {0.5f, 0.25f, 1.0f};
    light.intensity = 10.0f;
    light.color = {1.0f, 0.5f, 0.25f};
    return light;
}

glm::vec3 shadeOne(const Material& material, const Light& light, glm::vec3 P, glm::vec3 N, glm::vec3 V) {
    return probeOnCpu(material, {light}, {{P, N, V}})[0];
}

TEST(HemisphereLight, HasNoSpecularAndIgnoresRoughnessAndSpecular) {
    const Light light = hemisphereLight();
    const glm::vec3 N = glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f));
    const glm::vec3 V = glm::normalize(glm::vec3(-0.2f, 0.5f, 1.0f));
    Material base;
    base.baseColor = {0.6f, 0.5f, 0.4f};
    const glm::vec3 expected = shadeOne(base, light, glm::vec3(0.0f), N, V);
    for (float roughness : {0.0f, 0.05f, 0.5f, 1.0f}) {
        for (float specular : {0.0f, 0.5f, 1.0f}) {
            Material m = base;
            m.roughness = roughness;
            m.specular = specular;
            const glm::vec3 value = shadeOne(m, light, glm::vec3(0.0f), N, V);
            EXPECT_EQ(value, expected) << "roughness " << roughness << " specular " << specular;
        }
    }
    // A pure metal has no diffuse colour, so a diffuse-only light leaves it black.
    Material metal = base;
    metal.metallic = 1.0f;
    EXPECT_EQ(shadeOne(metal, light, glm::vec3(0.0f), N, V), glm::vec3(0.0f));
}

TEST(HemisphereLight, DownFacingPointsSeeOnlyTheGround) {
    const Light light = hemisphereLight();
    Material m;
    m.baseColor = {1.0f, 1.0f, 1.0f};
    const glm::vec3 down(0.0f, -1.0f, 0.0f);
    const glm::vec3 value = shadeOne(m, light, glm::vec3(0.0f), down, down);
    const glm::vec3 expected = light.ground * light.intensity / std::numbers::pi_v<float>;
    EXPECT_NEAR(value.r, expected.r, 1e-6f);
    EXPECT_NEAR(value.g, expected.g, 1e-6f);
    EXPECT_NEAR(value.b, expected.b, 1e-6f);
    // Facing straight up: only the sky. Sideways: half way is still all ground (clamp at 0).
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    EXPECT_NEAR(shadeOne(m, light, glm::vec3(0.0f), up, up).b, light.sky.b * 2.0f / std::numbers::pi_v<float>, 1e-6f);
    const glm::vec3 side(1.0f, 0.0f, 0.0f);
    EXPECT_NEAR(shadeOne(m, light, glm::vec3(0.0f), side, side).r, expected.r, 1e-6f);
}

TEST(PointLight, IsZeroAtAndBeyondItsRadius) {
    const Light light = pointLight(4.0f);
    Material m;
    const glm::vec3 N(0.0f, 1.0f, 0.0f);
    for (float t : {4.0f, 4.001f, 5.0f, 100.0f}) {
        const glm::vec3 P(0.0f, -t, 0.0f);
        EXPECT_EQ(shadeOne(m, light, P, N, N), glm::vec3(0.0f)) << "t = " << t;
    }
    EXPECT_GT(shadeOne(m, light, glm::vec3(0.0f, -3.9f, 0.0f), N, N).r, 0.0f);
}

TEST(PointLight, InsideTheRadiusMatchesTheWindowedFormula) {
    const Light light = pointLight(4.0f);
    Material m;
    m.baseColor = {0.7f, 0.7f, 0.7f};
    m.roughness = 0.6f;
    const std::vector<reference::Light> lights = test::toReference({light});
    const glm::vec3 N = glm::normalize(glm::vec3(0.1f, 1.0f, 0.2f));
    const glm::vec3 V = glm::normalize(glm::vec3(0.5f, 1.0f, 0.0f));
    for (float t : {0.1f, 0.5f, 1.0f, 2.0f, 3.0f, 3.9f}) {
        const glm::vec3 P(0.0f, -t, 0.0f);
        const glm::vec3 value = shadeOne(m, light, P, N, V);
        const reference::Vec3 expected = reference::shadeAll(test::toReference(m), lights,
                                                             test::toReference(P), test::toReference(N),
                                                             test::toReference(V));
        EXPECT_LT(test::maxRelativeError({value}, {expected}, 1e-9), 1e-5) << "t = " << t;
    }
    // The attenuation itself, by hand: t = 2, range 4: window = (1 - 1/16)^2 = 0.87890625,
    // denominator = 0.5 + 0.5 + 4 = 5.
    EXPECT_FLOAT_EQ(shader::pointLightAttenuation(2.0f, 1.0f / 4.0f, light.attenuation), 0.87890625f / 5.0f);
    // Range 0 (packed as inverse range 0): no window at all.
    EXPECT_FLOAT_EQ(shader::pointLightAttenuation(2.0f, 0.0f, light.attenuation), 1.0f / 5.0f);
}

TEST(DirectionalLight, ShinesAlongItsDirection) {
    Light light;
    light.type = LightType::Directional;
    light.direction = {0.0f, -2.0f, 0.0f};   // straight down, not unit on purpose
    Material m;
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    EXPECT_GT(shadeOne(m, light, glm::vec3(0.0f), up, up).r, 0.0f);
    EXPECT_EQ(shadeOne(m, light, glm::vec3(0.0f), -up, -up), glm::vec3(0.0f));
    // Lambert at normal incidence: c_diff / pi * NoL plus the specular peak.
    EXPECT_EQ(packLight(light).directionToLight, up);
}

TEST(Lights, DisabledLightsAddNothingAndLightsAddUp) {
    Light a = pointLight(0.0f);
    a.position = {0.0f, 2.0f, 0.0f};
    Light b = hemisphereLight();
    Material m;
    const glm::vec3 P(0.0f), N(0.0f, 1.0f, 0.0f), V = glm::normalize(glm::vec3(0.3f, 1.0f, 0.0f));
    const glm::vec3 sum = probeOnCpu(m, {a, b}, {{P, N, V}})[0];
    const glm::vec3 separate = shadeOne(m, a, P, N, V) + shadeOne(m, b, P, N, V);
    EXPECT_NEAR(sum.g, separate.g, 1e-6f);
    b.enabled = false;
    EXPECT_EQ(probeOnCpu(m, {a, b}, {{P, N, V}})[0], shadeOne(m, a, P, N, V));
}

// Every light's default is Karis's falloff; only a point light's coefficients count.
TEST(LightPacking, KnowsKarisCoefficients) {
    EXPECT_TRUE(hasKarisAttenuation(packLight(Light{})));
    EXPECT_FALSE(hasKarisAttenuation(packLight(pointLight(2.0f))));
    Light sun;
    sun.type = LightType::Directional;
    EXPECT_FALSE(hasKarisAttenuation(packLight(sun)));
}

// The constant stands in for the coefficients exactly where they are Karis's.
TEST(PointLight, KarisConstantMatchesReadingKarisCoefficients) {
    const shader::SurfaceMaterial material = surfaceMaterial(Material{});
    const glm::vec3 P(0.3f, 0.1f, 0.2f), N(0.0f, 1.0f, 0.0f), V = glm::normalize(glm::vec3(0.3f, 1.0f, 0.4f));
    Light light = pointLight(6.0f);
    light.position = {1.0f, 2.0f, 0.5f};
    light.attenuation = {1.0f, 0.0f, 1.0f};
    const shader::PackedLight karis = packLight(light);
    EXPECT_EQ(shader::model_Epic::shadePointLight(karis, true, true, material, P, N, V),
              shader::model_Epic::shadePointLight(karis, true, false, material, P, N, V));
    light.attenuation = {0.5f, 0.25f, 1.0f};
    const shader::PackedLight other = packLight(light);
    EXPECT_NE(shader::model_Epic::shadePointLight(other, true, true, material, P, N, V),
              shader::model_Epic::shadePointLight(other, true, false, material, P, N, V));
}

}  // namespace
}  // namespace patina
