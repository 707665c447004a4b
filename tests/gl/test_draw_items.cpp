// A prepared scene of many draw items (scene/prepared_scene.h): every render path draws each
// item where its transform puts it, with its own material, its sides (glTF 2.0 §3.9.5), its
// winding under a mirror (§3.7.2.1) and its blending (§3.9.4); and the CPU rasteriser of the
// ground truth sees the same item at each pixel as the GPU.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/renderer.h"
#include "model/placement.h"
#include "reference/pixel_surfaces.h"
#include "reference/reference_render.h"
#include "scene/view.h"
#include "test_support.h"

namespace patina {
namespace {

constexpr int kWidth = 160, kHeight = 96;
constexpr RenderPath kPaths[] = {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised};

// The default scene's analytic lights (the ground truth adds them exactly), seen from further
// back; no environment.
Scene litScene() {
    Scene scene = defaultScene();
    std::erase_if(scene.lights, [](const Light& light) { return light.type == LightType::Environment; });
    scene.camera.position = {0.0f, 0.8f, 5.0f};
    return scene;
}

// The model's items in world space, one mesh: what PreparedScene::mesh holds for a model.
std::shared_ptr<const Mesh> flattened(const Model& model) {
    auto mesh = std::make_shared<Mesh>();
    for (const DrawItem& item : model.draws) {
        const Mesh& part = model.primitives[size_t(item.primitive)];
        const uint32_t base = uint32_t(mesh->positions.size());
        for (size_t i = 0; i < part.positions.size(); ++i) {
            mesh->positions.push_back(glm::vec3(item.transform * glm::vec4(part.positions[i], 1.0f)));
            mesh->normals.push_back(unitNormal(normalTransform(item.transform) * part.normals[i]));
        }
        const bool flip = mirrors(item.transform);
        for (size_t t = 0; t + 2 < part.indices.size(); t += 3) {
            mesh->indices.insert(mesh->indices.end(), {base + part.indices[t], base + part.indices[t + (flip ? 2 : 1)],
                                                       base + part.indices[t + (flip ? 1 : 2)]});
        }
    }
    return mesh;
}

PreparedScene preparedWith(const Scene& scene, const std::shared_ptr<const Model>& model) {
    return {scene, flattened(*model), nullptr, model};
}

ModelMaterial dielectric(glm::vec3 baseColor, bool doubleSided = false) {
    ModelMaterial material;
    material.factors.baseColor = baseColor;
    material.factors.metallic = 0.0f;
    material.factors.roughness = 0.5f;
    material.doubleSided = doubleSided;
    return material;
}

glm::mat4 placed(glm::vec3 at, glm::vec3 scale) {
    return glm::scale(glm::translate(glm::mat4(1.0f), at), scale);
}

// Two unit spheres, red on the left and blue on the right, each scaled by 0.8.
std::shared_ptr<const Model> twoSpheres() {
    Model model;
    model.primitives = {makeUvSphere(32, 64), makeUvSphere(24, 48)};
    model.materials = {dielectric({0.8f, 0.1f, 0.1f}), dielectric({0.1f, 0.2f, 0.8f})};
    model.draws = {{0, 0, placed({-1.1f, 0.0f, 0.0f}, glm::vec3(0.8f)), "left"},
                   {1, 1, placed({1.1f, 0.0f, 0.0f}, glm::vec3(0.8f)), "right"}};
    return std::make_shared<const Model>(std::move(model));
}

// Each path at 1 and 4 samples, named for a message.
template <typename Check>
void onEveryPath(Check&& check) {
    for (RenderPath path : kPaths) {
        for (int samples : {1, 4}) {
            check(path, samples, std::string(renderPathName(path)) + ", " + std::to_string(samples) + " samples");
        }
    }
}

// Where `point` lands in the image (rows top first).
glm::ivec2 pixelOf(const Scene& scene, glm::vec3 point) {
    return test::pixelOf(scene.camera, point, kWidth, kHeight);
}

bool near(glm::vec3 a, glm::vec3 b, float relative) {
    for (int c = 0; c < 3; ++c) {
        if (!(std::abs(a[c] - b[c]) <= relative * std::max(std::abs(b[c]), 0.05f))) {
            return false;
        }
    }
    return true;
}

// Of the pixels the ground truth sees a surface at, the share the render agrees with (each
// channel within `relative`); the analytic lights make the two equal to rounding.
double agreement(const HdrImage& render, const PixelSurfaces& surfaces, const ReferenceImage& reference) {
    int agreeing = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (surfaces.sampleOfPixel[size_t(y * kWidth + x)] >= 0) {
                agreeing += near(test::pixel(render, x, y), test::pixel(reference.value, x, y), 2e-3f);
            }
        }
    }
    return double(agreeing) / double(std::max<size_t>(surfaces.samples.size(), 1));
}

ReferenceImage groundTruth(const PreparedScene& prepared, const PixelSurfaces& surfaces) {
    ReferenceRenderOptions options;
    options.samplesPerPixel = 1;   // the analytic lights are exact at any count
    return renderReference(prepared, surfaces, options);
}

// Each sphere where its transform puts it and in its own colour, on every path, as the ground
// truth shades the same item at each pixel.
TEST(DrawItems, EachItemShowsWhereItIsWithItsOwnMaterialOnEveryPath) {
    test::glContext();
    Renderer renderer;
    const Scene scene = litScene();
    const std::shared_ptr<const Model> model = twoSpheres();
    const PreparedScene prepared = preparedWith(scene, model);
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kWidth, kHeight);
    const ReferenceImage reference = groundTruth(prepared, surfaces);
    // The CPU rasteriser: the left item on the left half, the right one on the right.
    int seen[2] = {0, 0};
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const int32_t sample = surfaces.sampleOfPixel[size_t(y * kWidth + x)];
            if (sample >= 0) {
                const int32_t item = surfaces.drawOfSample[size_t(sample)];
                EXPECT_EQ(item, x < kWidth / 2 ? 0 : 1) << x << " " << y;
                ++seen[item];
            }
        }
    }
    EXPECT_GT(seen[0], 500);
    EXPECT_GT(seen[1], 500);
    const glm::ivec2 left = pixelOf(scene, {-1.1f, 0.0f, 0.8f}), right = pixelOf(scene, {1.1f, 0.0f, 0.8f});
    onEveryPath([&](RenderPath path, int samples, const std::string& what) {
        const HdrImage render = renderer.render(prepared, test::renderSettings(kWidth, kHeight, path, samples)).hdr;
        const glm::vec3 red = test::pixel(render, left.x, left.y), blue = test::pixel(render, right.x, right.y);
        EXPECT_GT(red.r, 2.0f * red.b) << what;
        EXPECT_GT(blue.b, 2.0f * blue.r) << what;
        EXPECT_TRUE(near(red, test::pixel(reference.value, left.x, left.y), 2e-3f)) << what;
        EXPECT_TRUE(near(blue, test::pixel(reference.value, right.x, right.y), 2e-3f)) << what;
        // Without MSAA every pixel the ground truth sees (MSAA shades off the pixel centre).
        if (samples == 1) {
            EXPECT_GT(agreement(render, surfaces, reference), 0.97) << what;
        }
    });
}

// Each item under its own BRDF model: the left sphere epic, the right glTF's, drawn on every
// path as the ground truth shades each (the frame switches programs and their tables), and
// the right one unlike the same sphere under epic.
TEST(DrawItems, EachItemIsShadedWithItsOwnBrdfModelOnEveryPath) {
    test::glContext();
    Renderer renderer;
    const Scene scene = litScene();
    Model mixed = *twoSpheres();
    mixed.materials[0].factors.model = BrdfModelId::Epic;
    mixed.materials[1].factors.model = BrdfModelId::Gltf;
    mixed.materials[1].factors.roughness = 0.3f;   // glTF's visibility and Fresnel show on the highlight
    const PreparedScene prepared = preparedWith(scene, std::make_shared<const Model>(mixed));
    Scene allEpic = scene;
    allEpic.modelBrdf = BrdfModelId::Epic;
    const PreparedScene epic = preparedWith(allEpic, std::make_shared<const Model>(mixed));
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kWidth, kHeight);
    const ReferenceImage reference = groundTruth(prepared, surfaces);
    const glm::ivec2 right = pixelOf(scene, {1.1f, 0.0f, 0.8f});
    onEveryPath([&](RenderPath path, int samples, const std::string& what) {
        const RenderSettings settings = test::renderSettings(kWidth, kHeight, path, samples);
        const HdrImage render = renderer.render(prepared, settings).hdr;
        const HdrImage underEpic = renderer.render(epic, settings).hdr;
        const glm::vec3 gltf = test::pixel(render, right.x, right.y);
        EXPECT_TRUE(near(gltf, test::pixel(reference.value, right.x, right.y), 2e-3f)) << what;
        EXPECT_FALSE(near(gltf, test::pixel(underEpic, right.x, right.y), 1e-2f)) << what;
        if (samples == 1) {
            EXPECT_GT(agreement(render, surfaces, reference), 0.97) << what;
        }
    });
}

// A mirroring transform winds the primitive's triangles the other way: its front faces must
// still be the ones drawn and lit from the front. A sphere mirrored in x is the same sphere,
// so the image is the unmirrored one's (to the facets' rounding), single- or double-sided.
TEST(DrawItems, AMirroredItemStillShowsItsFrontFaces) {
    test::glContext();
    Renderer renderer;
    const Scene scene = litScene();
    for (bool doubleSided : {false, true}) {
        Model plain;
        plain.primitives = {makeUvSphere(32, 64)};
        plain.materials = {dielectric({0.7f, 0.6f, 0.5f}, doubleSided)};
        plain.draws = {{0, 0, placed({0.3f, 0.0f, 0.0f}, glm::vec3(1.2f)), "plain"}};
        Model mirrored = plain;
        mirrored.draws[0].transform = placed({0.3f, 0.0f, 0.0f}, {-1.2f, 1.2f, 1.2f});
        ASSERT_TRUE(mirrors(mirrored.draws[0].transform));
        const PreparedScene a = preparedWith(scene, std::make_shared<const Model>(plain));
        const PreparedScene b = preparedWith(scene, std::make_shared<const Model>(mirrored));
        const PixelSurfaces surfaces = rasterizeSurfaces(b, kWidth, kHeight);
        const ReferenceImage reference = groundTruth(b, surfaces);
        for (RenderPath path : kPaths) {
            const std::string what = std::string(renderPathName(path)) + (doubleSided ? ", double-sided" : "");
            const RenderSettings settings = test::renderSettings(kWidth, kHeight, path, 1);
            const HdrImage shown = renderer.render(a, settings).hdr;
            const HdrImage shownMirrored = renderer.render(b, settings).hdr;
            int same = 0;
            for (int y = 0; y < kHeight; ++y) {
                for (int x = 0; x < kWidth; ++x) {
                    same += near(test::pixel(shownMirrored, x, y), test::pixel(shown, x, y), 2e-2f);
                }
            }
            EXPECT_GT(same, kWidth * kHeight * 97 / 100) << what;
            EXPECT_GT(agreement(shownMirrored, surfaces, reference), 0.97) << what;
        }
    }
}

// A quad seen from behind: single-sided, culled (nothing drawn); double-sided, drawn and lit
// as its back with the normal reversed (glTF 2.0 §3.9.5), by a light on the eye's side.
TEST(DrawItems, OnlyADoubleSidedItemShowsItsBack) {
    test::glContext();
    Renderer renderer;
    Scene scene = litScene();
    scene.camera.position = {0.2f, 0.3f, -3.0f};
    Light behind;
    behind.type = LightType::Directional;
    behind.direction = {0.0f, 0.0f, 1.0f};   // travelling towards +z: onto the quad's back
    behind.intensity = 3.0f;
    scene.lights = {behind};
    const glm::ivec2 centre = pixelOf(scene, glm::vec3(0.0f));
    for (bool doubleSided : {false, true}) {
        Model model;
        model.primitives = {test::facingQuad(1.0f, 1.0f)};
        model.materials = {dielectric({0.6f, 0.6f, 0.6f}, doubleSided)};
        model.draws = {{0, 0, glm::mat4(1.0f), "quad"}};
        const PreparedScene prepared = preparedWith(scene, std::make_shared<const Model>(model));
        const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kWidth, kHeight);
        EXPECT_EQ(surfaces.samples.empty(), !doubleSided) << "the ground truth culls as the renderer does";
        const ReferenceImage reference = groundTruth(prepared, surfaces);
        onEveryPath([&](RenderPath path, int samples, const std::string& name) {
            const std::string what = name + (doubleSided ? ", double-sided" : ", single-sided");
            const HdrImage render = renderer.render(prepared, test::renderSettings(kWidth, kHeight, path, samples)).hdr;
            if (!doubleSided) {
                int drawn = 0;
                for (int y = 0; y < kHeight; ++y) {
                    for (int x = 0; x < kWidth; ++x) {
                        drawn += !near(test::pixel(render, x, y), scene.display.background, 1e-5f);
                    }
                }
                EXPECT_EQ(drawn, 0) << what << ": only background";
                return;
            }
            const glm::vec3 seen = test::pixel(render, centre.x, centre.y);
            EXPECT_GT(seen.g, 0.2f) << what << ": lit from its back";
            EXPECT_TRUE(near(seen, test::pixel(reference.value, centre.x, centre.y), 2e-3f)) << what;
            if (samples == 1) {
                EXPECT_GT(agreement(render, surfaces, reference), 0.97) << what;
            }
        });
    }
}

// glTF's BLEND: a red quad at alpha 0.25 in front of a grey one, and reaching past it over the
// background, is "over" what is behind it: 0.75 of that plus 0.25 of itself, on every path.
TEST(DrawItems, ABlendedItemIsOverWhatIsBehindIt) {
    test::glContext();
    Renderer renderer;
    Scene scene = litScene();
    scene.camera.position = {0.0f, 0.0f, 5.0f};
    scene.display.background = {0.1f, 0.3f, 0.2f};
    const Mesh quad = test::facingQuad(1.0f, 1.0f);
    const glm::mat4 back = placed(glm::vec3(0.0f), glm::vec3(1.0f)), front = placed({0.0f, 0.0f, 0.5f}, {1.6f, 0.6f, 1.0f});
    auto modelOf = [&](std::vector<DrawItem> draws, float alpha) {
        Model model;
        model.primitives = {quad};
        model.materials = {dielectric({0.5f, 0.5f, 0.5f}), dielectric({0.9f, 0.1f, 0.1f})};
        if (alpha < 1.0f) {
            model.materials[1].alphaMode = AlphaMode::Blend;
            model.materials[1].baseAlpha = alpha;
        }
        model.draws = std::move(draws);
        return std::make_shared<const Model>(std::move(model));
    };
    // The blended item first in the list: the renderer still draws it after the opaque one.
    const auto both = modelOf({{0, 1, front, "front"}, {0, 0, back, "back"}}, 0.25f);
    const auto backOnly = modelOf({{0, 0, back, "back"}}, 1.0f);
    const auto frontOnly = modelOf({{0, 1, front, "front"}}, 1.0f);
    const glm::ivec2 overQuad = pixelOf(scene, {0.3f, 0.1f, 0.5f}), overBackground = pixelOf(scene, {1.4f, 0.1f, 0.5f});
    onEveryPath([&](RenderPath path, int samples, const std::string& what) {
        const RenderSettings settings = test::renderSettings(kWidth, kHeight, path, samples);
        const HdrImage blended = renderer.render(preparedWith(scene, both), settings).hdr;
        const HdrImage behind = renderer.render(preparedWith(scene, backOnly), settings).hdr;
        const HdrImage over = renderer.render(preparedWith(scene, frontOnly), settings).hdr;
        const glm::vec3 expected =
            0.75f * test::pixel(behind, overQuad.x, overQuad.y) + 0.25f * test::pixel(over, overQuad.x, overQuad.y);
        EXPECT_TRUE(near(test::pixel(blended, overQuad.x, overQuad.y), expected, 1e-3f)) << what;
        const glm::vec3 overColour =
            0.75f * scene.display.background + 0.25f * test::pixel(over, overBackground.x, overBackground.y);
        EXPECT_TRUE(near(test::pixel(blended, overBackground.x, overBackground.y), overColour, 1e-3f))
            << what << ": over the background";
    });
}

}  // namespace
}  // namespace patina
