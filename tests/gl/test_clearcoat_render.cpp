// KHR_materials_clearcoat on the GPU (shade.frag's PATINA_CLEARCOAT): the three paths draw the
// coat alike under every light type and the environment, a coat changes the picture, and at the
// sphere's centre the GPU gives what clearcoat.glsl gives on the CPU: the base weighed by
// 1 - clearcoat fr_c, the coat's lobe added.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "gl/renderer.h"
#include "shading/brdf_models.h"
#include "shading/shading.h"
#include "test_support.h"

namespace patina {
namespace {

Material coatedMaterial(float clearcoat) {
    Material material;
    material.model = BrdfModelId::Gltf;
    material.baseColor = {0.013f, 0.022f, 0.11f};   // ClearCoatTest's blue base
    material.roughness = 0.44f;
    material.metallic = 0.0f;
    material.clearcoat = clearcoat;
    material.clearcoatRoughness = 0.2f;
    return material;
}

// Every light type and the studio environment around the sphere.
Scene everyLight(float clearcoat) {
    Scene scene = defaultScene();
    scene.material = coatedMaterial(clearcoat);
    scene.lights = test::everyLightType();
    return scene;
}

TEST(ClearcoatRender, TheThreePathsDrawTheCoatAlikeAndItChangesThePicture) {
    test::glContext();
    Renderer renderer;
    const Scene coated = everyLight(1.0f);
    const HdrImage single = renderer.render(test::prepared(coated), test::renderSettings(96, 96, RenderPath::Single, 1)).hdr;
    for (RenderPath path : {RenderPath::Multi, RenderPath::Specialised}) {
        const HdrImage other = renderer.render(test::prepared(coated), test::renderSettings(96, 96, path, 1)).hdr;
        EXPECT_LE(test::maxRelativeDifference(other, single), 1e-4) << renderPathName(path);
    }
    const Scene bare = everyLight(0.0f);
    const HdrImage uncoated = renderer.render(test::prepared(bare), test::renderSettings(96, 96, RenderPath::Single, 1)).hdr;
    double brightest = 0.0, brightestBare = 0.0;
    for (size_t i = 0; i < single.rgb.size(); ++i) {
        brightest = std::max(brightest, double(single.rgb[i]));
        brightestBare = std::max(brightestBare, double(uncoated.rgb[i]));
    }
    // The coat's sharper highlights over the rough base.
    EXPECT_GT(brightest, 1.5 * brightestBare);
}

// At the centre of a 31 x 31 image of the sphere seen down -z, N = V = L = +z for a directional
// light from the eye: the base is weighed by 1 - fr_c(1) = 0.96 and the coat adds
// fr_c D(alpha_c) Vis(alpha_c) at N.H = 1; under a hemisphere light the coat only weighs the base.
TEST(ClearcoatRender, AtTheSpheresCentreTheGpuIsTheCpuTwin) {
    test::glContext();
    Renderer renderer;
    for (bool hemisphere : {false, true}) {
        Light light;
        light.type = hemisphere ? LightType::Hemisphere : LightType::Directional;
        light.direction = {0.0f, 0.0f, -1.0f};
        light.sky = {0.5f, 0.5f, 0.5f};
        Scene scene = test::sphereSeenDownZ(light);
        auto centre = [&](float clearcoat, RenderPath path) {
            scene.material = coatedMaterial(clearcoat);
            scene.material.clearcoatRoughness = 0.5f;   // a lobe broad against the mesh's facets
            return test::centreBlue(renderer, scene, 31, path);
        };
        const glm::vec3 N(0.0f, 0.0f, 1.0f);
        const shader::Clearcoat coat = shader::deriveClearcoat(1.0f, 0.5f, N, N);
        const float layer = hemisphere ? 0.0f : shader::clearcoatBrdf(coat, N, N);
        for (RenderPath path : {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised}) {
            const float bare = centre(0.0f, path);
            const float expected = bare * (1.0f - 0.04f) + layer;
            EXPECT_NEAR(centre(1.0f, path), expected, 2e-3f * expected)
                << renderPathName(path) << (hemisphere ? " hemisphere" : " directional");
        }
    }
}

}  // namespace
}  // namespace patina
