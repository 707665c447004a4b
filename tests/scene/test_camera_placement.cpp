// Where the camera goes as the ecosystem puts it (scene/camera_placement.h): model-viewer's
// camera-orbit formula, its framing of a model it loads, and a glTF file's own cameras.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/camera_control.h"
#include "scene/camera_placement.h"
#include "scene/light_rig.h"
#include "scene/view.h"

namespace patina {
namespace {

void expectNear(glm::vec3 got, glm::vec3 want, float tolerance, const char* what) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], want[c], tolerance) << what << ", component " << c;
    }
}

// The turntable turns the eye about the vertical axis through the target as model-viewer's
// theta grows (from +Z towards +X), keeping its height and distance; a whole turn, and any
// number of them, is the start bit for bit, so the frame after a turntable's last is its first.
TEST(Turntable, TurnsTheEyeAboutTheTargetsVerticalAxisAndAWholeTurnIsTheStart) {
    Camera start;
    start.target = glm::vec3(0.3f, -0.2f, 0.1f);
    start.position = start.target + orbitOffset({0.0f, 70.0f, 2.5f});
    start.fovYDegrees = 38.0f;
    for (const float theta : {90.0f, 180.0f, 250.0f, -45.0f}) {
        const Camera turned = turntableCamera(start, theta);
        expectNear(turned.position, start.target + orbitOffset({theta, 70.0f, 2.5f}), 1e-5f, "turned eye");
        EXPECT_EQ(turned.target, start.target);
        EXPECT_EQ(turned.fovYDegrees, start.fovYDegrees);
        EXPECT_NE(turned.position, start.position) << theta;
    }
    for (const float whole : {0.0f, 360.0f, 720.0f, -360.0f}) {
        EXPECT_EQ(turntableCamera(start, whole), start) << whole;
    }
    // 360 k / N for the frames of a turn: N / N is the start again.
    EXPECT_EQ(turntableCamera(start, float(360.0 * 7 / 7)), start);
}

// modelviewer.dev: theta about +Y from +Z, phi down from +Y; theta 0 and phi 90 look from +Z
// towards -Z, theta 90 from +X, phi 0 from straight above.
TEST(Orbit, IsModelViewersCameraOrbit) {
    const glm::vec3 target(1.0f, 2.0f, 3.0f);
    Camera camera;
    placeOnOrbit(camera, target, {0.0f, 90.0f, 2.0f});
    expectNear(camera.position, target + glm::vec3(0.0f, 0.0f, 2.0f), 1e-6f, "front");
    EXPECT_EQ(camera.target, target);
    placeOnOrbit(camera, target, {90.0f, 90.0f, 2.0f});
    expectNear(camera.position, target + glm::vec3(2.0f, 0.0f, 0.0f), 1e-6f, "from +X");
    placeOnOrbit(camera, target, {0.0f, 0.0f, 2.0f});
    expectNear(camera.position, target + glm::vec3(0.0f, 2.0f, 0.0f), 1e-6f, "from above");
    // r (sin phi sin theta, cos phi, sin phi cos theta), worked by hand for 30 and 60 degrees.
    expectNear(orbitOffset({30.0f, 60.0f, 4.0f}), {4.0f * 0.8660254f * 0.5f, 4.0f * 0.5f, 4.0f * 0.8660254f * 0.8660254f},
               1e-5f, "30, 60");
    EXPECT_EQ(camera.fovYDegrees, Camera{}.fovYDegrees) << "the field of view stays";
}

// model-viewer's default view of a model it loads: from theta 0 and phi 75 degrees, at 105% of
// R / sin(fov / 2) from the bounding sphere's centre, whatever the camera looked at before
// (ClearCoatTest opened edge-on when the camera kept the last model's direction).
TEST(FrameAsModelViewer, LooksFromTheFrontAndAboveWithTheWholeSphereInView) {
    const BoundingSphere bounds{{10.0f, -4.0f, 2.0f}, 3.0f};
    Camera fromTheSide, fromBelow;
    fromTheSide.position = {-50.0f, 0.0f, 0.0f};
    fromBelow.position = {0.0f, -20.0f, 1.0f};
    fromBelow.fovYDegrees = fromTheSide.fovYDegrees = 30.0f;
    frameAsModelViewer(fromTheSide, bounds);
    frameAsModelViewer(fromBelow, bounds);
    EXPECT_EQ(fromTheSide, fromBelow) << "the previous direction plays no part";
    const Camera& camera = fromTheSide;
    EXPECT_EQ(camera.target, bounds.center);
    const float distance = 1.05f * 3.0f / std::sin(glm::radians(15.0f));
    const glm::vec3 offset = camera.position - camera.target;
    EXPECT_NEAR(glm::length(offset), distance, 1e-3f * distance);
    EXPECT_NEAR(glm::degrees(std::acos(offset.y / glm::length(offset))), 75.0f, 1e-3f) << "phi";
    EXPECT_NEAR(offset.x, 0.0f, 1e-4f) << "theta 0: straight in front";
    EXPECT_GT(offset.z, 0.0f) << "from +Z";
    // Every point of the sphere's silhouette is inside the picture, top to bottom.
    const glm::mat4 transform = viewProjection(camera, 1.0f);
    const glm::vec3 forward = glm::normalize(-offset);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, forward);
    for (int i = 0; i < 64; ++i) {
        const float a = float(i) * 6.2831853f / 64.0f;
        const glm::vec4 clip = transform * glm::vec4(bounds.center + bounds.radius * (std::cos(a) * right +
                                                                                       std::sin(a) * up), 1.0f);
        EXPECT_LT(std::abs(clip.y / clip.w), 1.0f) << i;
        EXPECT_LT(std::abs(clip.x / clip.w), 1.0f) << i;
    }
}

// A box given by --mesh or opened in the editor reads as a box, not a flat square: framed from
// 15 degrees above, its top faces the camera.
TEST(FrameAsModelViewer, OpeningABoxShowsItsTop) {
    Scene scene = defaultScene();
    fitSceneTo(scene, {glm::vec3(0.0f), 1.0f}, {glm::vec3(0.0f), std::sqrt(3.0f) * 0.5f});
    const glm::vec3 topCentre(0.0f, 0.5f, 0.0f), frontCentre(0.0f, 0.0f, 0.5f);
    EXPECT_GT(glm::dot(glm::vec3(0, 1, 0), scene.camera.position - topCentre), 0.0f) << "the top is seen";
    EXPECT_GT(glm::dot(glm::vec3(0, 0, 1), scene.camera.position - frontCentre), 0.0f) << "and the front";
}

ModelCamera fileCamera(glm::mat4 world, float yfov = 0.6f) {
    ModelCamera camera;
    camera.name = "shot";
    camera.yfov = yfov;
    camera.position = glm::vec3(world[3]);
    camera.forward = glm::normalize(-glm::vec3(world[2]));
    camera.up = glm::normalize(glm::vec3(world[1]));
    return camera;
}

// A glTF camera looks down its node's -Z with +Y up from the node's origin, yfov in radians:
// Patina's camera there looks the same way, its target on that line at the model's depth.
TEST(ModelCamera, IsPlacedAsItsNodePlacesIt) {
    const glm::mat4 world = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(6.0f, 1.0f, 0.0f)),
                                        glm::radians(90.0f), glm::vec3(0, 1, 0));   // -Z turned to -X
    Camera camera;
    const float roll = placeModelCamera(camera, fileCamera(world), {glm::vec3(0.0f), 1.0f});
    EXPECT_EQ(camera.position, glm::vec3(6.0f, 1.0f, 0.0f));
    expectNear(glm::normalize(camera.target - camera.position), {-1.0f, 0.0f, 0.0f}, 1e-6f, "looks down -X");
    EXPECT_NEAR(glm::length(camera.target - camera.position), 6.0f, 1e-5f) << "at the model's centre's depth";
    EXPECT_NEAR(camera.fovYDegrees, glm::degrees(0.6f), 1e-4f);
    EXPECT_NEAR(roll, 0.0f, 1e-3f);
    // Behind the camera, the model gives no depth: the target a tenth of its radius ahead.
    placeModelCamera(camera, fileCamera(world), {glm::vec3(20.0f, 0.0f, 0.0f), 5.0f});
    EXPECT_NEAR(glm::length(camera.target - camera.position), 0.5f, 1e-5f);
    // A camera turned 30 degrees about its view is shown level, and says how far it is rolled.
    const glm::mat4 rolled = glm::rotate(world, glm::radians(30.0f), glm::vec3(0, 0, 1));
    EXPECT_NEAR(std::abs(placeModelCamera(camera, fileCamera(rolled), {glm::vec3(0.0f), 1.0f})), 30.0f, 1e-3f);
    // The scene file's range of fields of view.
    placeModelCamera(camera, fileCamera(world, 3.2f), {glm::vec3(0.0f), 1.0f});
    EXPECT_EQ(camera.fovYDegrees, 179.0f);
}

TEST(ModelCamera, IsFoundByNameOrIndexAndAnOrthographicOneIsRefused) {
    ModelCamera front = fileCamera(glm::mat4(1.0f)), plan = front, again = front;
    front.name = "front";
    front.index = 0;
    plan.name = "plan";
    plan.index = 1;
    plan.perspective = false;
    again.name = "7";   // a name of digits is a name first
    again.index = 2;
    const std::vector<ModelCamera> cameras{front, plan, again};
    EXPECT_EQ(&findModelCamera(cameras, "front"), &cameras[0]);
    EXPECT_EQ(&findModelCamera(cameras, "0"), &cameras[0]);
    EXPECT_EQ(&findModelCamera(cameras, "7"), &cameras[2]);
    EXPECT_EQ(&findModelCamera(cameras, "2"), &cameras[2]);
    auto refusal = [&](const std::string& name) {
        try {
            findModelCamera(cameras, name);
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string("(found)");
    };
    EXPECT_EQ(refusal("1"), "camera 1 \"plan\" is orthographic: Patina draws perspective cameras only");
    EXPECT_EQ(refusal("side"), "the model has no camera \"side\" (its cameras, by index and name: 0 \"front\" "
                               "(perspective), 1 \"plan\" (orthographic), 2 \"7\" (perspective))");
    EXPECT_NE(refusal("3").find("no camera \"3\""), std::string::npos);
    EXPECT_NE(refusal("-1").find("no camera \"-1\""), std::string::npos);
    EXPECT_NE(refusal("99999999999999").find("no camera"), std::string::npos);
    EXPECT_EQ(modelCameraList({}), "none");
}

}  // namespace
}  // namespace patina
