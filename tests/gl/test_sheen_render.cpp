// KHR_materials_sheen on the GPU (shade.frag's PATINA_SHEEN): the three paths draw the sheen
// alike under every light type and the environment, a sheen changes the picture (a colour of 0
// draws the bare program's bytes), and at the sphere's centre the GPU gives what sheen.glsl gives
// on the CPU: each light's base weighed by the albedo scaling, the sheen's lobe added.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "gl/renderer.h"
#include "scene/light_packing.h"
#include "shading/shading.h"
#include "test_support.h"

namespace patina {
namespace {

Material sheenMaterial(glm::vec3 sheenColor, float sheenRoughness) {
    Material material;
    material.model = BrdfModelId::Gltf;
    material.baseColor = {0.3f, 0.05f, 0.1f};   // a dark velvet
    material.roughness = 0.8f;
    material.metallic = 0.0f;
    material.sheenColor = sheenColor;
    material.sheenRoughness = sheenRoughness;
    return material;
}

// Every light type and the studio environment around the sphere.
Scene everyLight(glm::vec3 sheenColor) {
    Scene scene = defaultScene();
    scene.material = sheenMaterial(sheenColor, 0.4f);
    scene.lights = test::everyLightType();
    return scene;
}

double total(const HdrImage& image) {
    double sum = 0.0;
    for (float v : image.rgb) {
        sum += v;
    }
    return sum;
}

TEST(SheenRender, TheThreePathsDrawTheSheenAlikeAndItChangesThePicture) {
    test::glContext();
    Renderer renderer;
    const Scene sheened = everyLight(glm::vec3(1.0f, 0.8f, 0.9f));
    const HdrImage single = renderer.render(test::prepared(sheened), test::renderSettings(96, 96, RenderPath::Single, 1)).hdr;
    for (RenderPath path : {RenderPath::Multi, RenderPath::Specialised}) {
        const HdrImage other = renderer.render(test::prepared(sheened), test::renderSettings(96, 96, path, 1)).hdr;
        EXPECT_LE(test::maxRelativeDifference(other, single), 1e-4) << renderPathName(path);
    }
    const Scene bare = everyLight(glm::vec3(0.0f));
    const HdrImage unsheened = renderer.render(test::prepared(bare), test::renderSettings(96, 96, RenderPath::Single, 1)).hdr;
    // The sheen's light on a dark base: more than it takes from the base beneath.
    EXPECT_GT(total(single), 1.2 * total(unsheened));
    // A sheen of colour 0 is none (hasSheen): the bare program, the same bytes, roughness or not.
    Scene none = bare;
    none.material.sheenRoughness = 0.7f;
    for (RenderPath path : {RenderPath::Single, RenderPath::Specialised}) {
        const HdrImage a = renderer.render(test::prepared(none), test::renderSettings(48, 48, path, 1)).hdr;
        const HdrImage b = renderer.render(test::prepared(bare), test::renderSettings(48, 48, path, 1)).hdr;
        EXPECT_EQ(a.rgb, b.rgb) << renderPathName(path);
    }
}

// At the centre of a 31 x 31 image of the sphere seen down -z, N = V = +z. A directional light
// from 60 degrees off the view (H 30 degrees off N, where the Charlie lobe is not 0) and a
// hemisphere light: the GPU's pixel is the bare pixel times the CPU's base weight plus the CPU's
// sheen term (sheen.glsl compiled as C++, the same table).
TEST(SheenRender, AtTheSpheresCentreTheGpuIsTheCpuTwin) {
    test::glContext();
    Renderer renderer;
    for (bool hemisphere : {false, true}) {
        Light light;
        light.type = hemisphere ? LightType::Hemisphere : LightType::Directional;
        light.direction = {-std::sqrt(0.75f), 0.0f, -0.5f};
        light.intensity = 2.0f;
        light.sky = {0.5f, 0.5f, 0.5f};
        light.ground = {0.4f, 0.4f, 0.4f};   // what N = +z sees (up is +y)
        Scene scene = test::sphereSeenDownZ(light);
        const glm::vec3 color(0.9f, 0.6f, 1.0f);
        auto centre = [&](glm::vec3 sheenColor, RenderPath path) {
            scene.material = sheenMaterial(sheenColor, 0.7f);
            return test::centreBlue(renderer, scene, 31, path);
        };
        const glm::vec3 N(0.0f, 0.0f, 1.0f);
        const shader::Sheen sheen = shader::deriveSheen(color, 0.7f, N, N);
        const shader::PackedLight packed = packEnabledLights(scene.lights).at(0);
        const shader::SheenShare share = hemisphere ? shader::sheenHemisphereLight(packed, sheen, N)
                                                    : shader::sheenDirectionalLight(packed, sheen, N, N);
        EXPECT_GT(share.sheen.z, 0.0f);
        EXPECT_LT(share.baseWeight, 1.0f);
        for (RenderPath path : {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised}) {
            const float bare = centre(glm::vec3(0.0f), path);
            const float expected = bare * share.baseWeight + share.sheen.z;
            EXPECT_NEAR(centre(color, path), expected, 2e-3f * expected)
                << renderPathName(path) << (hemisphere ? " hemisphere" : " directional");
        }
    }
}

}  // namespace
}  // namespace patina
