// The renderer: single, multi and specialised passes agree, and the default scene shows all three lights.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "gl/render_targets.h"
#include "bench/brdf_floor.h"
#include "gl/renderer.h"
#include "shading/shading.h"
#include "scene/view.h"
#include "test_support.h"

namespace patina {
namespace {

using FlatLights = RenderSettings::FlatLights;

RenderOutput renderScene(Renderer& renderer, const Scene& scene, RenderPath passes, int size = 160, int samples = 4,
                         FlatLights flatLights = FlatLights::WherePaying) {
    RenderSettings settings = test::renderSettings(size, size, passes, samples);
    settings.flatLightUse = flatLights;
    return renderer.render(test::prepared(scene), settings);
}

int maxByteDifference(const LdrImage& a, const LdrImage& b) {
    int worst = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        worst = std::max(worst, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
    }
    return worst;
}

double maxHdrRelativeDifference(const HdrImage& a, const HdrImage& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        const double scale = std::max({std::abs(double(a.rgb[i])), std::abs(double(b.rgb[i])), 1e-6});
        worst = std::max(worst, std::abs(double(a.rgb[i]) - double(b.rgb[i])) / scale);
    }
    return worst;
}

Scene manyLightScene(int perType) {
    Scene scene = defaultScene();
    scene.lights.clear();
    for (int i = 0; i < perType; ++i) {
        const float angle = 2.0f * std::numbers::pi_v<float> * float(i) / float(perType);
        Light point;
        point.type = LightType::Point;
        point.position = {2.5f * std::cos(angle), 1.0f, 2.5f * std::sin(angle) + 1.0f};
        point.range = 6.0f;
        point.intensity = 3.0f;
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = {std::cos(angle), -0.5f, -std::sin(angle)};
        sun.intensity = 0.3f;
        Light sky;
        sky.type = LightType::Hemisphere;
        sky.sky = {0.1f, 0.1f, 0.2f};
        scene.lights.insert(scene.lights.end(), {point, sun, sky});
    }
    return scene;
}

// Two lights of each type, shown with an exposure and a tone map.
Scene toneMappedScene(float exposure, Tonemap tonemap) {
    Scene scene = manyLightScene(2);
    scene.display.exposure = exposure;
    scene.display.tonemap = tonemap;
    return scene;
}

// Sphere and tube lights around the mesh, with the window and Karis's coefficients and without.
Scene areaLightScene(int perType) {
    Scene scene = defaultScene();
    scene.lights.clear();
    for (int i = 0; i < perType; ++i) {
        const float angle = 2.0f * std::numbers::pi_v<float> * float(i) / float(perType);
        Light sphere;
        sphere.type = LightType::Sphere;
        sphere.position = {2.0f * std::cos(angle), 1.2f, 2.0f * std::sin(angle) + 1.0f};
        sphere.sourceRadius = 0.1f + 0.2f * float(i % 3);
        sphere.range = i % 2 ? 6.0f : 0.0f;
        sphere.intensity = 3.0f;
        Light tube;
        tube.type = LightType::Tube;
        tube.start = {2.0f * std::cos(angle), 0.3f, 2.0f * std::sin(angle) + 1.0f};
        tube.end = tube.start + glm::vec3(0.0f, 1.0f, 0.4f);
        tube.sourceRadius = 0.05f;
        tube.attenuation = i % 2 ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 1.0f);
        tube.intensity = 2.0f;
        scene.lights.insert(scene.lights.end(), {sphere, tube});
    }
    return scene;
}

Scene onlyLightsOfType(LightType type, int count) {
    Scene scene = manyLightScene(count);
    std::erase_if(scene.lights, [type](const Light& light) { return light.type != type; });
    return scene;
}

// Single, multi and specialised: the same image to rounding, for 0, 1 and many lights of each
// type, a point light without a window, points with and without Karis's coefficients, and a
// pure metal (whose shader drops diffuse). With MSAA all three resolve in the display pass;
// without, single and specialised write the display image in the shading pass and multi in a
// display pass after its sum.
TEST(Renderer, AllThreePassModesAgree) {
    test::glContext();
    Renderer renderer;
    Scene noLights = defaultScene();
    noLights.lights.clear();
    Scene torus = manyLightScene(10);
    torus.mesh = MeshKind::Torus;
    // Specialised takes its first lights as flat inputs and the rest from the block: the torus
    // has both kinds (GL 3.3 guarantees room for 6 flat lights).
    EXPECT_GE(renderer.flatLightSlots(), 6u);
    EXPECT_LT(renderer.flatLightSlots(), torus.lights.size());
    Scene unwindowed = onlyLightsOfType(LightType::Point, 3);
    unwindowed.lights[1].range = 0.0f;
    // Points with Karis's coefficients and others, interleaved: specialised compiles each its
    // own way, and single reads them all.
    Scene mixedAttenuation = onlyLightsOfType(LightType::Point, 4);
    mixedAttenuation.lights[0].attenuation = {0.2f, 0.1f, 0.6f};
    mixedAttenuation.lights[2].attenuation = {0.0f, 0.0f, 1.0f};
    Scene metal = manyLightScene(2);
    metal.material.metallic = 1.0f;
    metal.material.baseColor = {0.95f, 0.64f, 0.54f};
    struct Case {
        std::string name;
        Scene scene;
    };
    std::vector<Case> cases = {{"default", defaultScene()},  {"no lights", noLights},
                               {"30 lights on a torus", torus}, {"a point light of range 0", unwindowed},
                               {"pure metal", metal}, {"points with other coefficients", mixedAttenuation}};
    // Area lights: alone, many (flat and block), and among the other types.
    Scene areaAmongOthers = manyLightScene(2);
    for (const Light& light : areaLightScene(2).lights) {
        areaAmongOthers.lights.push_back(light);
    }
    Scene onlySpheres = areaLightScene(3);
    std::erase_if(onlySpheres.lights, [](const Light& light) { return light.type != LightType::Sphere; });
    cases.push_back({"1 sphere and 1 tube", areaLightScene(1)});
    cases.push_back({"8 spheres and 8 tubes", areaLightScene(8)});
    cases.push_back({"spheres and tubes among the others", areaAmongOthers});
    cases.push_back({"only spheres", onlySpheres});
    for (LightType type : {LightType::Point, LightType::Directional, LightType::Hemisphere}) {
        for (int count : {1, 12}) {
            cases.push_back({std::to_string(count) + " " + std::string(lightTypeName(type)),
                             onlyLightsOfType(type, count)});
        }
        // Two types: single compiles out the third type's loop, and the later types' lights
        // must still be found after it.
        Scene without = manyLightScene(2);
        std::erase_if(without.lights, [type](const Light& light) { return light.type == type; });
        cases.push_back({"no " + std::string(lightTypeName(type)), without});
    }
    for (const Case& c : cases) {
        for (int samples : {4, 1}) {
            const RenderOutput single = renderScene(renderer, c.scene, RenderPath::Single, 160, samples);
            // Specialised with its first lights as flat inputs and with every light from the block.
            for (auto [other, flat] : {std::pair{RenderPath::Multi, FlatLights::WherePaying},
                                       std::pair{RenderPath::Specialised, FlatLights::Always},
                                       std::pair{RenderPath::Specialised, FlatLights::Never}}) {
                const RenderOutput image = renderScene(renderer, c.scene, other, 160, samples, flat);
                const std::string what = c.name + ", " + std::string(renderPathName(other)) +
                                         (other == RenderPath::Multi        ? ", "
                                          : flat == FlatLights::Always ? " (flat lights), "
                                                                       : " (block lights), ") +
                                         std::to_string(samples) + " samples";
                EXPECT_LE(maxByteDifference(single.ldr, image.ldr), 1) << what;
                EXPECT_LE(maxHdrRelativeDifference(single.hdr, image.hdr), 1e-4) << what;
            }
        }
    }
}

// The timer queries time the whole draw, not a piece of it: on llvmpipe a query in the draw's
// own scene timed one tile, about 0.02 ms of a frame of tens of ms.
TEST(Renderer, GpuTimeCoversTheDraw) {
    test::glContext();
    Renderer renderer;
    RenderSettings settings;
    settings.width = 1280;
    settings.height = 720;
    settings.samples = 1;
    const Scene scene = manyLightScene(4);
    // Each path drawn once first: compiling its programs is work on the CPU the timer queries
    // rightly leave out, and on a busy machine it took three quarters of the timed draw's wall.
    for (RenderPath passes : {RenderPath::Single, RenderPath::Specialised, RenderPath::Multi}) {
        settings.path = passes;
        renderer.draw(test::prepared(scene), settings);
    }
    for (RenderPath passes : {RenderPath::Single, RenderPath::Specialised, RenderPath::Multi, RenderPath::Single}) {
        settings.path = passes;
        glFinish();
        renderer.lastGpuMilliseconds();   // collect the last draw's queries so this one is timed
        const auto start = std::chrono::steady_clock::now();
        renderer.draw(test::prepared(scene), settings);
        glFinish();
        const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const double gpu = renderer.lastGpuMilliseconds();
        EXPECT_GT(gpu, 0.25 * wall) << renderPathName(passes) << ": " << gpu << " of " << wall << " ms";
        EXPECT_LT(gpu, wall + 1.0) << renderPathName(passes);
    }
}

// The floor shader shades a scene of directional lights like the others (it only leaves out
// the light handling), so the benchmark compares like with like.
TEST(Renderer, BrdfFloorMatchesSinglePassForDirectionalLights) {
    test::glContext();
    Renderer renderer;
    const Scene scene = onlyLightsOfType(LightType::Directional, 8);
    const RenderOutput single = renderScene(renderer, scene, RenderPath::Single);
    for (FlatLights flat : {FlatLights::Always, FlatLights::Never}) {
        RenderSettings settings = brdfFloorSettings(test::renderSettings(160, 160, RenderPath::Specialised, 4));
        settings.flatLightUse = flat;
        const RenderOutput floor = renderer.render(test::prepared(scene), settings);
        EXPECT_LE(maxHdrRelativeDifference(single.hdr, floor.hdr), 1e-4) << (flat == FlatLights::Always);
    }
}

// A render in strips (to bound memory) gives the image drawn whole, for every path; the strip
// height here does not divide the image, so the last strip is partial.
TEST(Renderer, StripsGiveTheWholeImage) {
    test::glContext();
    Renderer renderer;
    const Scene scene = manyLightScene(2);
    for (RenderPath passes : {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised}) {
        RenderSettings settings;
        settings.width = 150;
        settings.height = 130;
        settings.path = passes;
        const RenderOutput whole = renderer.render(test::prepared(scene), settings);
        // 37 rows of 4x RGBA32F a strip; then 1 byte, which the cap of 16 strips overrides.
        for (size_t budget : {size_t(settings.width) * 4 * 16 * 37, size_t(1)}) {
            settings.maxTargetBytes = budget;
            const RenderOutput strips = renderer.render(test::prepared(scene), settings);
            EXPECT_LE(maxByteDifference(whole.ldr, strips.ldr), 1) << renderPathName(passes) << " " << budget;
            EXPECT_LE(maxHdrRelativeDifference(whole.hdr, strips.hdr), 1e-4) << renderPathName(passes) << " " << budget;
            int identical = 0;
            for (size_t i = 0; i < whole.ldr.rgba.size(); ++i) {
                identical += whole.ldr.rgba[i] == strips.ldr.rgba[i];
            }
            EXPECT_GT(identical, int(whole.ldr.rgba.size() * 99 / 100)) << renderPathName(passes) << " " << budget;
        }
    }
}

// MSAA samples are not cleared for each strip: each strip stamps the samples it draws, and the
// resolve takes any other for background. So a large sphere drawn first must leave no trace in
// a small one drawn next into the same slot, whole or in strips. (Strips against the whole
// image: StripsGiveTheWholeImage.)
TEST(Renderer, SamplesOfAnEarlierDrawNeverShow) {
    test::glContext();
    Renderer renderer, fresh;
    Scene near = defaultScene(), far = defaultScene();
    near.camera.position *= 0.5f;
    far.camera.position *= 2.5f;
    far.lights[0].intensity *= 3.0f;   // other values in the samples too, not only other coverage
    for (RenderPath passes : {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised}) {
        for (size_t budget : {size_t(0), size_t(120) * 4 * 16 * 30}) {   // whole, or strips of 30 rows
            RenderSettings settings;
            settings.width = settings.height = 120;
            settings.path = passes;
            settings.maxTargetBytes = budget;
            renderer.render(test::prepared(near), settings);
            const RenderOutput after = renderer.render(test::prepared(far), settings);
            const RenderOutput alone = fresh.render(test::prepared(far), settings);
            const std::string what = std::string(renderPathName(passes)) + ", budget " + std::to_string(budget);
            EXPECT_EQ(after.ldr.rgba, alone.ldr.rgba) << what;
            EXPECT_EQ(after.hdr.rgb, alone.hdr.rgb) << what;
        }
    }
}

TEST(RenderTargets, SampleStampsAskForAClearWhenNewAndWhenFloatsRunOut) {
    RenderTargets::SampleStamp stamp;
    EXPECT_TRUE(stamp.advance());   // samples just made: undefined contents
    EXPECT_EQ(stamp.value, 1.0f);
    EXPECT_FALSE(stamp.advance());
    EXPECT_EQ(stamp.value, 2.0f);
    stamp.value = 16777215.0f;      // 2^24 - 1
    EXPECT_FALSE(stamp.advance());
    EXPECT_EQ(stamp.value, 16777216.0f);
    EXPECT_TRUE(stamp.advance());   // 2^24 + 1 is not a float: start again from a clear
    EXPECT_EQ(stamp.value, 1.0f);
}

// New samples hold anything, a stamp still to come included: remaking them starts the count
// again, so the next strip clears them first.
TEST(RenderTargets, NewSamplesStartTheStampsAgain) {
    test::glContext();
    RenderTargets targets;
    targets.prepare(64, 64, 64, 4, false, false);
    EXPECT_TRUE(targets.sampleStamp.advance());
    EXPECT_FALSE(targets.sampleStamp.advance());
    targets.prepare(64, 64, 64, 4, false, false);   // the same size: the same samples
    EXPECT_EQ(targets.sampleStamp.value, 2.0f);
    targets.prepare(80, 64, 32, 4, false, false);
    EXPECT_EQ(targets.sampleStamp.value, 0.0f);
    EXPECT_TRUE(targets.sampleStamp.advance());
    targets.prepare(80, 64, 64, 1, false, true);   // no MSAA: the samples go
    targets.prepare(80, 64, 32, 4, false, false);
    EXPECT_EQ(targets.sampleStamp.value, 0.0f);
}

// Each caller's target is its own: drawing into one, at another size, leaves the other's
// texture and pixels as they were (the editor's viewport keeps showing its texture while a
// screenshot renders).
TEST(Renderer, DrawingIntoOneTargetLeavesAnotherAlone) {
    test::glContext();
    Renderer renderer;
    RenderTarget shown, other;
    EXPECT_EQ(shown.displayTexture(), 0u) << "nothing drawn yet";
    const RenderSettings small = test::renderSettings(48, 32, RenderPath::Single, 4);
    const unsigned texture = renderer.draw(test::preparedDefault(), small, shown);
    EXPECT_EQ(texture, shown.displayTexture());
    const RenderOutput before = renderer.readBack(shown, false);
    Scene dark = defaultScene();
    dark.material.baseColor = glm::vec3(0.0f);
    renderer.draw(test::prepared(dark), test::renderSettings(80, 60, RenderPath::Multi, 1), other);
    renderer.render(test::prepared(dark), test::renderSettings(100, 20, RenderPath::Single, 1));
    EXPECT_TRUE(glIsTexture(texture));
    EXPECT_EQ(shown.displayTexture(), texture);
    const RenderOutput after = renderer.readBack(shown, false);
    EXPECT_EQ(after.ldr.width, 48);
    EXPECT_EQ(after.ldr.rgba, before.ldr.rgba);
    EXPECT_EQ(renderer.readBack(other, false).ldr.width, 80);
}

// A GL error someone else left on the queue (the UI drawing a deleted texture, say) is not
// reported as the next draw's.
TEST(Renderer, AnErrorLeftByOtherCodeIsNotTheDrawsError) {
    test::glContext();
    Renderer renderer;
    glBindTexture(GL_TEXTURE_2D, 987654);   // never generated: GL_INVALID_OPERATION in a core context
    ASSERT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION)) << "the error this test leaves behind";
    glBindTexture(GL_TEXTURE_2D, 987654);
    EXPECT_NO_THROW(renderer.render(test::preparedDefault(), test::renderSettings(16, 16, RenderPath::Single, 1)));
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A draw that fails after binding its own target (here a specialised shader that does not
// compile) leaves bound the framebuffer it found: the editor's UI draws into the window's after a
// failed screenshot, instead of into the renderer's until the next good draw.
TEST(Renderer, AFailedDrawLeavesTheFramebufferItFound) {
    test::glContext();
    Renderer renderer;
    GLuint mine = 0;
    glGenFramebuffers(1, &mine);
    glBindFramebuffer(GL_FRAMEBUFFER, mine);
    RenderSettings broken = test::renderSettings(16, 16, RenderPath::Specialised, 1);
    broken.lightCode = [](const std::vector<shader::PackedLight>&, size_t) {
        ShaderSpecialisation code;
        code.lights = "this is not GLSL(";
        return code;
    };
    EXPECT_THROW(renderer.render(test::preparedDefault(), broken), std::exception);
    GLint bound = -1;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
    EXPECT_EQ(GLuint(bound), mine);
    renderer.render(test::preparedDefault(), test::renderSettings(16, 16, RenderPath::Single, 1));
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
    EXPECT_EQ(GLuint(bound), mine) << "and a draw that succeeds likewise";
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &mine);
    while (glGetError() != GL_NO_ERROR) {
    }
}

TEST(Renderer, ReadsTheLinearImageOnlyWhenAsked) {
    test::glContext();
    Renderer renderer;
    EXPECT_TRUE(renderer.readBack().ldr.rgba.empty()) << "a target never drawn reads back empty";
    RenderSettings settings;
    settings.width = settings.height = 32;
    settings.readHdr = false;
    const RenderOutput output = renderer.render(test::preparedDefault(), settings);
    EXPECT_TRUE(output.hdr.rgb.empty());
    EXPECT_EQ(output.ldr.rgba.size(), 32u * 32u * 4u);
    // The draw kept no linear image, so there is none to read: a clear error, not garbage.
    EXPECT_THROW(renderer.readBack(true), std::logic_error);
}

// Keeping the linear image or not changes nothing shown, with MSAA or without, on every path;
// and with exposure and a tone map, the shading pass's own display values (single and
// specialised without MSAA) match the display pass's (multi).
TEST(Renderer, TheDisplayImageIsTheSameWithOrWithoutTheLinearImage) {
    test::glContext();
    Renderer renderer;
    const Scene scene = toneMappedScene(0.7f, Tonemap::Reinhard);
    for (int samples : {1, 4}) {
        LdrImage multi;
        for (RenderPath passes : {RenderPath::Multi, RenderPath::Single, RenderPath::Specialised}) {
            RenderSettings settings = test::renderSettings(96, 96, passes, samples);
            const RenderOutput kept = renderer.render(test::prepared(scene), settings);
            settings.readHdr = false;
            const RenderOutput shown = renderer.render(test::prepared(scene), settings);
            const std::string what = std::string(renderPathName(passes)) + ", " + std::to_string(samples) + " samples";
            EXPECT_EQ(kept.ldr.rgba, shown.ldr.rgba) << what;
            if (passes == RenderPath::Multi) {
                multi = shown.ldr;
            } else {
                EXPECT_LE(maxByteDifference(shown.ldr, multi), 1) << what;
            }
        }
    }
}

// The display image is stored as bytes, so reading it back is a copy (llvmpipe converting a
// float image in glReadPixels took 3 ms of a 512x512 sheet cell). Storing rounds to nearest, as
// that conversion did: the bytes are the linear image's display values rounded. With Narkowicz's ACES and
// with PBR Neutral, Hill's ACES and AgX, so the GPU's tone maps are the CPU's.
TEST(Renderer, TheDisplayImageIsStoredAsRoundedBytes) {
    test::glContext();
    Renderer renderer;
    for (const auto& [tonemap, index] : {std::pair{Tonemap::AcesNarkowicz, shader::TONEMAP_ACES_NARKOWICZ},
                                         std::pair{Tonemap::PbrNeutral, shader::TONEMAP_PBR_NEUTRAL},
                                         std::pair{Tonemap::AcesHill, shader::TONEMAP_ACES_HILL},
                                         std::pair{Tonemap::Agx, shader::TONEMAP_AGX}}) {
        // The environment behind the mesh: every pixel is radiance through the display
        // transform (the flat background shows as its swatch: TheFlatBackgroundShowsAsItsSwatch).
        Scene scene = toneMappedScene(0.4f, tonemap);
        scene.lights.push_back(defaultScene().lights[2]);
        ASSERT_EQ(scene.lights.back().type, LightType::Environment);
        scene.display.backgroundFromEnvironment = true;
        for (int samples : {1, 4}) {
            for (RenderPath passes : {RenderPath::Multi, RenderPath::Single}) {
                RenderSettings settings = test::renderSettings(64, 64, passes, samples);
                const GLuint texture = renderer.draw(test::prepared(scene), settings);
                const std::string what = std::string(renderPathName(passes)) + ", " + std::to_string(samples) +
                                         " samples, " + std::string(tonemapName(tonemap));
                GLint format = 0;
                glBindTexture(GL_TEXTURE_2D, texture);
                glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
                glBindTexture(GL_TEXTURE_2D, 0);
                EXPECT_EQ(format, GL_RGBA8) << what;
                const RenderOutput image = renderer.readBack();
                size_t exact = 0, values = 0;
                for (size_t p = 0; p * 3 < image.hdr.rgb.size(); ++p) {
                    const glm::vec3 linear(image.hdr.rgb[3 * p], image.hdr.rgb[3 * p + 1], image.hdr.rgb[3 * p + 2]);
                    const glm::vec3 shown = shader::displayTransform(linear, scene.display.exposure, index);
                    for (int c = 0; c < 3; ++c) {
                        const int expected = int(std::lround(std::clamp(shown[c], 0.0f, 1.0f) * 255.0f));
                        const int stored = image.ldr.rgba[4 * p + size_t(c)];
                        ASSERT_LE(std::abs(stored - expected), 1) << what << ", pixel " << p;
                        exact += stored == expected;
                        ++values;
                    }
                }
                // Truncating would put about half the values one below; the GPU's and the CPU's
                // float arithmetic may differ by an ulp at a rounding boundary.
                EXPECT_GE(double(exact), 0.99 * double(values)) << what;
            }
        }
    }
}

TEST(Renderer, EachLightOfTheDefaultSceneShowsOnTheSphere) {
    test::glContext();
    Renderer renderer;
    const Scene scene = defaultScene();
    ASSERT_EQ(scene.lights.size(), 4u);   // point, directional, environment, hemisphere
    const RenderOutput all = renderScene(renderer, scene, RenderPath::Single);
    const int center = (80 * 160 + 80) * 3;
    EXPECT_GT(all.hdr.rgb[center], 0.0f);
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        Scene without = scene;
        without.lights[i].enabled = false;
        const RenderOutput image = renderScene(renderer, without, RenderPath::Single);
        // Each light alone must move many pixels, not a stray one.
        int changed = 0;
        for (size_t p = 0; p < all.ldr.rgba.size(); p += 4) {
            changed += all.ldr.rgba[p] != image.ldr.rgba[p] || all.ldr.rgba[p + 2] != image.ldr.rgba[p + 2];
        }
        EXPECT_GT(changed, 500) << scene.lights[i].name;
    }
}

TEST(Renderer, BackgroundShowsAroundTheMesh) {
    test::glContext();
    Renderer renderer;
    Scene scene = defaultScene();
    scene.display.background = {0.25f, 0.5f, 0.75f};
    const RenderOutput image = renderScene(renderer, scene, RenderPath::Multi, 64);
    EXPECT_FLOAT_EQ(image.hdr.rgb[0], 0.25f);
    EXPECT_FLOAT_EQ(image.hdr.rgb[2], 0.75f);
    // Without MSAA the single pass clears the display image to the background's display value
    // (computed on the CPU); it matches the display pass's to the byte.
    scene.display.tonemap = Tonemap::AcesNarkowicz;
    scene.display.exposure = 1.5f;
    const RenderOutput shownByPass = renderScene(renderer, scene, RenderPath::Multi, 64, 1);
    const RenderOutput cleared = renderScene(renderer, scene, RenderPath::Single, 64, 1);
    for (int channel = 0; channel < 4; ++channel) {
        EXPECT_EQ(cleared.ldr.rgba[size_t(channel)], shownByPass.ldr.rgba[size_t(channel)]) << channel;
    }
}

TEST(Renderer, DisplayTransformAppliesExposureAndToneMap) {
    test::glContext();
    Renderer renderer;
    Scene scene = defaultScene();
    const size_t centre = 16 * 32 + 16;
    auto render = [&](float exposure, Tonemap tonemap) {
        scene.display.exposure = exposure;
        scene.display.tonemap = tonemap;
        return renderScene(renderer, scene, RenderPath::Single, 32, 1);
    };
    const float before = render(0.0f, Tonemap::None).hdr.rgb[centre * 3];
    for (const auto& [exposure, tonemap] : {std::pair{0.0f, Tonemap::None}, std::pair{1.0f, Tonemap::None},
                                            std::pair{0.0f, Tonemap::Reinhard}, std::pair{1.0f, Tonemap::AcesNarkowicz},
                                            std::pair{-1.0f, Tonemap::PbrNeutral}, std::pair{0.5f, Tonemap::AcesHill},
                                            std::pair{2.0f, Tonemap::Agx}}) {
        const RenderOutput image = render(exposure, tonemap);
        const glm::vec3 linear(image.hdr.rgb[centre * 3], image.hdr.rgb[centre * 3 + 1], image.hdr.rgb[centre * 3 + 2]);
        const glm::vec3 shown = shader::displayTransform(linear, exposure, tonemapShaderIndex(tonemap));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(image.ldr.rgba[centre * 4 + size_t(c)], std::lround(shown[c] * 255.0f), 1)
                << exposure << " EV, " << tonemapName(tonemap);
        }
        // The HDR image is before exposure: unchanged by it.
        EXPECT_FLOAT_EQ(linear.r, before);
    }
    EXPECT_LT(render(-3.0f, Tonemap::None).ldr.rgba[centre * 4 + 1], render(-2.0f, Tonemap::None).ldr.rgba[centre * 4 + 1]);
}

// The flat background is a colour picked on screen: every path shows it as the editor's swatch
// (its sRGB encoding), whatever the exposure and tone map, while the HDR image holds it
// linear. (It went through the tone map: the default's #27272C swatch showed as #080815.)
TEST(Renderer, TheFlatBackgroundShowsAsItsSwatch) {
    test::glContext();
    Renderer renderer;
    Scene scene = defaultScene();
    const glm::vec3 swatch = shader::srgbColor(scene.display.background) * 255.0f;
    EXPECT_EQ(std::lround(swatch.r), 0x27);
    EXPECT_EQ(std::lround(swatch.b), 0x2C);
    for (const auto& [exposure, tonemap] : {std::pair{0.0f, Tonemap::PbrNeutral}, std::pair{3.0f, Tonemap::AcesNarkowicz},
                                            std::pair{-2.0f, Tonemap::None}}) {
        scene.display.exposure = exposure;
        scene.display.tonemap = tonemap;
        for (RenderPath passes : {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised}) {
            for (int samples : {1, 4}) {
                const RenderOutput image = renderScene(renderer, scene, passes, 48, samples);
                const std::string what = std::string(renderPathName(passes)) + ", " + std::to_string(samples) +
                                         " samples, " + std::string(tonemapName(tonemap));
                for (int c = 0; c < 3; ++c) {
                    EXPECT_EQ(image.ldr.rgba[size_t(c)], std::lround(swatch[c])) << what;
                    EXPECT_FLOAT_EQ(image.hdr.rgb[size_t(c)], scene.display.background[c]) << what;
                }
            }
        }
    }
}

// The GL may give more samples than asked (llvmpipe, like GPUs, makes 2 and 3 into 4): the
// resolve averages every sample it made, so asking for 3 draws the 4-sample image exactly.
TEST(Renderer, ResolveAveragesEverySampleTheGlMade) {
    test::glContext();
    Renderer renderer;
    const Scene scene = manyLightScene(1);
    const RenderOutput four = renderScene(renderer, scene, RenderPath::Single, 64, 4);
    const RenderOutput three = renderScene(renderer, scene, RenderPath::Single, 64, 3);
    EXPECT_EQ(three.ldr.rgba, four.ldr.rgba);
    EXPECT_EQ(three.hdr.rgb, four.hdr.rgb);
}

// Inside the mesh every sample of a pixel is shaded alike, so the resolved mean is the
// one-sample value: a resolve that skipped a sample or counted one twice is a quarter off.
TEST(Renderer, ResolvedInteriorMatchesOneSample) {
    test::glContext();
    Renderer renderer;
    const Scene scene = defaultScene();
    const int size = 64;
    const HdrImage four = renderScene(renderer, scene, RenderPath::Single, size, 4).hdr;
    const HdrImage one = renderScene(renderer, scene, RenderPath::Single, size, 1).hdr;
    double worst = 0.0;
    for (int y = size / 2 - 8; y < size / 2 + 8; ++y) {   // the middle of the sphere
        for (int x = size / 2 - 8; x < size / 2 + 8; ++x) {
            for (int c = 0; c < 3; ++c) {
                const size_t i = (size_t(y) * size + size_t(x)) * 3 + size_t(c);
                worst = std::max(worst, std::abs(double(four.rgb[i]) / double(one.rgb[i]) - 1.0));
            }
        }
    }
    EXPECT_LT(worst, 1e-3);
}

// A flat rectangle facing +z: its bounding box is the rectangle itself, so its screen bounds
// are tight and any cropping short of them shows.
Mesh facingQuad() {
    return test::facingQuad(0.8f, 0.5f);
}

// The pixels MSAA work is cropped to hold every vertex the camera sees in front of it, for
// cameras all around a sphere and a flat quad (whose box is tight) and close to them; a box
// reaching behind the eye gives the whole image, and an empty mesh none.
TEST(Renderer, ScreenBoundsHoldEveryProjectedVertex) {
    const int w = 320, h = 200;
    for (const Mesh& mesh : {makeUvSphere(16, 32), facingQuad()})
    for (int i = 0; i < 24; ++i) {
        const BoundingBox box = boundingBox(mesh);
        const std::vector<glm::vec3>& positions = mesh.positions;
        const float angle = 0.1f + 0.12f * float(i);   // from +x round to the quad's front
        Camera camera = defaultScene().camera;
        const float distance = 1.2f + 0.5f * float(i % 6);
        camera.position = {distance * std::cos(angle), 0.4f * std::sin(1.3f * angle), distance * std::sin(angle)};
        camera.target = {0.3f * std::sin(angle), 0.0f, 0.0f};
        const glm::mat4 transform = viewProjection(camera, float(w) / float(h));
        const PixelRect rect = screenBounds(transform, box, w, h);
        for (const glm::vec3& p : positions) {
            const glm::vec4 clip = transform * glm::vec4(p, 1.0f);
            ASSERT_GT(clip.w, 0.0f) << "the camera is outside the sphere";
            const float x = (clip.x / clip.w * 0.5f + 0.5f) * float(w), y = (clip.y / clip.w * 0.5f + 0.5f) * float(h);
            if (x >= 0.0f && x < float(w) && y >= 0.0f && y < float(h)) {
                EXPECT_TRUE(x >= float(rect.x0) && x <= float(rect.x1) && y >= float(rect.y0) && y <= float(rect.y1))
                    << "camera " << i << ": (" << x << ", " << y << ") outside [" << rect.x0 << ", " << rect.x1
                    << "] x [" << rect.y0 << ", " << rect.y1 << "]";
            }
        }
    }
    Camera inside = defaultScene().camera;
    inside.position = {0.0f, 0.0f, 0.5f};
    const BoundingBox box = boundingBox(makeUvSphere(16, 32));
    EXPECT_EQ(screenBounds(viewProjection(inside, 1.6f), box, w, h), (PixelRect{0, 0, w, h}));
    EXPECT_TRUE(screenBounds(viewProjection(inside, 1.6f), BoundingBox{}, w, h).empty());
}

// Cropping MSAA work to the mesh changes no pixel: framed, close up (corners projected far
// outside), from inside the bounding box (corners behind the eye), off to one side, in strips.
TEST(Renderer, CroppingToTheMeshGivesTheSameImage) {
    test::glContext();
    Renderer renderer;
    struct Case {
        std::string name;
        Scene scene;
        size_t budget = 0;
    };
    Scene closeUp = manyLightScene(2);
    closeUp.camera.position = {0.0f, 0.0f, 1.05f};
    Scene inBox = manyLightScene(2);   // outside the sphere, inside its box: corners behind the eye
    inBox.camera.position = {0.9f, 0.9f, 0.9f};
    Scene aside = manyLightScene(2);
    aside.camera.target = {1.5f, 0.8f, 0.0f};
    aside.display.tonemap = Tonemap::AcesNarkowicz;
    aside.display.exposure = -0.5f;
    Scene quad = manyLightScene(2);
    quad.camera.position = {0.3f, 0.2f, 2.0f};
    const std::vector<Case> cases = {{"framed", manyLightScene(2)},
                                     {"close up", closeUp},
                                     {"inside the bounding box", inBox},
                                     {"aside", aside},
                                     {"aside, in strips", aside, size_t(150) * 4 * 16 * 23},
                                     {"a flat quad", quad}};
    for (const Case& c : cases) {
        const Scene& scene = c.scene;
        const PreparedScene shown{scene, std::make_shared<const Mesh>(c.name == "a flat quad" ? facingQuad() : makeUvSphere()),
                                  test::prepared(scene).environment};
        RenderSettings settings;
        settings.width = 150;
        settings.height = 110;
        settings.maxTargetBytes = c.budget;
        settings.cropToMesh = false;
        const RenderOutput whole = renderer.render(shown, settings);
        settings.cropToMesh = true;
        const RenderOutput cropped = renderer.render(shown, settings);
        EXPECT_LE(maxByteDifference(whole.ldr, cropped.ldr), 1) << c.name;
        EXPECT_LE(maxHdrRelativeDifference(whole.hdr, cropped.hdr), 1e-6) << c.name;
        int identical = 0;
        for (size_t i = 0; i < whole.ldr.rgba.size(); ++i) {
            identical += whole.ldr.rgba[i] == cropped.ldr.rgba[i];
        }
        EXPECT_EQ(identical, int(whole.ldr.rgba.size())) << c.name;
    }
}

// A box wholly beyond the near plane: not one with the eye inside, nor one the plane cuts.
TEST(Renderer, BeyondNearPlaneOnlyWhenNothingIsCutOpen) {
    const BoundingBox box = boundingBox(makeUvSphere(8, 16));
    Camera camera = defaultScene().camera;
    EXPECT_TRUE(beyondNearPlane(viewProjection(camera, 1.0f), box));
    camera.position = {0.0f, 0.0f, 0.5f};   // inside
    EXPECT_FALSE(beyondNearPlane(viewProjection(camera, 1.0f), box));
    // Outside the sphere, the near plane (1% of the distance to the target) inside it.
    camera.position = {0.0f, 0.0f, 1.005f};
    EXPECT_FALSE(beyondNearPlane(viewProjection(camera, 1.0f), box));
    camera.position = {0.0f, 0.0f, 1.2f};
    EXPECT_TRUE(beyondNearPlane(viewProjection(camera, 1.0f), box));
    EXPECT_FALSE(beyondNearPlane(viewProjection(camera, 1.0f), BoundingBox{}));
}

// Culling a closed mesh's hidden faces changes no pixel, with every path, with and without
// MSAA: the sphere and torus framed, close up, a sphere wound inward; and where the eye can
// see a closed mesh's inside (from inside, or through the hole the near plane cuts) the
// renderer must not cull.
TEST(Renderer, CullingHiddenFacesGivesTheSameImage) {
    test::glContext();
    Renderer renderer;
    const Mesh inward = reversedWinding(makeUvSphere());
    struct Case {
        std::string name;
        Mesh mesh;
        glm::vec3 eye;
    };
    const glm::vec3 framed = defaultScene().camera.position;
    const std::vector<Case> cases = {{"sphere", makeUvSphere(), framed},
                                     {"torus", makeTorus(), framed},
                                     {"sphere wound inward", inward, framed},
                                     {"sphere close up", makeUvSphere(), {0.3f, 0.2f, 1.15f}},
                                     {"inside the sphere", makeUvSphere(), {0.1f, 0.2f, 0.5f}},
                                     {"near plane cutting the sphere", makeUvSphere(), {0.0f, 0.0f, 1.005f}}};
    const Scene lit = manyLightScene(2);
    for (const Case& c : cases) {
        Scene scene = lit;
        scene.camera.position = c.eye;
        const PreparedScene shown{scene, std::make_shared<const Mesh>(c.mesh), test::prepared(scene).environment};
        for (RenderPath passes : {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised}) {
            for (int samples : {4, 1}) {
                RenderSettings settings = test::renderSettings(150, 110, passes, samples);
                settings.cullHiddenFaces = false;
                const RenderOutput every = renderer.render(shown, settings);
                settings.cullHiddenFaces = true;
                const RenderOutput culled = renderer.render(shown, settings);
                const std::string what = c.name + ", " + std::string(renderPathName(passes)) + ", " +
                                         std::to_string(samples) + " samples";
                EXPECT_EQ(maxByteDifference(every.ldr, culled.ldr), 0) << what;
                // A sample exactly on a silhouette edge is in the front and the back triangle
                // there at one depth, and the first drawn took it: a few linear values differ.
                size_t differing = 0;
                for (size_t i = 0; i < every.hdr.rgb.size(); ++i) {
                    differing += std::abs(every.hdr.rgb[i] - culled.hdr.rgb[i]) > 1e-6f * std::abs(every.hdr.rgb[i]);
                }
                EXPECT_LE(differing, every.hdr.rgb.size() / 1000) << what;
                EXPECT_LE(maxHdrRelativeDifference(every.hdr, culled.hdr), 1e-2) << what;
            }
        }
    }
}

// What culling is for: the sphere's far half is never shaded. Counted with the GL's pipeline
// statistics where it has them.
TEST(Renderer, CullingSkipsTheSpheresFarHalf) {
    test::glContext();
    if (!epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query")) {
        GTEST_SKIP() << "no GL_ARB_pipeline_statistics_query";
    }
    Renderer renderer;
    GLuint query = 0;
    glGenQueries(1, &query);
    auto fragmentsShaded = [&](bool cull, int samples) {
        RenderSettings settings;
        settings.width = 320;
        settings.height = 240;
        settings.samples = samples;
        settings.cullHiddenFaces = cull;
        glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, query);
        renderer.draw(test::preparedDefault(), settings);
        glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
        GLuint64 count = 0;
        glGetQueryObjectui64v(query, GL_QUERY_RESULT, &count);
        return double(count);
    };
    // Without MSAA the shading pass is all there is; with it, clears and the resolve too.
    EXPECT_LT(fragmentsShaded(true, 1), 0.6 * fragmentsShaded(false, 1));
    EXPECT_LT(fragmentsShaded(true, 4), 0.9 * fragmentsShaded(false, 4));
    glDeleteQueries(1, &query);
}

TEST(Renderer, RejectsImpossibleSizes) {
    test::glContext();
    Renderer renderer;
    RenderSettings settings;
    settings.width = 0;
    EXPECT_THROW(renderer.render(test::preparedDefault(), settings), std::invalid_argument);
}

}  // namespace
}  // namespace patina
