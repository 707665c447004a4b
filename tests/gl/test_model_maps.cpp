// A model's texture maps on the GPU (shaders/stages/surface_maps.glsl): each map does what glTF
// 2.0 sections 3.9.2-3.9.4 say, on every render path and with and without MSAA. Each case is
// checked against an image the maps must reproduce: the same surface drawn with factors alone
// (a base colour, a normal, a roughness) that the texel stands for.
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "gl/renderer.h"
#include "reference/channel_image.h"
#include "reference/pixel_surfaces.h"
#include "reference/reference_render.h"
#include "scene/view.h"
#include "shading/shading.h"
#include "test_support.h"

namespace patina {
namespace {

constexpr int kWidth = 96, kHeight = 96;
constexpr RenderPath kPaths[] = {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised};

// The default scene's analytic lights and the quad head on.
Scene quadScene() {
    Scene scene = defaultScene();
    std::erase_if(scene.lights, [](const Light& light) { return light.type == LightType::Environment; });
    scene.camera.position = {0.0f, 0.0f, 3.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    return scene;
}

// A square from (-1, -1) to (1, 1) facing +z, UV (0, 0) at its top-left corner (glTF's v runs
// down the image), tangent +x; `normal` at every corner.
Mesh quad(glm::vec3 normal = {0.0f, 0.0f, 1.0f}, float tangentSign = 1.0f) {
    Mesh mesh;
    mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    mesh.normals.assign(4, glm::normalize(normal));
    mesh.uv0 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    mesh.tangents.assign(4, glm::vec4(1, 0, 0, tangentSign));
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

ModelMaterial factors(glm::vec3 baseColor) {
    ModelMaterial material;
    material.factors.baseColor = baseColor;
    material.factors.metallic = 0.0f;
    material.factors.roughness = 0.5f;
    return material;
}

ModelImage image(int width, int height, std::vector<uint8_t> rgba) {
    return {"map", width, height, std::move(rgba)};
}

// A slot on image 0, magnified texel by texel.
TextureSlot nearestSlot() {
    TextureSlot slot;
    slot.image = 0;
    slot.sampler.nearestMagnification = true;
    slot.sampler.wrapS = slot.sampler.wrapT = TextureWrap::ClampToEdge;
    return slot;
}

std::shared_ptr<const Model> oneQuad(const Mesh& mesh, const ModelMaterial& material, std::vector<ModelImage> images = {}) {
    Model model;
    model.primitives = {mesh};
    model.materials = {material};
    model.images = std::move(images);
    model.draws = {{0, 0, glm::mat4(1.0f), "quad"}};
    return std::make_shared<const Model>(std::move(model));
}

// Where `point` lands in the image (rows top first).
glm::ivec2 pixelOf(const Scene& scene, glm::vec3 point) {
    return test::pixelOf(scene.camera, point, kWidth, kHeight);
}

float largestRelativeError(glm::vec3 actual, glm::vec3 expected) {
    float largest = 0.0f;
    for (int c = 0; c < 3; ++c) {
        largest = std::max(largest, std::abs(actual[c] - expected[c]) / std::max(std::abs(expected[c]), 0.02f));
    }
    return largest;
}

const std::vector<glm::vec3> kQuadrants{{-0.5f, 0.5f, 0.0f}, {0.5f, 0.5f, 0.0f}, {-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}};

class ModelMaps : public ::testing::Test {
protected:
    HdrImage render(const Scene& scene, const std::shared_ptr<const Model>& model, RenderPath path, int samples) {
        const PreparedScene prepared{scene, std::make_shared<const Mesh>(model->primitives[0]), nullptr, model};
        return renderer_.render(prepared, test::renderSettings(kWidth, kHeight, path, samples)).hdr;
    }

    // At each of `points` (on the quad), `mapped` and `expected` agree on every path.
    void expectSame(const Scene& scene, const std::shared_ptr<const Model>& mapped,
                    const std::shared_ptr<const Model>& expected, const std::vector<glm::vec3>& points,
                    float tolerance, const std::string& what) {
        for (RenderPath path : kPaths) {
            for (int samples : {1, 4}) {
                const HdrImage a = render(scene, mapped, path, samples), b = render(scene, expected, path, samples);
                for (const glm::vec3& point : points) {
                    const glm::ivec2 at = pixelOf(scene, point);
                    EXPECT_LE(largestRelativeError(test::pixel(a, at.x, at.y), test::pixel(b, at.x, at.y)), tolerance)
                        << what << ", " << renderPathName(path) << ", " << samples << " samples, at " << at.x << " "
                        << at.y;
                }
            }
        }
    }

    // The 2 x 2 image `rgba` on the maps `mapped` has beyond `unmapped`: each quadrant is the quad
    // drawn with `unmapped` as `expectedAt` changes it for that quadrant's texel (RGBA), on every
    // path; and the quadrant `differing` without the maps differs by more than `by` (the maps
    // did it).
    void expectEachQuadrantIsItsTexelsFactors(const Scene& scene, const ModelMaterial& unmapped,
                                              const ModelMaterial& mapped, const std::vector<uint8_t>& rgba,
                                              const std::function<void(const uint8_t*, MaterialParameters&)>& expectedAt,
                                              size_t differing, float by) {
        const auto model = oneQuad(quad(), mapped, {image(2, 2, rgba)});
        for (size_t q = 0; q < 4; ++q) {
            ModelMaterial expected = unmapped;
            expectedAt(&rgba[q * 4], expected.factors);
            expectSame(scene, model, oneQuad(quad(), expected), {kQuadrants[q]}, 1e-2f, "quadrant " + std::to_string(q));
        }
        const HdrImage plain = render(scene, oneQuad(quad(), unmapped), RenderPath::Single, 1);
        const HdrImage shown = render(scene, model, RenderPath::Single, 1);
        const glm::ivec2 at = pixelOf(scene, kQuadrants[differing]);
        EXPECT_GT(largestRelativeError(test::pixel(shown, at.x, at.y), test::pixel(plain, at.x, at.y)), by);
    }

    // On every path, with and without MSAA: the quad's right half shows the background (cut out),
    // its left half does not.
    void expectRightHalfCutOut(const Scene& scene, const std::shared_ptr<const Model>& model) {
        for (RenderPath path : kPaths) {
            for (int samples : {1, 4}) {
                const HdrImage shown = render(scene, model, path, samples);
                const glm::ivec2 kept = pixelOf(scene, {-0.5f, 0.2f, 0.0f}), cut = pixelOf(scene, {0.5f, 0.2f, 0.0f});
                const std::string what = std::string(renderPathName(path)) + ", " + std::to_string(samples) + " samples";
                EXPECT_LE(largestRelativeError(test::pixel(shown, cut.x, cut.y), scene.display.background), 1e-3f)
                    << what;
                EXPECT_GT(largestRelativeError(test::pixel(shown, kept.x, kept.y), scene.display.background), 0.1f)
                    << what;
            }
        }
    }

    HeadlessContext& context_ = test::glContext();   // before the renderer: it needs the context
    Renderer renderer_;
};

// glTF 2.0 3.9.2: base colour = factor x the map's texel, sRGB-decoded; the image's first row
// at the top of the quad (v = 0), its first column on the left. Each quadrant shows its texel
// as that colour given as a factor does.
TEST_F(ModelMaps, TheBaseColourMapMultipliesTheFactorTexelByTexel) {
    const Scene scene = quadScene();
    const std::vector<uint8_t> rgba{200, 40, 40, 255, 40, 200, 40, 255, 40, 40, 200, 255, 230, 230, 230, 255};
    ModelMaterial mapped = factors(glm::vec3(0.5f, 1.0f, 1.0f));
    mapped.baseColor = nearestSlot();
    const auto model = oneQuad(quad(), mapped, {image(2, 2, rgba)});
    for (size_t q = 0; q < 4; ++q) {
        const glm::vec3 texel{shader::srgbDecode(rgba[q * 4] / 255.0f), shader::srgbDecode(rgba[q * 4 + 1] / 255.0f),
                              shader::srgbDecode(rgba[q * 4 + 2] / 255.0f)};
        const auto expected = oneQuad(quad(), factors(glm::vec3(0.5f, 1.0f, 1.0f) * texel));
        // GL's sRGB decode (llvmpipe's table) is within 0.6% of the exact one on these texels.
        expectSame(scene, model, expected, {kQuadrants[q]}, 1e-2f, "quadrant " + std::to_string(q));
    }
}

// KHR_materials_transmission's map scales the factor by its R, KHR_materials_volume's the
// thickness by its G (one image holds both here): each quadrant is the quad drawn with the
// factors its texel stands for, lit from the front and by a light behind it that shines through.
TEST_F(ModelMaps, TheTransmissionAndThicknessMapsScaleTheirFactors) {
    Scene scene = quadScene();
    Light behind;
    behind.type = LightType::Directional;
    behind.direction = glm::normalize(glm::vec3(0.2f, 0.1f, 1.0f));   // travelling towards the camera
    behind.intensity = 3.0f;
    scene.lights.push_back(behind);
    const std::vector<uint8_t> rgba{0, 255, 0, 255, 255, 255, 0, 255, 128, 64, 0, 255, 255, 0, 0, 255};
    ModelMaterial glass = factors(glm::vec3(0.9f, 0.8f, 0.7f));
    glass.factors.transmission = 1.0f;
    glass.factors.thickness = 2.0f;
    glass.factors.attenuationColor = {1.0f, 0.5f, 0.25f};
    glass.factors.attenuationDistance = 1.0f;
    ModelMaterial mapped = glass;
    mapped.transmissionMap = nearestSlot();
    mapped.thicknessMap = nearestSlot();
    expectEachQuadrantIsItsTexelsFactors(scene, glass, mapped, rgba, [](const uint8_t* texel, MaterialParameters& m) {
        m.transmission = texel[0] / 255.0f;
        m.thickness = 2.0f * texel[1] / 255.0f;
    }, 0, 0.1f);
}

// KHR_materials_specular's maps: the colour map's RGB (sRGB) scales the tint, the specular map's
// A the weight (one image holds both here); each quadrant is the quad drawn with the factors its
// texel stands for, and without the maps the picture differs.
TEST_F(ModelMaps, TheSpecularMapsScaleTheTintAndTheWeight) {
    const Scene scene = quadScene();
    const std::vector<uint8_t> rgba{255, 40, 40, 255, 40, 255, 40, 128, 200, 200, 255, 0, 255, 255, 255, 64};
    ModelMaterial tinted = factors(glm::vec3(0.2f, 0.3f, 0.4f));
    tinted.factors.roughness = 0.3f;
    tinted.factors.specular = 1.0f;
    tinted.factors.specularTint = {4.0f, 2.0f, 1.0f};
    tinted.factors.specularWeight = 0.9f;
    ModelMaterial mapped = tinted;
    mapped.specularColor = nearestSlot();
    mapped.specular = nearestSlot();
    expectEachQuadrantIsItsTexelsFactors(scene, tinted, mapped, rgba, [](const uint8_t* texel, MaterialParameters& m) {
        for (int c = 0; c < 3; ++c) {
            m.specularTint[c] *= shader::srgbDecode(texel[c] / 255.0f);
        }
        m.specularWeight *= texel[3] / 255.0f;
    }, 2, 0.05f);
}

// KHR_materials_anisotropy's map: each texel's RG turns the stretch's direction (its angle added
// to the rotation), its B scales the strength; each quadrant is the quad drawn with the factors
// its texel stands for, and without the map the picture differs.
TEST_F(ModelMaps, TheAnisotropyMapTurnsTheStretchAndScalesIt) {
    const Scene scene = quadScene();
    // (1, 0.5): along t; (0.5, 1): along b; (0, 0.5): against t (the same lobe); (0.85, 0.85) at 45 degrees.
    const std::vector<uint8_t> rgba{255, 128, 255, 255, 128, 255, 200, 255, 0, 128, 255, 255, 217, 217, 100, 255};
    ModelMaterial brushed = factors(glm::vec3(0.8f, 0.8f, 0.85f));
    brushed.factors.metallic = 1.0f;
    brushed.factors.roughness = 0.35f;
    brushed.factors.anisotropyStrength = 0.9f;
    brushed.factors.anisotropyRotation = 0.3f;
    ModelMaterial mapped = brushed;
    mapped.anisotropyMap = nearestSlot();
    expectEachQuadrantIsItsTexelsFactors(scene, brushed, mapped, rgba, [](const uint8_t* texel, MaterialParameters& m) {
        const float dx = 2.0f * texel[0] / 255.0f - 1.0f, dy = 2.0f * texel[1] / 255.0f - 1.0f;
        m.anisotropyRotation += std::atan2(dy, dx);
        m.anisotropyStrength *= texel[2] / 255.0f;
    }, 1, 0.02f);
}

// The specialised path compiles a program for each set of maps the items have (PATINA_MAP_SET),
// so a map an item lacks costs it nothing, and draws the same picture as the single path, whose
// one program asks the uniforms which maps there are.
TEST_F(ModelMaps, TheSpecialisedPathCompilesAProgramForEachMapSet) {
    const Scene scene = quadScene();
    Model model;
    model.primitives = {quad()};
    ModelMaterial coloured = factors(glm::vec3(0.9f, 0.8f, 0.7f));
    coloured.baseColor = nearestSlot();
    ModelMaterial bumped = factors(glm::vec3(0.4f, 0.6f, 0.8f));
    bumped.normal = nearestSlot();
    bumped.normal.image = 1;
    model.materials = {coloured, bumped, factors(glm::vec3(0.5f))};
    model.images = {image(2, 2, {200, 40, 40, 255, 40, 200, 40, 255, 40, 40, 200, 255, 230, 230, 230, 255}),
                    image(1, 1, {200, 90, 220, 255})};
    // Three quads side by side, half size: a base colour map, a normal map, no map.
    for (int i = 0; i < 3; ++i) {
        const glm::mat4 placed = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(float(i - 1) * 1.1f, 0.0f, 0.0f)),
                                            glm::vec3(0.5f));
        model.draws.push_back({0, i, placed, "quad " + std::to_string(i)});
    }
    const auto shared = std::make_shared<const Model>(std::move(model));
    Renderer fresh;
    const PreparedScene prepared{scene, std::make_shared<const Mesh>(shared->primitives[0]), nullptr, shared};
    const HdrImage specialised =
        fresh.render(prepared, test::renderSettings(kWidth, kHeight, RenderPath::Specialised, 1)).hdr;
    EXPECT_EQ(fresh.specialisedProgramCount(), 3u) << "base colour, normal, none";
    const HdrImage single = fresh.render(prepared, test::renderSettings(kWidth, kHeight, RenderPath::Single, 1)).hdr;
    for (int i = 0; i < 3; ++i) {
        for (const glm::vec3& corner : {glm::vec3(-0.2f, 0.2f, 0.0f), glm::vec3(0.2f, -0.2f, 0.0f)}) {
            const glm::ivec2 at = pixelOf(scene, corner + glm::vec3(float(i - 1) * 1.1f, 0.0f, 0.0f));
            const glm::vec3 a = test::pixel(specialised, at.x, at.y), b = test::pixel(single, at.x, at.y);
            EXPECT_GT(b.x + b.y + b.z, 0.05f) << "quad " << i << " is lit";
            EXPECT_LE(largestRelativeError(a, b), 1e-3f) << "quad " << i << " at " << at.x << " " << at.y;
        }
    }
}

// 3.9.2: roughness = factor x G, metallic = factor x B of the metallic-roughness map; a metallic
// factor of 1 the map lowers still has diffuse light (the specialised shader keeps it).
TEST_F(ModelMaps, TheMetallicRoughnessMapScalesRoughnessByGreenAndMetallicByBlue) {
    const Scene scene = quadScene();
    ModelMaterial mapped = factors(glm::vec3(0.9f, 0.6f, 0.3f));
    mapped.factors.roughness = 0.8f;
    mapped.factors.metallic = 1.0f;
    mapped.metallicRoughness = nearestSlot();
    const auto model = oneQuad(quad(), mapped, {image(1, 1, {255, 128, 64, 255})});
    ModelMaterial plain = mapped;
    plain.metallicRoughness = {};
    plain.factors.roughness = 0.8f * 128.0f / 255.0f;
    plain.factors.metallic = 64.0f / 255.0f;
    expectSame(scene, model, oneQuad(quad(), plain), kQuadrants, 1e-3f, "metallic-roughness");
}

// 3.9.3: the map's normal in the frame (T, cross(N, T) w, N): the quad shades as a quad whose
// vertex normal is that normal. w = -1 (mirrored UVs) turns the bitangent round.
TEST_F(ModelMaps, TheNormalMapBendsTheNormalInTheTangentFrame) {
    const Scene scene = quadScene();
    const std::vector<uint8_t> texel{200, 90, 220, 255};
    const glm::vec3 tangentNormal = glm::normalize(glm::vec3(texel[0], texel[1], texel[2]) * (2.0f / 255.0f) - 1.0f);
    for (float w : {1.0f, -1.0f}) {
        ModelMaterial mapped = factors(glm::vec3(0.7f));
        mapped.normal = nearestSlot();
        const auto model = oneQuad(quad({0, 0, 1}, w), mapped, {image(1, 1, texel)});
        // T = +x, N = +z, bitangent = cross(N, T) w = +y w.
        const glm::vec3 bent{tangentNormal.x, tangentNormal.y * w, tangentNormal.z};
        expectSame(scene, model, oneQuad(quad(bent), factors(glm::vec3(0.7f))), kQuadrants, 2e-3f,
                   "w = " + std::to_string(int(w)));
    }
}

// 3.9.3: occlusion darkens the hemisphere light (indirect light) by 1 + strength (R - 1), and
// leaves a directional light alone.
TEST_F(ModelMaps, OcclusionDarkensTheHemisphereLightOnly) {
    Scene scene = quadScene();
    ModelMaterial mapped = factors(glm::vec3(0.6f));
    mapped.occlusion = nearestSlot();
    mapped.occlusionStrength = 0.5f;
    const auto model = oneQuad(quad(), mapped, {image(1, 1, {64, 0, 0, 255})});
    const auto plain = oneQuad(quad(), factors(glm::vec3(0.6f)));
    const float occlusion = 1.0f + 0.5f * (64.0f / 255.0f - 1.0f);
    for (LightType kept : {LightType::Hemisphere, LightType::Directional}) {
        Scene lit = scene;
        std::erase_if(lit.lights, [&](const Light& light) { return light.type != kept; });
        ASSERT_EQ(lit.lights.size(), 1u) << lightTypeName(kept);
        const float expected = kept == LightType::Hemisphere ? occlusion : 1.0f;
        for (RenderPath path : kPaths) {
            const HdrImage a = render(lit, model, path, 1), b = render(lit, plain, path, 1);
            const glm::ivec2 at = pixelOf(lit, {0.2f, 0.1f, 0.0f});
            EXPECT_LE(largestRelativeError(test::pixel(a, at.x, at.y), test::pixel(b, at.x, at.y) * expected), 1e-3f)
                << lightTypeName(kept) << ", " << renderPathName(path);
        }
    }
}

// 3.9.3: emission = emissiveFactor x the map's texel, added once (the multi-pass path adds one
// pass per light: emission must come in one of them).
TEST_F(ModelMaps, EmissionIsAddedOnceOnEveryPath) {
    const Scene scene = quadScene();
    ASSERT_GE(scene.lights.size(), 2u);
    ModelMaterial mapped = factors(glm::vec3(0.5f));
    mapped.emissive = nearestSlot();
    mapped.emissiveFactor = {2.0f, 1.0f, 0.5f};
    const auto model = oneQuad(quad(), mapped, {image(1, 1, {255, 128, 255, 255})});
    const auto plain = oneQuad(quad(), factors(glm::vec3(0.5f)));
    const glm::vec3 emitted = mapped.emissiveFactor * glm::vec3(1.0f, shader::srgbDecode(128.0f / 255.0f), 1.0f);
    for (RenderPath path : kPaths) {
        for (int samples : {1, 4}) {
            const HdrImage a = render(scene, model, path, samples), b = render(scene, plain, path, samples);
            const glm::ivec2 at = pixelOf(scene, {0.3f, -0.2f, 0.0f});
            EXPECT_LE(largestRelativeError(test::pixel(a, at.x, at.y) - test::pixel(b, at.x, at.y), emitted), 1e-2f)   // sRGB
                << renderPathName(path) << ", " << samples << " samples";
        }
    }
}

// 3.9.4: MASK draws a pixel only where alpha (factor x the base colour map's) reaches the
// cutoff; the pixels cut out show what is behind, on every path (the multi-pass depth
// pre-pass must cut them out too, or the light passes would add nothing there and leave black).
TEST_F(ModelMaps, MaskCutsOutThePixelsBelowTheCutoff) {
    Scene scene = quadScene();
    scene.display.background = {0.25f, 0.5f, 0.75f};
    ModelMaterial mapped = factors(glm::vec3(0.8f));
    mapped.baseColor = nearestSlot();
    mapped.alphaMode = AlphaMode::Mask;
    mapped.alphaCutoff = 0.5f;
    // Left column opaque, right column alpha 0.4 (cut out); the factor's alpha 0.9 keeps the left.
    mapped.baseAlpha = 0.9f;
    const auto model = oneQuad(quad(), mapped, {image(2, 1, {255, 255, 255, 255, 255, 255, 255, 102})});
    expectRightHalfCutOut(scene, model);
}

// 3.9.2: COLOR_0 multiplies the base colour factor (a primitive with colours is shaded with its
// maps even where its material has none). In a frame where one item has colours, another
// without them keeps its factor: it reads the attribute's constant 1.
TEST_F(ModelMaps, VertexColoursMultiplyTheBaseColourOnEveryPath) {
    Scene scene = quadScene();
    scene.camera.position = {0.0f, 0.0f, 6.0f};
    const glm::vec4 colour(0.5f, 1.0f, 0.25f, 1.0f);
    Mesh coloured = quad();
    coloured.colors.assign(4, colour);
    auto twoQuads = [](const Mesh& left, const ModelMaterial& leftMaterial, const ModelMaterial& rightMaterial) {
        Model model;
        model.primitives = {left, quad()};
        model.materials = {leftMaterial, rightMaterial};
        model.draws = {{0, 0, glm::translate(glm::mat4(1.0f), glm::vec3(-1.2f, 0, 0)), "left"},
                       {1, 1, glm::translate(glm::mat4(1.0f), glm::vec3(1.2f, 0, 0)), "right"}};
        return std::make_shared<const Model>(std::move(model));
    };
    const glm::vec3 factor(0.8f, 0.6f, 0.9f);
    const auto model = twoQuads(coloured, factors(factor), factors(factor));
    const auto expected = twoQuads(quad(), factors(factor * glm::vec3(colour)), factors(factor));
    expectSame(scene, model, expected, {{-1.2f, 0.3f, 0.0f}, {-0.7f, -0.5f, 0.0f}, {1.2f, 0.3f, 0.0f}}, 1e-4f,
               "vertex colours");
}

// 3.9.4: MASK's alpha is the factor's times the map's times the vertex colour's: alpha falling
// from 1 at the left edge to 0 at the right cuts out the right half (the multi-pass depth
// pre-pass too, or the light passes would leave black there).
TEST_F(ModelMaps, AVertexColoursAlphaCutsOutUnderMask) {
    Scene scene = quadScene();
    scene.display.background = {0.25f, 0.5f, 0.75f};
    Mesh faded = quad();
    faded.colors = {{1, 1, 1, 1}, {1, 1, 1, 0}, {1, 1, 1, 0}, {1, 1, 1, 1}};
    ModelMaterial material = factors(glm::vec3(0.8f));
    material.alphaMode = AlphaMode::Mask;
    material.alphaCutoff = 0.5f;
    const auto model = oneQuad(faded, material);
    expectRightHalfCutOut(scene, model);
}

// The ground truth interpolates the vertex colours as the GPU does (perspective-correct, over a
// quad seen at a slant) and multiplies them in with a base colour map's texels.
TEST_F(ModelMaps, TheGroundTruthShadesTheVertexColoursAsTheGpu) {
    Scene scene = quadScene();
    scene.camera.position = {1.5f, 1.0f, 2.5f};
    Mesh mesh = quad();
    mesh.colors = {{1, 0.2f, 0.2f, 1}, {0.2f, 1, 0.2f, 1}, {0.2f, 0.2f, 1, 1}, {1, 1, 0.2f, 1}};
    ModelMaterial mapped = factors(glm::vec3(0.9f));
    mapped.baseColor = nearestSlot();
    const auto model = oneQuad(mesh, mapped, {image(2, 2, {255, 255, 255, 255, 128, 128, 128, 255, 200, 200, 200, 255,
                                                           90, 90, 90, 255})});
    const PreparedScene prepared{scene, std::make_shared<const Mesh>(model->primitives[0]), nullptr, model};
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kWidth, kHeight);
    ReferenceRenderOptions options;
    options.samplesPerPixel = 1;
    const ReferenceImage reference = renderReference(prepared, surfaces, options);
    const HdrImage withoutColours = render(scene, oneQuad(quad(), mapped, model->images), RenderPath::Single, 1);
    for (RenderPath path : kPaths) {
        const HdrImage shown = render(scene, model, path, 1);
        int covered = 0, agreeing = 0, coloured = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                if (surfaces.sampleOfPixel[size_t(y * kWidth + x)] < 0) {
                    continue;
                }
                ++covered;
                agreeing += largestRelativeError(test::pixel(shown, x, y), test::pixel(reference.value, x, y)) <= 2e-2f;
                coloured += largestRelativeError(test::pixel(shown, x, y), test::pixel(withoutColours, x, y)) > 0.1f;
            }
        }
        EXPECT_GT(covered, 1000);
        EXPECT_GT(coloured, covered / 2) << "the colours show";
        EXPECT_GE(agreeing, covered * 98 / 100) << renderPathName(path) << ": " << agreeing << " of " << covered;
    }
}

// KHR_texture_transform: an offset of half the image in u moves the right column to the left.
TEST_F(ModelMaps, TheTextureTransformMovesTheMap) {
    const Scene scene = quadScene();
    ModelMaterial mapped = factors(glm::vec3(1.0f));
    mapped.baseColor = nearestSlot();
    mapped.baseColor.sampler.wrapS = TextureWrap::Repeat;
    mapped.baseColor.transform.offset = {0.5f, 0.0f};
    const auto model = oneQuad(quad(), mapped, {image(2, 1, {255, 0, 0, 255, 0, 0, 255, 255})});
    expectSame(scene, model, oneQuad(quad(), factors({0.0f, 0.0f, 1.0f})), {{-0.5f, 0.2f, 0.0f}}, 1e-3f, "left");
    expectSame(scene, model, oneQuad(quad(), factors({1.0f, 0.0f, 0.0f})), {{0.5f, 0.2f, 0.0f}}, 1e-3f, "right");
}

// A small texture of varied texels (a fixed pattern of `seed`), magnified over the quad so
// that the GPU reads its mip 0 as the CPU does.
std::vector<uint8_t> pattern(int width, int height, unsigned seed) {
    std::vector<uint8_t> rgba(size_t(width * height * 4));
    for (size_t i = 0; i < rgba.size(); ++i) {
        seed = seed * 1664525u + 1013904223u;
        rgba[i] = uint8_t(64 + (seed >> 24) % 192);
    }
    return rgba;
}

// A material with all five maps, on images 0 to 4 (patterns()), a normal map transform, emission
// and MASK; roughness 0.9 (D is steep at low roughness, where the filters' rounding would show).
// KHR_materials_specular's two maps read images 1 and 4 again, over a tinted F0 and a weight;
// KHR_materials_iridescence's images 0 and 3, over a film.
ModelMaterial everyMap() {
    ModelMaterial mapped = factors(glm::vec3(0.9f, 0.8f, 0.7f));
    mapped.factors.metallic = 0.6f;
    mapped.factors.roughness = 0.9f;
    int image = 0;
    for (const MapOf<TextureSlot>& map : mapsOf(mapped)) {
        map.slot->image = image++;
    }
    mapped.factors.specular = 1.0f;
    mapped.factors.specularTint = {3.0f, 1.0f, 0.5f};
    mapped.factors.specularWeight = 0.8f;
    mapped.specularColor.image = 1;
    mapped.specular.image = 4;
    // KHR_materials_iridescence's two read images 0 and 3, over a film.
    mapped.factors.iridescence = 0.9f;
    mapped.factors.iridescenceThicknessMinimum = 150.0f;
    mapped.factors.iridescenceThicknessMaximum = 700.0f;
    mapped.iridescenceMap.image = 0;
    mapped.iridescenceThickness.image = 3;
    // KHR_materials_anisotropy's reads image 2, over a stretched lobe.
    mapped.factors.anisotropyStrength = 0.6f;
    mapped.factors.anisotropyRotation = 0.4f;
    mapped.anisotropyMap.image = 2;
    mapped.normal.transform = {{0.1f, 0.2f}, {1.5f, 1.0f}, 0.3f};
    mapped.emissiveFactor = {0.05f, 0.02f, 0.01f};
    mapped.alphaMode = AlphaMode::Mask;
    mapped.alphaCutoff = 0.4f;
    return mapped;
}

// Five 6 x 5 patterns from `seed` on.
std::vector<ModelImage> patterns(unsigned seed) {
    std::vector<ModelImage> images;
    for (unsigned i = 0; i < 5; ++i) {
        images.push_back(image(6, 5, pattern(6, 5, seed + i)));
    }
    return images;
}

// The CPU twin (reference/surface_maps.h) shades a textured item as the GPU does: every map at
// once, bilinear, under the analytic lights (which the ground truth adds exactly), MASK's
// cut-outs included. They differ by the GPU's filtering arithmetic (8-bit weights on llvmpipe)
// and its sRGB decode.
TEST_F(ModelMaps, TheGroundTruthShadesTheSameMapsAsTheGpu) {
    const Scene scene = quadScene();
    ModelMaterial mapped = everyMap();
    for (const MapOf<TextureSlot>& map : mapsOf(mapped)) {
        map.slot->sampler.wrapS = TextureWrap::MirroredRepeat;
    }
    const std::vector<ModelImage> images = patterns(7u);
    const auto model = oneQuad(quad(glm::vec3(0.1f, 0.0f, 1.0f)), mapped, images);
    const PreparedScene prepared{scene, std::make_shared<const Mesh>(model->primitives[0]), nullptr, model};
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kWidth, kHeight);
    ASSERT_EQ(surfaces.sampleMaterials.size(), surfaces.samples.size());
    ReferenceRenderOptions options;
    options.samplesPerPixel = 1;
    const ReferenceImage reference = renderReference(prepared, surfaces, options);
    for (RenderPath path : kPaths) {
        const HdrImage shown = render(scene, model, path, 1);
        int covered = 0, agreeing = 0, cut = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                const glm::vec3 a = test::pixel(shown, x, y), b = test::pixel(reference.value, x, y);
                if (surfaces.sampleOfPixel[size_t(y * kWidth + x)] < 0) {
                    cut += pixelOf(scene, {-0.9f, -0.9f, 0.0f}).x < x && x < pixelOf(scene, {0.9f, 0.9f, 0.0f}).x &&
                           pixelOf(scene, {0.9f, 0.9f, 0.0f}).y < y && y < pixelOf(scene, {-0.9f, -0.9f, 0.0f}).y;
                    continue;
                }
                ++covered;
                agreeing += largestRelativeError(a, b) <= 2e-2f;
            }
        }
        EXPECT_GT(cut, 100) << "MASK cuts out some of the quad";
        EXPECT_GT(covered, 1000);
        // Texel edges: where the two filters' arithmetic puts a pixel across a sharp step.
        EXPECT_GE(agreeing, covered * 97 / 100) << renderPathName(path) << ": " << agreeing << " of " << covered;
    }
}

// The inspector's channels of a textured item (every map, a transform, MASK): the GPU's channel
// render is the CPU twin's (reference/channel_image.h) wherever both see the quad, but for the
// two filters' arithmetic at texel edges, as the shading above.
TEST_F(ModelMaps, EveryChannelOfATexturedItemIsTheCpuTwins) {
    const Scene scene = quadScene();
    ModelMaterial mapped = everyMap();
    mapped.occlusion.texCoord = 1;
    std::vector<ModelImage> images = patterns(3u);
    // A normal map as they are: tilts within 30 degrees of the surface's normal (random texels
    // would turn normals away from the viewer, where normalising magnifies the filters' rounding).
    for (size_t i = 0; i < images[2].rgba.size(); i += 4) {
        images[2].rgba[i] = uint8_t(96 + images[2].rgba[i] % 64);
        images[2].rgba[i + 1] = uint8_t(96 + images[2].rgba[i + 1] % 64);
        images[2].rgba[i + 2] = 255;
    }
    // The anisotropy reads a pattern of its own: the normal map's RG, near (0.5, 0.5), are
    // directions of almost no length, whose angle the filters' rounding turns at will (D and G
    // read the stretched lobe, which turns with it).
    mapped.anisotropyMap.image = 0;
    Mesh mirrored = quad(glm::vec3(0.1f, 0.0f, 1.0f), -1.0f);
    mirrored.uv1 = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    const auto model = oneQuad(mirrored, mapped, images);
    const PreparedScene prepared{scene, std::make_shared<const Mesh>(model->primitives[0]), nullptr, model};
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kWidth, kHeight);
    for (const std::string& name : fixedChannelNames()) {
        RenderSettings settings = test::renderSettings(kWidth, kHeight, RenderPath::Specialised, 4);
        settings.channel = *channelFromName(name);
        const HdrImage shown = renderer_.render(prepared, settings).hdr;
        const HdrImage twin = channelImage(prepared, surfaces, settings.channel);
        int covered = 0, agreeing = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                if (surfaces.sampleOfPixel[size_t(y * kWidth + x)] >= 0) {
                    ++covered;
                    const glm::vec3 a = test::pixel(shown, x, y), b = test::pixel(twin, x, y);
                    // D and G magnify the normal's few-per-mille filtering differences several times.
                    agreeing += glm::all(glm::lessThanEqual(glm::abs(a - b), 1e-2f + 4e-2f * glm::abs(b)));
                }
            }
        }
        EXPECT_GT(covered, 1000) << name;
        EXPECT_GE(agreeing, covered * 97 / 100) << name << ": " << agreeing << " of " << covered;
    }
}

// Where a map is minified the CPU twin reads the GPU's mip levels at the GPU's level of detail
// (texture.glsl's textureLevelOfDetail, shading/texture_sampling.h's mipLevels): a busy
// 256 x 256 map, repeated four times across a quad seen at a slant, shows as the same blur of
// its texels on both (with level 0 alone the CPU would show the texels' noise). Each sampler
// the glTF enums give: trilinear, nearest within a level, and no mipmaps.
TEST_F(ModelMaps, AMinifiedMapReadsTheSameLevelsOnTheCpuAsOnTheGpu) {
    Scene scene = quadScene();
    scene.camera.position = {0.0f, 2.2f, 2.2f};   // 45 degrees: the far side more minified than the near
    Mesh slanted = quad();
    const std::vector<uint8_t> busy = pattern(256, 256, 11u);
    for (const auto& [nearest, mipmaps] : {std::pair{false, true}, std::pair{true, true}, std::pair{false, false}}) {
        ModelMaterial mapped = factors(glm::vec3(1.0f));
        mapped.baseColor.image = 0;
        mapped.baseColor.transform.scale = {4.0f, 4.0f};
        mapped.baseColor.sampler.nearestMinification = nearest;
        mapped.baseColor.sampler.mipmaps = mipmaps;
        const auto model = oneQuad(slanted, mapped, {image(256, 256, busy)});
        const PreparedScene prepared{scene, std::make_shared<const Mesh>(model->primitives[0]), nullptr, model};
        const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kWidth, kHeight);
        ReferenceRenderOptions options;
        options.samplesPerPixel = 1;
        const ReferenceImage reference = renderReference(prepared, surfaces, options);
        const HdrImage shown = render(scene, model, RenderPath::Single, 1);
        int covered = 0, agreeing = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                if (surfaces.sampleOfPixel[size_t(y * kWidth + x)] >= 0) {
                    ++covered;
                    agreeing += largestRelativeError(test::pixel(shown, x, y), test::pixel(reference.value, x, y)) <= 3e-2f;
                }
            }
        }
        EXPECT_GT(covered, 2000);
        // Every pixel agrees on llvmpipe (with level 0 alone on the CPU, none did); a margin for
        // another rasteriser's filtering arithmetic.
        EXPECT_GE(agreeing, covered * 98 / 100)
            << "nearest " << nearest << ", mipmaps " << mipmaps << ": " << agreeing << " of " << covered;
    }
}

}  // namespace
}  // namespace patina
