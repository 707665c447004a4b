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
    scene.lights.clear();
    Light point;
    point.type = LightType::Point;
    point.position = {1.5f, 1.0f, 2.0f};
    point.range = 8.0f;
    point.intensity = 4.0f;
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {-0.4f, -0.5f, -1.0f};
    sun.intensity = 1.5f;
    Light sky;
    sky.type = LightType::Hemisphere;
    sky.sky = {0.2f, 0.2f, 0.3f};
    Light sphere;
    sphere.type = LightType::Sphere;
    sphere.position = {-1.5f, 1.2f, 1.5f};
    sphere.sourceRadius = 0.2f;
    sphere.intensity = 3.0f;
    Light tube;
    tube.type = LightType::Tube;
    tube.start = {1.0f, -0.8f, 1.8f};
    tube.end = {1.5f, 0.2f, 1.8f};
    tube.sourceRadius = 0.05f;
    tube.intensity = 2.0f;
    Light environment;
    environment.type = LightType::Environment;
    environment.source = "builtin:studio";
    environment.intensity = 0.5f;
    scene.lights = {point, sun, sky, sphere, tube, environment};
    return scene;
}

double maxRelativeDifference(const HdrImage& a, const HdrImage& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        worst = std::max(worst, double(std::abs(a.rgb[i] - b.rgb[i])) / std::max(1e-2, double(std::abs(b.rgb[i]))));
    }
    return worst;
}

TEST(ClearcoatRender, TheThreePathsDrawTheCoatAlikeAndItChangesThePicture) {
    test::glContext();
    Renderer renderer;
    const Scene coated = everyLight(1.0f);
    const HdrImage single = renderer.render(test::prepared(coated), test::renderSettings(96, 96, RenderPath::Single, 1)).hdr;
    for (RenderPath path : {RenderPath::Multi, RenderPath::Specialised}) {
        const HdrImage other = renderer.render(test::prepared(coated), test::renderSettings(96, 96, path, 1)).hdr;
        EXPECT_LE(maxRelativeDifference(other, single), 1e-4) << renderPathName(path);
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
        Scene scene = defaultScene();
        scene.camera.position = {0.0f, 0.0f, 3.4f};
        scene.camera.target = {0.0f, 0.0f, 0.0f};
        Light light;
        light.type = hemisphere ? LightType::Hemisphere : LightType::Directional;
        light.direction = {0.0f, 0.0f, -1.0f};
        light.sky = {0.5f, 0.5f, 0.5f};
        scene.lights = {light};
        auto centre = [&](float clearcoat, RenderPath path) {
            scene.material = coatedMaterial(clearcoat);
            scene.material.clearcoatRoughness = 0.5f;   // a lobe broad against the mesh's facets
            const HdrImage image = renderer.render(test::prepared(scene), test::renderSettings(31, 31, path, 1)).hdr;
            return image.rgb[(15 * 31 + 15) * 3 + 2];   // blue, the base's strongest
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
