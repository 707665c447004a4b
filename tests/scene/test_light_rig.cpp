// moveLightRig: the default scene's rig, moved onto a model 300 times larger and elsewhere,
// lights every point of it as the unit sphere's matching point (the 2CylinderEngine route:
// a model of hundreds of units swallowed every light and rendered flat).
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "scene/light_packing.h"
#include "scene/light_rig.h"
#include "scene/scene.h"
#include "shading/cpu_shading.h"

namespace patina {
namespace {

// Linear radiance at `position` with `normal`, seen from `direction` away, under `lights`.
glm::vec3 radianceAt(const Scene& scene, const std::vector<Light>& lights, glm::vec3 position, glm::vec3 normal) {
    const glm::vec3 toViewer = glm::normalize(glm::vec3(0.3f, 0.4f, 1.0f));
    return shadePoint(scene.material.model, surfaceMaterial(scene.material), packEnabledLights(lights), position,
                      normal, toViewer);
}

std::vector<Light> everyPositionalKind() {
    Light point, sphere, tube, directional;
    point.position = {1.5f, 2.0f, 2.5f};
    point.range = 6.0f;
    sphere.type = LightType::Sphere;
    sphere.position = {-2.0f, 1.0f, 2.0f};
    sphere.sourceRadius = 0.4f;
    tube.type = LightType::Tube;
    tube.start = {-1.0f, 2.5f, 1.5f};
    tube.end = {1.0f, 2.5f, 1.8f};
    tube.sourceRadius = 0.1f;
    tube.range = 8.0f;
    directional.type = LightType::Directional;
    directional.direction = {0.2f, -1.0f, -0.3f};
    directional.intensity = 0.5f;
    return {point, sphere, tube, directional};
}

TEST(LightRig, AModelOfAnotherSizeIsLitAsTheOneTheRigWasMadeFor) {
    Scene scene = defaultScene();
    const std::vector<Light> unit = everyPositionalKind();
    const BoundingSphere from{glm::vec3(0.0f), 1.0f};
    const BoundingSphere to{glm::vec3(120.0f, -40.0f, 75.0f), 300.0f};
    std::vector<Light> moved = unit;
    moveLightRig(moved, from, to);
    int lit = 0;
    for (int i = 0; i < 64; ++i) {
        // Points of the unit sphere, and of the big one at the same place.
        const float theta = 0.1f + 2.9f * float(i) / 63.0f, phi = 0.77f * float(i);
        const glm::vec3 n{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
        const glm::vec3 before = radianceAt(scene, unit, from.center + n * from.radius, n);
        const glm::vec3 after = radianceAt(scene, moved, to.center + n * to.radius, n);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(after[c], before[c], 2e-4f * std::max(1.0f, before[c])) << "point " << i;
        }
        lit += before.r > 0.01f;
    }
    EXPECT_GT(lit, 16) << "the rig lights the sphere";
    // Without the move, the positional lights leave the big model dark: they are inside it.
    const std::vector<Light> positional(unit.begin(), unit.begin() + 3);
    const glm::vec3 n{0.0f, 1.0f, 0.0f};
    EXPECT_LT(radianceAt(scene, positional, to.center + n * to.radius, n).r,
              0.01f * radianceAt(scene, positional, from.center + n, n).r);
}

TEST(LightRig, OnlyPositionalLightsMoveAndABadRadiusMovesNothing) {
    const std::vector<Light> unit = everyPositionalKind();
    std::vector<Light> moved = unit;
    moveLightRig(moved, {glm::vec3(0.0f), 1.0f}, {glm::vec3(0.0f), 10.0f});
    EXPECT_EQ(moved[3], unit[3]) << "a directional light has no place or size";
    EXPECT_EQ(moved[0].position, unit[0].position * 10.0f);
    EXPECT_EQ(moved[2].end, unit[2].end * 10.0f);
    EXPECT_FLOAT_EQ(moved[1].sourceRadius, 4.0f);
    EXPECT_FLOAT_EQ(moved[0].range, 60.0f);
    for (const float bad : {0.0f, -1.0f, NAN, INFINITY}) {
        std::vector<Light> kept = unit;
        moveLightRig(kept, {glm::vec3(0.0f), 1.0f}, {glm::vec3(5.0f), bad});
        EXPECT_EQ(kept, unit) << bad;
        moveLightRig(kept, {glm::vec3(0.0f), bad}, {glm::vec3(5.0f), 2.0f});
        EXPECT_EQ(kept, unit) << bad;
    }
}

}  // namespace
}  // namespace patina
