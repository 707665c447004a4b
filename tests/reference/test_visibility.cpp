// The ground truth with visibility (issue 37, item 5): Embree's ray casts (reference/visibility.h)
// block each point and directional light by one shadow ray, sphere lights and the environment
// sample by sample. Each checked where the answer is known exactly: a roof over a point takes
// the sun, the lights above it and the half of the sky it covers; lights beside it or below the
// roof are not blocked; a convex shape does not shadow itself.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "environment/builtin_environments.h"
#include "reference/pixel_surfaces.h"
#include "reference/probe_reference.h"
#include "reference/radiance.h"
#include "reference/visibility.h"
#include "reference/reference_render.h"
#include "scene/light_packing.h"
#include "shading/cpu_shading.h"
#include "test_support.h"

namespace patina {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// A horizontal quad at height y over [x0, x1] x [z0, z1], both windings.
RayCaster roof(float y, float x0, float x1, float z0, float z1) {
    return RayCaster({{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}}, {0, 1, 2, 0, 2, 3, 0, 2, 1, 0, 3, 2});
}

TEST(RayCaster, ARayIsBlockedOnlyByWhatLiesOnItWithinItsReach) {
    const RayCaster quad = roof(1.0f, -1.0f, 1.0f, -1.0f, 1.0f);
    EXPECT_EQ(quad.triangles(), 4u);
    const glm::vec3 up(0, 1, 0);
    EXPECT_TRUE(quad.occluded({0, 0, 0}, up, 0.0f, kInfinity));
    EXPECT_FALSE(quad.occluded({0, 0, 0}, -up, 0.0f, kInfinity)) << "behind the ray's start";
    EXPECT_FALSE(quad.occluded({0, 0, 0}, up, 0.0f, 0.9f)) << "beyond its far end";
    EXPECT_FALSE(quad.occluded({3, 0, 0}, up, 0.0f, kInfinity)) << "beside the quad";
    EXPECT_FALSE(RayCaster({}, {}).occluded({0, 0, 0}, up, 0.0f, kInfinity)) << "nothing to hit";
    // A ray from a point on the quad itself, lifted by rayOrigin, leaves it.
    const glm::vec3 onIt(0.3f, 1.0f, 0.2f);
    EXPECT_TRUE(unoccluded(&quad, onIt, up, glm::normalize(glm::vec3(0.5f, 1.0f, 0.0f)), kInfinity));
    EXPECT_TRUE(unoccluded(&quad, onIt, up, glm::normalize(glm::vec3(0.5f, -1.0f, 0.0f)), kInfinity));
}

TEST(ReferenceVisibility, ARoofTakesTheLightsAboveAndLeavesTheOthers) {
    const RayCaster quad = roof(1.0f, -1.0f, 1.0f, -1.0f, 1.0f);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.1f, -1.0f, 0.05f};
    Light above;
    above.position = {0.0f, 2.0f, 0.2f};
    Light beside = above;
    beside.position = {5.0f, 2.0f, 0.0f};   // the ray passes x = 2.5 at the roof's height
    Light under = above;
    under.position = {0.2f, 0.5f, 0.0f};    // between the point and the roof
    const shader::SurfaceMaterial m = surfaceMaterial(Material{});
    const glm::vec3 P(0.0f), N(0, 1, 0), V = glm::normalize(glm::vec3(0.0f, 0.8f, 0.6f));
    ReferenceOptions options;
    options.occluders = &quad;
    for (const auto& [light, blocked] : {std::pair{sun, true}, {above, true}, {beside, false}, {under, false}}) {
        const std::vector<shader::PackedLight> lights = packEnabledLights({light});
        const ReferenceEstimate e = referenceRadiance(BrdfModelId::Epic, m, {}, lights, P, N, V, options);
        const glm::vec3 lit = shadePoint(BrdfModelId::Epic, m, lights, P, N, V);
        ASSERT_GT(lit.x, 0.0f);
        EXPECT_EQ(e.value, blocked ? glm::vec3(0.0f) : lit) << light.position.x << " " << light.position.y;
    }
}

TEST(ReferenceVisibility, ASphereLightBehindTheRoofIsBlockedSampleBySample) {
    const RayCaster quad = roof(1.0f, -3.0f, 3.0f, -3.0f, 3.0f);
    Light sphere;
    sphere.type = LightType::Sphere;
    sphere.position = {0.0f, 3.0f, 0.0f};
    sphere.sourceRadius = 0.5f;
    sphere.intensity = 100.0f;
    const glm::vec3 N(0, 1, 0), V = glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f));
    const ReferenceRow open = probeReference({Material{}}, {0}, {sphere}, {{glm::vec3(0.0f), N, V}}, nullptr, 256)[0];
    const ReferenceRow covered =
        probeReference({Material{}}, {0}, {sphere}, {{glm::vec3(0.0f), N, V}}, nullptr, 256, 0, {}, &quad)[0];
    EXPECT_GT(open.value.x, 0.0f);
    EXPECT_EQ(covered.value, glm::vec3(0.0f));
}

// Under a white sky of radiance 1, a white Lambert surface returns 1; a roof over the half of
// the sky on the +x side leaves it exactly 1/2 (the cosine-weighted half of the hemisphere).
TEST(ReferenceVisibility, ARoofOverHalfTheSkyHalvesTheDiffuseLight) {
    const std::shared_ptr<const Environment> white = prepareEnvironment(*builtinEnvironment("white"), "white", {{2, 8}});
    const EnvironmentDistribution distribution(white->image);
    const ReferenceEnvironment sky{white.get(), &distribution, 1.0f, 0.0f};
    const RayCaster half = roof(1.0f, 0.0f, 1e5f, -1e5f, 1e5f);
    Material material;
    material.baseColor = glm::vec3(1.0f);
    const shader::SurfaceMaterial m = surfaceMaterial(material);
    ReferenceOptions options;
    options.samples = 40000;
    options.specular = false;
    const glm::vec3 P(0.0f), N(0, 1, 0), V = glm::normalize(glm::vec3(-0.3f, 1.0f, 0.2f));
    const ReferenceEstimate open = referenceRadiance(BrdfModelId::Epic, m, sky, {}, P, N, V, options);
    options.occluders = &half;
    const ReferenceEstimate covered = referenceRadiance(BrdfModelId::Epic, m, sky, {}, P, N, V, options);
    EXPECT_NEAR(open.value.x, 1.0f, 3.0f * open.standardError.x + 1e-3f);
    EXPECT_NEAR(covered.value.x, 0.5f, 3.0f * covered.standardError.x + 1e-3f);
    EXPECT_LT(covered.standardError.x, 0.01f);
}

// The default scene's sphere is convex: nothing of it stands between a point of it and a light
// in front of the point, so with visibility its picture is the same but for the few pixels at
// the terminator, where the smooth normal sees light the facets hide.
TEST(ReferenceVisibility, AConvexShapeDoesNotShadowItself) {
    const Scene scene = defaultScene();
    const PreparedScene ready = test::prepared(scene);
    const PixelSurfaces surfaces = rasterizeSurfaces(ready, 64, 64);
    ReferenceRenderOptions options;
    options.samplesPerPixel = 4;
    const ReferenceImage open = renderReference(ready, surfaces, options);
    options.visibility = true;
    const ReferenceImage seen = renderReference(ready, surfaces, options);
    double difference = 0.0, total = 0.0;
    for (size_t i = 0; i < open.value.rgb.size(); ++i) {
        difference += std::abs(double(open.value.rgb[i]) - double(seen.value.rgb[i]));
        total += double(open.value.rgb[i]);
    }
    EXPECT_LT(difference, 0.01 * total);
}

}  // namespace
}  // namespace patina
