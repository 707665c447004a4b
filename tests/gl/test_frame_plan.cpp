// What a draw decides before it touches the GL (engine/gl/frame_plan.h).
#include <algorithm>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/frame_plan.h"
#include "geometry/hidden_faces.h"
#include "geometry/mesh.h"
#include "scene/scene.h"
#include "test_support.h"

namespace patina {
namespace {

using FlatLights = RenderSettings::FlatLights;

RenderSettings settingsOf(RenderPath passes, int samples) {
    RenderSettings settings = test::renderSettings(320, 200, passes, samples);
    settings.readHdr = false;
    return settings;
}

// A UV sphere as MeshBuffers describes it: closed, wound outward, one convex part.
MeshFacts sphereFacts() {
    const Mesh sphere = makeUvSphere(16, 32);
    return {boundingBox(sphere), faceCulling(sphere), sphere.indices.size() / 3};
}

constexpr int kMaxSamples = 8;
constexpr size_t kSlots = 14;

// The mesh is drawn once per strip that meets the drawn area, and the box bounds its pixels.
TEST(FramePlan, FlatLightSlotsWeighTheBoxAgainstTrianglesDrawn) {
    const size_t slots = 14;
    const PixelRect box{0, 0, 1000, 1000};
    EXPECT_EQ(flatLightSlotsFor(FlatLights::WherePaying, slots, box, box, 1000, 16384), slots);
    EXPECT_EQ(flatLightSlotsFor(FlatLights::WherePaying, slots, box, box, 1000, 1'000'000), 0u);
    // 30,000 triangles: 33 pixels each in one draw, 3.3 in ten strips of 100 rows.
    EXPECT_EQ(flatLightSlotsFor(FlatLights::WherePaying, slots, box, box, 1000, 30'000), slots);
    EXPECT_EQ(flatLightSlotsFor(FlatLights::WherePaying, slots, box, box, 100, 30'000), 0u);
    // A box 200 rows high meets 2 strips when drawn cropped, all 10 when not (cropToMesh off).
    const PixelRect band{0, 400, 1000, 600};
    const PixelRect whole{0, 0, 1000, 1000};
    EXPECT_EQ(flatLightSlotsFor(FlatLights::WherePaying, slots, band, band, 100, 10'000), slots);
    EXPECT_EQ(flatLightSlotsFor(FlatLights::WherePaying, slots, band, whole, 100, 10'000), 0u);
    // Nothing on screen: nothing to gain. Forced either way, the box does not matter.
    EXPECT_EQ(flatLightSlotsFor(FlatLights::WherePaying, slots, PixelRect{}, whole, 1000, 10), 0u);
    EXPECT_EQ(flatLightSlotsFor(FlatLights::Always, slots, PixelRect{}, whole, 1000, 1'000'000), slots);
    EXPECT_EQ(flatLightSlotsFor(FlatLights::Never, slots, box, box, 1000, 10), 0u);
}

// Without MSAA single and specialised show their values from the shading pass itself; multi
// sums its passes into the linear image first, so it keeps one even when not asked to.
TEST(FramePlan, WithoutMsaaOnlyMultiNeedsADisplayPass) {
    const Camera camera = defaultScene().camera;
    for (RenderPath passes : {RenderPath::Single, RenderPath::Specialised, RenderPath::Multi}) {
        const bool multi = passes == RenderPath::Multi;
        const FramePlan plan = planFrame(settingsOf(passes, 1), camera, sphereFacts(), kMaxSamples, kSlots);
        EXPECT_FALSE(plan.msaa);
        EXPECT_EQ(plan.displayInPass, !multi) << renderPathName(passes);
        EXPECT_EQ(plan.keepLinear, multi) << renderPathName(passes);
        EXPECT_EQ(plan.stripRows, 200);
        EXPECT_EQ(plan.meshArea, (PixelRect{0, 0, 320, 200})) << "no samples to save: every pixel";
        RenderSettings hdr = settingsOf(passes, 1);
        hdr.readHdr = true;
        EXPECT_TRUE(planFrame(hdr, camera, sphereFacts(), kMaxSamples, kSlots).keepLinear);
    }
}

// MSAA: the count the GL offers at most, a resolve for every path, samples only in the mesh's
// box unless told otherwise, strips when the samples' bytes are capped.
TEST(FramePlan, MsaaResolvesAndShadesOnlyTheMeshsBox) {
    const Camera camera = defaultScene().camera;
    const FramePlan plan = planFrame(settingsOf(RenderPath::Single, 16), camera, sphereFacts(), kMaxSamples, kSlots);
    EXPECT_EQ(plan.samples, kMaxSamples);
    EXPECT_TRUE(plan.msaa);
    EXPECT_FALSE(plan.displayInPass);
    EXPECT_FALSE(plan.keepLinear);
    EXPECT_EQ(plan.transform, viewProjection(camera, 320.0f / 200.0f));
    EXPECT_EQ(plan.meshBox, screenBounds(plan.transform, sphereFacts().bounds, 320, 200));
    EXPECT_EQ(plan.meshArea, plan.meshBox);
    EXPECT_LT(plan.meshArea.x1 - plan.meshArea.x0, 320) << "the framed sphere leaves background beside it";
    EXPECT_EQ(plan.stripRows, 200);

    RenderSettings uncropped = settingsOf(RenderPath::Single, 4);
    uncropped.cropToMesh = false;
    EXPECT_EQ(planFrame(uncropped, camera, sphereFacts(), kMaxSamples, kSlots).meshArea, (PixelRect{0, 0, 320, 200}));

    RenderSettings capped = settingsOf(RenderPath::Single, 4);
    capped.maxTargetBytes = size_t(320) * 4 * 16 * 50;   // 50 rows of 4 float RGBA samples
    EXPECT_EQ(planFrame(capped, camera, sphereFacts(), kMaxSamples, kSlots).stripRows, 50);
    EXPECT_EQ(stripRowsFor(capped, 4), 50);

    RenderSettings hdr = settingsOf(RenderPath::Single, 4);
    hdr.readHdr = true;
    EXPECT_TRUE(planFrame(hdr, camera, sphereFacts(), kMaxSamples, kSlots).keepLinear);

    RenderSettings single = settingsOf(RenderPath::Single, 1);
    single.maxTargetBytes = size_t(320) * 16 * 50;   // 50 rows of one float RGBA sample
    ASSERT_EQ(stripRowsFor(single, 1), 50);
    EXPECT_EQ(planFrame(single, camera, sphereFacts(), kMaxSamples, kSlots).stripRows, 200)
        << "without MSAA the full-size images are drawn whole";

    for (int samples : {-3, 0, 1}) {
        const RenderSettings settings = settingsOf(RenderPath::Single, samples);
        const FramePlan none = planFrame(settings, camera, sphereFacts(), kMaxSamples, kSlots);
        EXPECT_FALSE(none.msaa);
        EXPECT_EQ(none.samples, std::max(samples, 0));
    }
    EXPECT_FALSE(planFrame(settingsOf(RenderPath::Single, 4), camera, sphereFacts(), 1, kSlots).msaa)
        << "a GL without multisampling";
}

// Faces are culled only where the eye is outside a closed mesh, and the depth test is left
// out only when what is left is one convex part.
TEST(FramePlan, CullsOnlyWithTheEyeOutsideAClosedMesh) {
    const Camera outside = defaultScene().camera;
    const MeshFacts sphere = sphereFacts();
    ASSERT_EQ(sphere.culling.hidden, HiddenFaces::Back);
    ASSERT_TRUE(sphere.culling.convex);
    const RenderSettings settings = settingsOf(RenderPath::Single, 4);

    FramePlan plan = planFrame(settings, outside, sphere, kMaxSamples, kSlots);
    EXPECT_EQ(plan.items[0].culled, HiddenFaces::Back);
    EXPECT_FALSE(plan.depthTest);

    Camera inside = outside;
    inside.position = {0.0f, 0.0f, 0.5f};
    plan = planFrame(settings, inside, sphere, kMaxSamples, kSlots);
    EXPECT_EQ(plan.items[0].culled, HiddenFaces::None);
    EXPECT_TRUE(plan.depthTest);

    RenderSettings everyFace = settings;
    everyFace.cullHiddenFaces = false;
    plan = planFrame(everyFace, outside, sphere, kMaxSamples, kSlots);
    EXPECT_EQ(plan.items[0].culled, HiddenFaces::None);
    EXPECT_TRUE(plan.depthTest);

    MeshFacts inward = sphere;
    inward.culling.hidden = HiddenFaces::Front;
    EXPECT_EQ(planFrame(settings, outside, inward, kMaxSamples, kSlots).items[0].culled, HiddenFaces::Front);

    MeshFacts torusLike = sphere;
    torusLike.culling.convex = false;
    plan = planFrame(settings, outside, torusLike, kMaxSamples, kSlots);
    EXPECT_EQ(plan.items[0].culled, HiddenFaces::Back);
    EXPECT_TRUE(plan.depthTest) << "culled faces of a non-convex mesh can still overlap";

    MeshFacts open = sphere;
    open.culling = {};
    plan = planFrame(settings, outside, open, kMaxSamples, kSlots);
    EXPECT_EQ(plan.items[0].culled, HiddenFaces::None);
    EXPECT_TRUE(plan.depthTest);
}

// Flat lights follow the settings, weighed over the box and strips this plan draws.
TEST(FramePlan, FlatLightsWeighThisPlansBoxAndStrips) {
    const Camera camera = defaultScene().camera;
    RenderSettings settings = settingsOf(RenderPath::Specialised, 4);
    const FramePlan plan = planFrame(settings, camera, sphereFacts(), kMaxSamples, kSlots);
    EXPECT_EQ(plan.flatLightCount, flatLightSlotsFor(FlatLights::WherePaying, kSlots, plan.meshBox, plan.meshArea,
                                                 plan.stripRows, sphereFacts().triangles));
    MeshFacts dense = sphereFacts();
    dense.triangles = 10'000'000;   // far under a pixel a triangle
    EXPECT_EQ(planFrame(settings, camera, dense, kMaxSamples, kSlots).flatLightCount, 0u);

    // In strips of 20 rows the mesh is drawn once per strip that meets the area drawn: all 10
    // uncropped, fewer cropped to a distant sphere's box. With triangles just too many for 4
    // pixels each over 10 draws, the cropped plan takes flat lights and the uncropped does not.
    Camera distant = camera;
    distant.position = camera.target + 2.0f * (camera.position - camera.target);
    RenderSettings strips = settingsOf(RenderPath::Specialised, 4);
    strips.maxTargetBytes = size_t(320) * 4 * 16 * 20;
    const PixelRect box = screenBounds(viewProjection(distant, 1.6f), sphereFacts().bounds, 320, 200);
    ASSERT_LT(box.y1 - box.y0, 120) << "the box meets at most 7 of the 10 strips";
    MeshFacts many = sphereFacts();
    many.triangles = size_t(double(box.x1 - box.x0) * double(box.y1 - box.y0) / 40.0) + 1;
    EXPECT_EQ(planFrame(strips, distant, many, kMaxSamples, kSlots).flatLightCount, kSlots);
    strips.cropToMesh = false;
    EXPECT_EQ(planFrame(strips, distant, many, kMaxSamples, kSlots).flatLightCount, 0u);

    settings.flatLightUse = FlatLights::Always;
    EXPECT_EQ(planFrame(settings, camera, dense, kMaxSamples, kSlots).flatLightCount, kSlots);
    settings.flatLightUse = FlatLights::Never;
    EXPECT_EQ(planFrame(settings, camera, sphereFacts(), kMaxSamples, kSlots).flatLightCount, 0u);
}

// Two spheres side by side, one blended: how each item is drawn and what the frame covers.
std::vector<DrawFacts> twoSpheres() {
    DrawFacts left{sphereFacts(), glm::translate(glm::mat4(1.0f), glm::vec3(-1.2f, 0.0f, 0.0f))};
    DrawFacts right{sphereFacts(), glm::translate(glm::mat4(1.0f), glm::vec3(1.2f, 0.0f, 0.0f))};
    return {left, right};
}

// The frame's box is every item's, each placed by its transform.
TEST(FramePlan, TheBoxHoldsEveryItemWhereItIs) {
    const Camera camera = defaultScene().camera;
    const RenderSettings settings = settingsOf(RenderPath::Single, 4);
    const std::vector<DrawFacts> items = twoSpheres();
    const FramePlan plan = planFrame(settings, camera, items, kMaxSamples, kSlots);
    for (const DrawFacts& item : items) {
        const PixelRect box = screenBounds(plan.transform * item.transform, item.mesh.bounds, 320, 200);
        EXPECT_LE(plan.meshBox.x0, box.x0);
        EXPECT_LE(plan.meshBox.y0, box.y0);
        EXPECT_GE(plan.meshBox.x1, box.x1);
        EXPECT_GE(plan.meshBox.y1, box.y1);
    }
    const PixelRect untransformed = screenBounds(plan.transform, sphereFacts().bounds, 320, 200);
    EXPECT_GT(plan.meshBox.x1 - plan.meshBox.x0, untransformed.x1 - untransformed.x0 + 40);
    EXPECT_EQ(plan.meshArea, plan.meshBox);
    EXPECT_TRUE(planFrame(settings, camera, std::vector<DrawFacts>{}, kMaxSamples, kSlots).meshBox.empty());
}

// Each item culls its own hidden side (the eye is outside each sphere), but two convex items'
// faces may share a sample: the depth test stays. A single-sided item culls its back faces
// wherever the eye is (glTF 2.0 §3.9.5), and a mirrored one turns its front winding round.
TEST(FramePlan, EachItemIsCulledAndWoundByItsOwnFacts) {
    const Camera camera = defaultScene().camera;
    const RenderSettings settings = settingsOf(RenderPath::Single, 4);
    std::vector<DrawFacts> items = twoSpheres();
    FramePlan plan = planFrame(settings, camera, items, kMaxSamples, kSlots);
    ASSERT_EQ(plan.items.size(), 2u);
    EXPECT_EQ(plan.items[0].culled, HiddenFaces::Back);
    EXPECT_EQ(plan.items[1].culled, HiddenFaces::Back);
    EXPECT_TRUE(plan.depthTest) << "the shortcut of one convex mesh does not hold for two";

    Camera inside = camera;
    inside.position = {1.2f, 0.0f, 0.5f};   // in the right sphere
    items[0].doubleSided = false;
    plan = planFrame(settings, inside, items, kMaxSamples, kSlots);
    EXPECT_EQ(plan.items[0].culled, HiddenFaces::Back);
    EXPECT_EQ(plan.items[1].culled, HiddenFaces::None) << "its inside is seen";

    items[1].transform = glm::scale(items[1].transform, glm::vec3(1.0f, -1.0f, 1.0f));
    plan = planFrame(settings, camera, items, kMaxSamples, kSlots);
    EXPECT_FALSE(plan.items[0].frontClockwise);
    EXPECT_TRUE(plan.items[1].frontClockwise);
}

// Blended items come after the opaque ones, farthest first; the display values then come from
// a display pass, over the composited linear values.
TEST(FramePlan, BlendedItemsComeLastFarthestFirst) {
    Camera camera = defaultScene().camera;
    camera.position = {-4.0f, 0.0f, 0.0f};   // on the left: the right sphere is the farther
    camera.target = {0.0f, 0.0f, 0.0f};
    std::vector<DrawFacts> items = twoSpheres();
    DrawFacts middle{sphereFacts()};
    items.insert(items.begin(), middle);
    for (DrawFacts& item : items) {
        item.blend = true;
    }
    items[1].blend = false;   // the left one, opaque
    const FramePlan plan = planFrame(settingsOf(RenderPath::Single, 1), camera, items, kMaxSamples, kSlots);
    ASSERT_EQ(plan.items.size(), 3u);
    EXPECT_EQ(plan.items[0].item, 1u);
    EXPECT_EQ(plan.items[1].item, 2u) << "the right sphere, farthest from the eye";
    EXPECT_EQ(plan.items[2].item, 0u);
    EXPECT_TRUE(plan.blending);
    EXPECT_FALSE(plan.displayInPass);
    EXPECT_TRUE(plan.keepLinear);
}

}  // namespace
}  // namespace patina
