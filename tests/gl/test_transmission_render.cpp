// KHR_materials_transmission and KHR_materials_volume on the GPU (shade.frag's
// PATINA_TRANSMISSION): the three paths draw them alike, a transmission changes the picture and
// a material without one draws the bare program's bytes; at the centre of a sphere seen down -z
// the environment behind it is seen through, tinted by the base colour and attenuated as
// Beer-Lambert says, as transmission.glsl gives it on the CPU; and a light behind the sphere
// shines through by the mirrored BTDF.
#include <cmath>

#include <gtest/gtest.h>

#include "environment/environment.h"
#include "gl/renderer.h"
#include "model/model.h"
#include "scene/light_packing.h"
#include "shading/cpu_shading.h"
#include "shading/shading.h"
#include "test_support.h"

namespace patina {
namespace {

Material glass(glm::vec3 baseColor, float transmission) {
    Material material;
    material.model = BrdfModelId::Gltf;
    material.baseColor = baseColor;
    material.roughness = 0.4f;
    material.metallic = 0.0f;
    material.transmission = transmission;
    return material;
}

Light studio() {
    Light environment;
    environment.type = LightType::Environment;
    environment.source = "builtin:studio";
    environment.intensity = 1.0f;
    return environment;
}

// A light behind the sphere (travelling +z, towards the camera), 20 degrees off the axis.
Light behind() {
    Light light;
    light.type = LightType::Directional;
    light.direction = {std::sin(0.35f), 0.0f, std::cos(0.35f)};
    light.intensity = 3.0f;
    return light;
}

glm::vec3 centre(Renderer& renderer, const Scene& scene, RenderPath path) {
    const int size = 31;
    const HdrImage image = renderer.render(test::prepared(scene), test::renderSettings(size, size, path, 1)).hdr;
    return test::pixel(image, size / 2, size / 2);
}

TEST(TransmissionRender, TheThreePathsDrawItAlikeItChangesThePictureAndNoneIsTheBareProgram) {
    test::glContext();
    Renderer renderer;
    Scene scene = defaultScene();
    scene.lights = test::everyLightType();
    scene.lights.push_back(behind());
    scene.material = glass({0.9f, 0.8f, 0.7f}, 0.8f);
    scene.material.thickness = 0.5f;
    scene.material.attenuationColor = {0.9f, 0.6f, 0.3f};
    scene.material.attenuationDistance = 1.0f;
    const HdrImage single = renderer.render(test::prepared(scene), test::renderSettings(96, 96, RenderPath::Single, 1)).hdr;
    for (RenderPath path : {RenderPath::Multi, RenderPath::Specialised}) {
        const HdrImage other = renderer.render(test::prepared(scene), test::renderSettings(96, 96, path, 1)).hdr;
        EXPECT_LE(test::maxRelativeDifference(other, single), 1e-4) << renderPathName(path);
    }
    Scene opaque = scene;
    opaque.material.transmission = 0.0f;
    const HdrImage solid = renderer.render(test::prepared(opaque), test::renderSettings(96, 96, RenderPath::Single, 1)).hdr;
    EXPECT_GT(test::maxRelativeDifference(single, solid), 0.2);
    // A transmission of 0 is none (hasTransmission): the bare program, the same bytes, whatever
    // the volume says.
    Scene bare = opaque;
    bare.material.thickness = 0.0f;
    bare.material.attenuationColor = glm::vec3(1.0f);
    bare.material.attenuationDistance = 0.0f;
    for (RenderPath path : {RenderPath::Single, RenderPath::Specialised}) {
        const HdrImage a = renderer.render(test::prepared(opaque), test::renderSettings(48, 48, path, 1)).hdr;
        const HdrImage b = renderer.render(test::prepared(bare), test::renderSettings(48, 48, path, 1)).hdr;
        EXPECT_EQ(a.rgb, b.rgb) << renderPathName(path);
    }
}

// At the centre N = V = +z: a white clear glass less a black one (the reflection alike, the
// diffuse gone in both) is the environment behind seen through, the CPU twin's value; a tinted
// base and a volume scale it by the base colour and by attenuationColor^(thickness / distance).
TEST(TransmissionRender, AtTheSpheresCentreTheEnvironmentBehindIsSeenThroughTintedAndAttenuated) {
    test::glContext();
    Renderer renderer;
    Scene scene = test::sphereSeenDownZ(studio());
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    const std::shared_ptr<const Environment> environment = test::madeEnvironment("builtin:studio");
    for (RenderPath path : {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised}) {
        auto at = [&](const Material& material) {
            scene.material = material;
            return centre(renderer, scene, path);
        };
        const glm::vec3 black = at(glass(glm::vec3(0.0f), 1.0f));
        const glm::vec3 through = at(glass(glm::vec3(1.0f), 1.0f)) - black;
        const shader::SurfaceMaterial white = surfaceMaterial(glass(glm::vec3(1.0f), 1.0f));
        const shader::Transmission t = shader::deriveTransmission(white, 1.0f, glm::vec3(1.0f), N, N);
        const glm::vec3 twin = transmissionEnvironmentOnCpu(BrdfModelId::Gltf, white, t, *environment, 1.0f, 0.0f, N);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(through[c], twin[c], 0.01f * twin[c] + 1e-4f) << renderPathName(path) << " channel " << c;
        }
        // The same white sphere opaque shows its diffuse, not what lies behind.
        const glm::vec3 opaque = at(glass(glm::vec3(1.0f), 0.0f));
        EXPECT_GT(glm::length(opaque - (through + black)), 0.1f * glm::length(through)) << renderPathName(path);
        // Tinted by the base colour, channel by channel.
        const glm::vec3 tint(0.9f, 0.5f, 0.2f);
        const glm::vec3 tinted = at(glass(tint, 1.0f)) - black;
        // Beer-Lambert: thickness 2 at distance 1 squares the attenuation colour.
        Material volume = glass(glm::vec3(1.0f), 1.0f);
        volume.thickness = 2.0f;
        volume.attenuationColor = {1.0f, 0.5f, 0.25f};
        volume.attenuationDistance = 1.0f;
        const glm::vec3 attenuated = at(volume) - black;
        const glm::vec3 T(1.0f, 0.25f, 0.0625f);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(tinted[c], tint[c] * through[c], 0.01f * through[c] + 1e-4f) << renderPathName(path) << c;
            EXPECT_NEAR(attenuated[c], T[c] * through[c], 0.01f * through[c] + 1e-4f) << renderPathName(path) << c;
        }
    }
}

// A directional light behind the sphere: what passes towards the camera at the centre is the
// CPU's transmissionDirectionalLight (the mirrored lobe, tinted).
TEST(TransmissionRender, ALightBehindShinesThroughByTheMirroredBtdf) {
    test::glContext();
    Renderer renderer;
    Scene scene = test::sphereSeenDownZ(behind());
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    const glm::vec3 tint(0.9f, 0.6f, 0.3f);
    const shader::SurfaceMaterial surface = surfaceMaterial(glass(tint, 0.7f));
    const shader::Transmission t = shader::deriveTransmission(surface, 0.7f, glm::vec3(1.0f), N, N);
    const glm::vec3 expected = shader::transmissionDirectionalLight(packEnabledLights(scene.lights).at(0), t, N, N);
    EXPECT_GT(expected.x, 0.01f);
    for (RenderPath path : {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised}) {
        scene.material = glass(tint, 0.7f);
        const glm::vec3 lit = centre(renderer, scene, path);
        scene.material = glass(tint, 0.0f);
        const glm::vec3 solid = centre(renderer, scene, path);
        // The light behind does not reach the opaque front: all of it is through the wall.
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(solid[c], 0.0f, 1e-6f) << renderPathName(path);
            EXPECT_NEAR(lit[c], expected[c], 2e-3f * expected[c] + 1e-5f) << renderPathName(path) << " channel " << c;
        }
    }
}

// A quad facing +z at depth z over [x0, x1] x [-1, 1], with the material `material`.
Mesh quadAt(float z, float x0, float x1) {
    Mesh mesh;
    mesh.positions = {{x0, -1, z}, {x1, -1, z}, {x1, 1, z}, {x0, 1, z}};
    mesh.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

// The scene's opaque parts are seen through a transmitting one (engine/gl/scene_behind.h): a
// clear white glass pane in front of a lit red quad that covers the left half of the view. Where
// the quad is behind the pane, the pane shows what it shows alone plus the quad's own radiance
// weighed by 1 - F(N.V) (no environment: docs/SHADING.md S7); where nothing is behind it, the
// pane alone, to the bit. Alike on every path: the multi path draws the scene behind with the
// single path's programs and adds it in an item's first pass only.
TEST(TransmissionRender, TheSceneBehindIsSeenThrough) {
    test::glContext();
    Renderer renderer;
    Light front;
    front.type = LightType::Directional;
    front.direction = glm::normalize(glm::vec3(0.3f, -0.2f, -1.0f));   // travelling away from the camera
    front.intensity = 2.0f;
    Scene scene = test::sphereSeenDownZ(front);
    scene.material.model = BrdfModelId::Gltf;
    ModelMaterial pane;
    pane.factors = glass(glm::vec3(1.0f), 1.0f);
    pane.factors.roughness = 0.2f;
    ModelMaterial red;
    red.factors = glass({0.8f, 0.1f, 0.05f}, 0.0f);
    auto modelOf = [](std::vector<Mesh> primitives, std::vector<ModelMaterial> materials) {
        Model model;
        for (size_t i = 0; i < primitives.size(); ++i) {
            model.draws.push_back({int(i), int(i), glm::mat4(1.0f), "quad " + std::to_string(i)});
        }
        model.primitives = std::move(primitives);
        model.materials = std::move(materials);
        return std::make_shared<const Model>(std::move(model));
    };
    const auto both = modelOf({quadAt(0.5f, -1.0f, 1.0f), quadAt(-0.5f, -3.0f, 0.0f)}, {pane, red});
    const auto paneAlone = modelOf({quadAt(0.5f, -1.0f, 1.0f)}, {pane});
    const auto redAlone = modelOf({quadAt(-0.5f, -3.0f, 0.0f)}, {red});
    // Framed by both quads, whichever is drawn.
    auto frame = std::make_shared<Mesh>(quadAt(0.5f, -1.0f, 1.0f));
    const Mesh back = quadAt(-0.5f, -3.0f, 0.0f);
    for (glm::vec3 p : back.positions) {
        frame->positions.push_back(p);
        frame->normals.push_back(glm::vec3(0.0f, 0.0f, 1.0f));
    }
    const int size = 64;
    auto render = [&](const std::shared_ptr<const Model>& model, RenderPath path) {
        const PreparedScene prepared{scene, frame, nullptr, model};
        return renderer.render(prepared, test::renderSettings(size, size, path, 1)).hdr;
    };
    // Through the pane at x = -0.6 the view meets the red quad; at x = +0.6 nothing.
    const glm::ivec2 overRed = test::pixelOf(scene.camera, {-0.6f, 0.0f, 0.5f}, size, size);
    const glm::ivec2 overNothing = test::pixelOf(scene.camera, {0.6f, 0.0f, 0.5f}, size, size);
    const glm::vec3 V = glm::normalize(scene.camera.position - glm::vec3(-0.6f, 0.0f, 0.5f));
    const float F = shader::F_Schlick(glm::vec3(0.04f), V.z).x;
    const HdrImage redImage = render(redAlone, RenderPath::Single);
    const glm::vec3 redSeen = test::pixel(redImage, overRed.x, overRed.y);
    ASSERT_GT(redSeen.x, 0.05f);
    for (RenderPath path : {RenderPath::Single, RenderPath::Specialised, RenderPath::Multi}) {
        const HdrImage shown = render(both, path), alone = render(paneAlone, path);
        const glm::vec3 expected = test::pixel(alone, overRed.x, overRed.y) +
                                   (1.0f - F) * redSeen;
        const glm::vec3 seen = test::pixel(shown, overRed.x, overRed.y);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(seen[c], expected[c], 0.01f * expected[c] + 1e-4f) << renderPathName(path) << " channel " << c;
            EXPECT_EQ(test::pixel(shown, overNothing.x, overNothing.y)[c],
                      test::pixel(alone, overNothing.x, overNothing.y)[c])
                << renderPathName(path) << " channel " << c;
        }
    }
}

}  // namespace
}  // namespace patina
