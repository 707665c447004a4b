// Which draw item a ray meets first (engine/model/pick.h): through each item's transform,
// either face, the nearest of several.
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "model/pick.h"

namespace patina {
namespace {

// Two unit spheres drawn at z = 0 and z = -3, and a mirrored one at x = 3.
Model threeSpheres() {
    Model model;
    model.primitives = {makeUvSphere(16, 32)};
    model.draws = {{0, 0, glm::translate(glm::mat4(1.0f), {0, 0, -3}), "far"},
                   {0, 1, glm::mat4(1.0f), "near"},
                   {0, 2, glm::scale(glm::translate(glm::mat4(1.0f), {3, 0, 0}), {-1, 1, 1}), "mirrored", true}};
    return model;
}

TEST(Pick, TheNearestDrawAlongTheRayIsHit) {
    const Model model = threeSpheres();
    const DrawHit hit = firstDrawHit(model, {0, 0, 10}, {0, 0, -1});
    EXPECT_EQ(hit.draw, 1);
    EXPECT_NEAR(hit.distance, 9.0f, 0.01f);
    // From behind, the far one first; a ray's length is its unit of distance.
    const DrawHit back = firstDrawHit(model, {0, 0, -10}, {0, 0, 2});
    EXPECT_EQ(back.draw, 0);
    EXPECT_NEAR(back.distance, 3.0f, 0.01f);
    EXPECT_EQ(firstDrawHit(model, {3, 0, 10}, {0, 0, -1}).draw, 2);
}

TEST(Pick, ARayThatMissesOrPointsAwayHitsNothing) {
    const Model model = threeSpheres();
    EXPECT_EQ(firstDrawHit(model, {0, 5, 10}, {0, 0, -1}).draw, -1);
    EXPECT_EQ(firstDrawHit(model, {0, 0, 10}, {0, 0, 1}).draw, -1);
    EXPECT_EQ(firstDrawHit(Model{}, {0, 0, 10}, {0, 0, -1}).draw, -1);
    // From inside a sphere its far side is hit: both faces count.
    EXPECT_EQ(firstDrawHit(model, {0, 0, 0}, {0, 1, 0}).draw, 1);
}

}  // namespace
}  // namespace patina
