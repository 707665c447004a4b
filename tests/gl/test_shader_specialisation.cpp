// The key of a shader specialised to a scene, and the cache that holds those shaders.
#include <gtest/gtest.h>

#include "bench/brdf_floor.h"
#include "gl/shading_programs.h"
#include "scene/light_packing.h"
#include "scene/scene.h"
#include "test_support.h"

namespace patina {
namespace {

// One analytic light of each type (the embedded default without its environment): what
// specialisation compiles per light.
Scene threeLightScene() {
    Scene scene = defaultScene();
    std::erase_if(scene.lights, [](const Light& light) { return light.type == LightType::Environment; });
    return scene;
}

// The three analytic lights and a sphere and a tube light (after them, as packed).
Scene fiveLightScene() {
    Scene scene = threeLightScene();
    Light sphere;
    sphere.type = LightType::Sphere;
    sphere.range = 0.0f;
    Light tube;
    tube.type = LightType::Tube;
    tube.attenuation = {0.0f, 0.0f, 1.0f};
    tube.range = 5.0f;
    scene.lights.insert(scene.lights.begin(), {tube, sphere});
    return scene;
}

// Sphere and tube lights take the point light's switches: window, Karis's coefficients.
TEST(ShaderSpecialisation, AreaLightsComeAfterTheOthersWithTheirSwitches) {
    const Scene scene = fiveLightScene();
    const std::vector<shader::PackedLight> lights = packEnabledLights(scene.lights);
    EXPECT_EQ(specialiseFor(lights, scene.material, 0).lights,
              "SHADE_POINT(BLOCK(0), true, true) SHADE_DIRECTIONAL(BLOCK(1)) SHADE_HEMISPHERE(BLOCK(2)) "
              "SHADE_SPHERE(BLOCK(3), false, true) SHADE_TUBE(BLOCK(4), true, false)");
    const ShaderSpecialisation flat = specialiseFor(lights, scene.material, 8);
    EXPECT_EQ(flat.flatLightRows, "FLAT_POINT(0) FLAT_DIRECTIONAL(1) FLAT_HEMISPHERE(2) FLAT_SPHERE(3) FLAT_TUBE(4)");
    EXPECT_EQ(flat.flatLightCount, 5);
}

TEST(ShaderSpecialisation, DefaultSceneListsItsThreeLightsInOrder) {
    const Scene scene = threeLightScene();
    const ShaderSpecialisation key = specialiseFor(packEnabledLights(scene.lights), scene.material, 0);
    EXPECT_EQ(key.lights, "SHADE_POINT(BLOCK(0), true, true) SHADE_DIRECTIONAL(BLOCK(1)) SHADE_HEMISPHERE(BLOCK(2))");
    EXPECT_FALSE(key.noDiffuse);
}

// The first lights that fit come from mesh.vert as flat inputs, the rest from the block.
TEST(ShaderSpecialisation, LightsPastTheFlatSlotsComeFromTheBlock) {
    const Scene scene = threeLightScene();
    const std::vector<shader::PackedLight> lights = packEnabledLights(scene.lights);
    const ShaderSpecialisation key = specialiseFor(lights, scene.material, 2);
    EXPECT_EQ(key.lights, "SHADE_POINT(FLAT(0), true, true) SHADE_DIRECTIONAL(FLAT(1)) SHADE_HEMISPHERE(BLOCK(2))");
    EXPECT_EQ(key.flatLightRows, "FLAT_POINT(0) FLAT_DIRECTIONAL(1)");
    EXPECT_EQ(key.flatLightCount, 2);
    const ShaderSpecialisation all = specialiseFor(lights, scene.material, 8);
    EXPECT_EQ(all.flatLightRows, "FLAT_POINT(0) FLAT_DIRECTIONAL(1) FLAT_HEMISPHERE(2)");
    EXPECT_EQ(all.flatLightCount, 3);
    EXPECT_EQ(specialiseFor(lights, scene.material, 0).flatLightCount, 0);
    // A pure metal leaves the hemisphere light out: nothing to hand on for it either.
    Material metal = scene.material;
    metal.metallic = 1.0f;
    EXPECT_EQ(specialiseFor(lights, metal, 8).flatLightRows, "FLAT_POINT(0) FLAT_DIRECTIONAL(1)");
    EXPECT_EQ(specialiseFor(lights, metal, 8).flatLightCount, 2);
    // The bench's floor reads its lights the same way, each as a direction.
    const ShaderSpecialisation floor = brdfFloorFor(3, 2);
    for (const char* light : {"FLAT(0)", "FLAT(1)", "BLOCK(2)"}) {
        EXPECT_NE(floor.lights.find(std::string("vec3 L = ") + light + ".directionToLight;"), std::string::npos)
            << light << " in " << floor.lights;
    }
    EXPECT_EQ(floor.flatLightRows, "FLAT_DIRECTIONAL(0) FLAT_DIRECTIONAL(1)");
    EXPECT_EQ(floor.flatLightCount, 2);
}

// Flat lights cost per triangle drawn and save per fragment: the default sphere (16,384
// triangles) at 1920x1080, drawn whole or in 8 MSAA strips, and in a 512x512 sheet cell gains;
// a million triangles at 1920x1080 does not.
TEST(ShaderSpecialisation, FlatLightsPayOnlyWherePixelsOutnumberTrianglesDrawn) {
    EXPECT_TRUE(flatLightsPay(1140.0 * 1002.0, 16384.0));
    EXPECT_TRUE(flatLightsPay(1140.0 * 1002.0, 16384.0 * 8));
    EXPECT_TRUE(flatLightsPay(512.0 * 476.0, 16384.0));
    EXPECT_FALSE(flatLightsPay(1140.0 * 1002.0, 1'000'000.0));
}

TEST(ShaderSpecialisation, DisabledLightsAndUnwindowedPointsCompileLess) {
    Scene scene = threeLightScene();
    scene.lights[1].enabled = false;
    scene.lights[0].range = 0.0f;
    const ShaderSpecialisation key = specialiseFor(packEnabledLights(scene.lights), scene.material, 0);
    // Indices follow the uniform block, which holds enabled lights only.
    EXPECT_EQ(key.lights, "SHADE_POINT(BLOCK(0), false, true) SHADE_HEMISPHERE(BLOCK(1))");
}

// Karis's coefficients compile as constants; any other set is read from the light.
TEST(ShaderSpecialisation, OnlyKarisCoefficientsCompileAsConstants) {
    Scene scene = threeLightScene();
    scene.lights[0].attenuation = {1.0f, 0.0f, 0.5f};
    EXPECT_EQ(specialiseFor(packEnabledLights(scene.lights), scene.material, 0).lights,
              "SHADE_POINT(BLOCK(0), true, false) SHADE_DIRECTIONAL(BLOCK(1)) SHADE_HEMISPHERE(BLOCK(2))");
    scene.lights.push_back(threeLightScene().lights[0]);   // Karis's again, packed after the other point
    EXPECT_EQ(specialiseFor(packEnabledLights(scene.lights), scene.material, 0).lights,
              "SHADE_POINT(BLOCK(0), true, false) SHADE_POINT(BLOCK(1), true, true) SHADE_DIRECTIONAL(BLOCK(2)) SHADE_HEMISPHERE(BLOCK(3))");
}

TEST(ShaderSpecialisation, PureMetalDropsDiffuseAndTheHemisphereLight) {
    Scene scene = threeLightScene();
    scene.material.metallic = 1.0f;
    ShaderSpecialisation key = specialiseFor(packEnabledLights(scene.lights), scene.material, 0);
    EXPECT_TRUE(key.noDiffuse);
    EXPECT_EQ(key.lights, "SHADE_POINT(BLOCK(0), true, true) SHADE_DIRECTIONAL(BLOCK(1))");
    // Almost metal still has a diffuse term; a black dielectric has none.
    scene.material.metallic = 0.999f;
    EXPECT_FALSE(specialiseFor(packEnabledLights(scene.lights), scene.material, 0).noDiffuse);
    scene.material.metallic = 0.0f;
    scene.material.baseColor = glm::vec3(0.0f);
    EXPECT_TRUE(specialiseFor(packEnabledLights(scene.lights), scene.material, 0).noDiffuse);
}

TEST(ShaderSpecialisation, KeysDifferOnlyWhenTheShaderWould) {
    Scene a = threeLightScene();
    Scene b = a;
    b.lights[0].position = {9.0f, 1.0f, 0.0f};   // a uniform: same shader
    b.material.roughness = 0.9f;
    EXPECT_EQ(specialiseFor(packEnabledLights(a.lights), a.material, 0),
              specialiseFor(packEnabledLights(b.lights), b.material, 0));
    b.lights.push_back(b.lights[1]);
    EXPECT_NE(specialiseFor(packEnabledLights(a.lights), a.material, 0),
              specialiseFor(packEnabledLights(b.lights), b.material, 0));
}

// Single reads the coefficients only when some point light has others than Karis's.
TEST(ShadingPrograms, SinglePassReadsCoefficientsOnlyWhenAPointLightNeedsThem) {
    auto karis = [](const Scene& scene) {
        return ShadingPrograms::singlePassFor(packEnabledLights(scene.lights)).karisPoints;
    };
    Scene scene = threeLightScene();
    EXPECT_TRUE(karis(scene));
    EXPECT_TRUE(ShadingPrograms::singlePassFor({}).karisPoints);
    scene.lights.push_back(scene.lights[0]);
    scene.lights.back().attenuation = {0.0f, 0.0f, 1.0f};
    EXPECT_FALSE(karis(scene));
    scene.lights.back().enabled = false;   // a disabled light is not drawn
    EXPECT_TRUE(karis(scene));
    // A directional light's coefficients are never read.
    scene.lights[1].attenuation = {0.0f, 0.0f, 1.0f};
    EXPECT_TRUE(karis(scene));
}

// Single has a loop for each light type the scene draws, and none for the others.
TEST(ShadingPrograms, SinglePassLoopsOnlyOverTheTypesPresent) {
    using SinglePass = ShadingPrograms::SinglePass;
    Scene scene = fiveLightScene();   // one light of each type
    for (Light& light : scene.lights) {
        light.attenuation = shader::KARIS_ATTENUATION;
    }
    const SinglePass all = ShadingPrograms::singlePassFor(packEnabledLights(scene.lights));
    EXPECT_TRUE(all.points && all.directionals && all.hemispheres && all.spheres && all.tubes);
    EXPECT_EQ(all.defines(), (std::vector<std::string>{"PATINA_SINGLE_PASS", "PATINA_KARIS_POINTS"}));
    for (size_t off = 0; off < scene.lights.size(); ++off) {
        Scene four = scene;
        four.lights[off].enabled = false;
        const SinglePass pass = ShadingPrograms::singlePassFor(packEnabledLights(four.lights));
        const LightType type = scene.lights[off].type;
        EXPECT_EQ(pass.points, type != LightType::Point) << off;
        EXPECT_EQ(pass.directionals, type != LightType::Directional) << off;
        EXPECT_EQ(pass.hemispheres, type != LightType::Hemisphere) << off;
        EXPECT_EQ(pass.spheres, type != LightType::Sphere) << off;
        EXPECT_EQ(pass.tubes, type != LightType::Tube) << off;
        const char* left = type == LightType::Point         ? "PATINA_NO_POINT_LIGHTS"
                           : type == LightType::Directional ? "PATINA_NO_DIRECTIONAL_LIGHTS"
                           : type == LightType::Hemisphere  ? "PATINA_NO_HEMISPHERE_LIGHTS"
                           : type == LightType::Sphere      ? "PATINA_NO_SPHERE_LIGHTS"
                                                            : "PATINA_NO_TUBE_LIGHTS";
        EXPECT_EQ(pass.defines().back(), left) << off;
        EXPECT_EQ(pass.defines().size(), 3u) << off;
    }
    const SinglePass none = ShadingPrograms::singlePassFor({});
    EXPECT_FALSE(none.points || none.directionals || none.hemispheres || none.spheres || none.tubes);
    EXPECT_EQ(none.defines().size(), 7u);
    // A sphere's or a tube's own coefficients make single read them all.
    scene.lights[0].attenuation = {0.0f, 0.0f, 1.0f};
    EXPECT_FALSE(ShadingPrograms::singlePassFor(packEnabledLights(scene.lights)).karisPoints);
}

TEST(ShaderSpecialisation, CacheKeepsAtMostItsCapacity) {
    test::glContext();
    ShadingPrograms programs;
    const size_t extra = 3;
    for (size_t count = 0; count < ShadingPrograms::kSpecialisedCapacity + extra; ++count) {
        programs.useSpecialised(BrdfModelId::Epic, brdfFloorFor(count, 0));
    }
    EXPECT_EQ(programs.specialisedCount(), ShadingPrograms::kSpecialisedCapacity);
    // The most recent key is still there and usable.
    GLint current = 0;
    const GlProgram& last = programs.useSpecialised(BrdfModelId::Epic, brdfFloorFor(ShadingPrograms::kSpecialisedCapacity + extra - 1, 0));
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    EXPECT_EQ(GLuint(current), last.id());
    EXPECT_EQ(programs.specialisedCount(), ShadingPrograms::kSpecialisedCapacity);
}

// A frame holds every program it takes (a model with many map sets), however many: none is
// deleted while the frame may still draw with it; the next frame's first use trims the rest.
TEST(ShaderSpecialisation, AFramesProgramsAreKeptWhileItDraws) {
    test::glContext();
    ShadingPrograms programs;
    const size_t count = ShadingPrograms::kSpecialisedCapacity + 4;
    programs.beginFrame();
    std::vector<GLuint> ids;
    for (size_t i = 0; i < count; ++i) {
        ids.push_back(programs.useSpecialised(BrdfModelId::Epic, brdfFloorFor(i, 0)).id());
    }
    EXPECT_EQ(programs.specialisedCount(), count);
    for (GLuint id : ids) {
        EXPECT_TRUE(glIsProgram(id)) << id;
    }
    programs.beginFrame();
    programs.useSpecialised(BrdfModelId::Epic, brdfFloorFor(0, 0));
    EXPECT_EQ(programs.specialisedCount(), ShadingPrograms::kSpecialisedCapacity);
}

}  // namespace
}  // namespace patina
