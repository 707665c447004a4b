// Ambient occlusion by rays (geometry/ambient_occlusion.h, issue 37 item 2): a point sees all of
// its sky in the open, none under a roof, half of it (cosine-weighted) beside a wall; a sphere
// over the ground darkens the ground under it and its own underside (scene/ambient_occlusion.h).
#include <gtest/gtest.h>

#include "geometry/ambient_occlusion.h"
#include "scene/ambient_occlusion.h"
#include "scene/ground.h"

namespace patina {
namespace {

constexpr float kFar = 1e4f;

// Two-sided quad of corners a, b, c, d.
RayCaster quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    return RayCaster({a, b, c, d}, {0, 1, 2, 0, 2, 3, 0, 2, 1, 0, 3, 2});
}

TEST(AmbientOcclusion, APointSeesAllOfItsSkyInTheOpenNoneUnderARoofAndHalfBesideAWall) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const OcclusionRays rays;
    const RayCaster nothing({}, {});
    EXPECT_EQ(unoccludedShare(nothing, {0, 0, 0}, up, rays, 7), 1.0f);
    const RayCaster roof = quad({-kFar, 1, -kFar}, {kFar, 1, -kFar}, {kFar, 1, kFar}, {-kFar, 1, kFar});
    EXPECT_EQ(unoccludedShare(roof, {0, 0, 0}, up, rays, 7), 0.0f);
    // A wall rising from the floor at x = 0: the rays towards -x (half of a cosine lobe about +y)
    // meet it.
    const RayCaster wall = quad({0, 0, -kFar}, {0, kFar, -kFar}, {0, kFar, kFar}, {0, 0, kFar});
    // Each point's 8 x 8 strata cut by the wall's plane: within a row of them (1/8) alone; the
    // jitter differs point by point, so the mean over points is closer.
    float sum = 0.0f;
    for (uint32_t seed = 0; seed < 32; ++seed) {
        const float share = unoccludedShare(wall, {1e-3f, 0, 0}, up, rays, seed);
        EXPECT_NEAR(share, 0.5f, 0.125f) << seed;
        sum += share;
    }
    EXPECT_NEAR(sum / 32.0f, 0.5f, 0.02f);
    // Only within reach: a roof beyond it hides nothing.
    OcclusionRays near = rays;
    near.reach = 0.5f;
    EXPECT_EQ(unoccludedShare(roof, {0, 0, 0}, up, near, 7), 1.0f);
}

TEST(AmbientOcclusion, ASphereOverTheGroundDarkensTheGroundUnderItAndItsOwnUnderside) {
    const Mesh sphere = makeUvSphere(16, 32);
    const AmbientOcclusion open = bakeAmbientOcclusion(sphere, nullptr, false);
    ASSERT_EQ(open.items.size(), 1u);
    ASSERT_EQ(open.items[0].size(), sphere.positions.size());
    EXPECT_TRUE(open.groundValues.empty());
    // A convex shape alone hides nothing of any vertex's sky.
    for (const float value : open.items[0]) {
        EXPECT_EQ(value, 1.0f);
    }
    const AmbientOcclusion grounded = bakeAmbientOcclusion(sphere, nullptr, true);
    ASSERT_EQ(grounded.groundValues.size(), grounded.ground.positions.size());
    EXPECT_EQ(grounded.ground.positions.size(), size_t((kOcclusionGroundCells + 1) * (kOcclusionGroundCells + 1)));
    EXPECT_EQ(groundUnder(boundingBox(sphere)).centre.y, grounded.ground.positions[0].y);
    for (size_t i = 0; i < sphere.positions.size(); ++i) {
        const float y = sphere.positions[i].y;
        if (y > 0.9f) {
            EXPECT_GT(grounded.items[0][i], 0.9f) << "the top sees little of the ground";
            EXPECT_EQ(open.items[0][i], 1.0f);
        } else if (y < -0.9f) {
            EXPECT_LT(grounded.items[0][i], 0.2f) << "the underside faces the ground";
        }
    }
    // On the ground: darkest under the sphere, open at the ground's edge.
    float under = 1.0f, edge = 0.0f;
    for (size_t i = 0; i < grounded.ground.positions.size(); ++i) {
        const glm::vec3 p = grounded.ground.positions[i];
        if (std::abs(p.x) < 0.1f && std::abs(p.z) < 0.1f) {
            under = std::min(under, grounded.groundValues[i]);
        } else if (std::abs(p.x) > 9.0f) {
            edge = std::max(edge, grounded.groundValues[i]);
        }
    }
    EXPECT_LT(under, 0.1f);
    EXPECT_GT(edge, 0.99f);
    EXPECT_EQ(itemOcclusion(grounded, -1, sphere.positions.size()), &grounded.items[0]);
    EXPECT_EQ(itemOcclusion(grounded, -1, sphere.positions.size() + 1), nullptr) << "baked for another shape";
    EXPECT_EQ(itemOcclusion(grounded, 3, sphere.positions.size()), nullptr);
}

}  // namespace
}  // namespace patina
