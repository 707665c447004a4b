// KHR_materials_pbrSpecularGlossiness converted to metallic-roughness (engine/gltf/spec_gloss.h):
// the Khronos example's formulas, checked against the inverse conversion the same example
// gives (metallic-roughness to specular-glossiness), and on whole files.
#include <algorithm>

#include <gtest/gtest.h>

#include "gltf/model_import.h"
#include "gltf/spec_gloss.h"
#include "gltf_builder.h"
#include "image/image.h"
#include "scratch_test.h"
#include "shading/shading.h"

namespace patina {
namespace {

using gltf::MetallicRoughness;
using gltf::SpecularGlossiness;

// The example's ConvertToSpecularGlossiness, written from its formulas: specular = mix(0.04,
// base, metallic); diffuse = base (1 - 0.04) (1 - metallic) / (1 - max(specular)).
SpecularGlossiness toSpecularGlossiness(glm::vec3 base, float metallic, float roughness) {
    SpecularGlossiness result;
    result.specular = glm::mix(glm::vec3(0.04f), base, metallic);
    const float oneMinusStrength = 1.0f - std::max({result.specular.r, result.specular.g, result.specular.b});
    result.diffuse = base * (0.96f * (1.0f - metallic) / std::max(oneMinusStrength, 1e-6f));
    result.glossiness = 1.0f - roughness;
    return result;
}

// The two conversions are inverses where a material is a dielectric or a metal (metallic 0 or
// 1): what a spec-gloss file made from a metallic-roughness material says comes back.
TEST(SpecularGlossiness, TheConversionUndoesTheInverseForDielectricsAndMetals) {
    const struct {
        glm::vec3 base;
        float metallic, roughness;
    } cases[] = {{{0.8f, 0.2f, 0.1f}, 0.0f, 0.5f}, {{0.18f, 0.18f, 0.18f}, 0.0f, 0.0f},
                 {{1.0f, 0.766f, 0.336f}, 1.0f, 0.1f}, {{0.95f, 0.64f, 0.54f}, 1.0f, 0.9f}};
    for (const auto& c : cases) {
        const MetallicRoughness back = gltf::metallicRoughnessFrom(toSpecularGlossiness(c.base, c.metallic, c.roughness));
        EXPECT_NEAR(back.metallic, c.metallic, 1e-4f) << c.base.r;
        EXPECT_NEAR(back.roughness, c.roughness, 1e-6f);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(back.baseColor[i], c.base[i], 2e-3f) << c.base.r << " channel " << i;
        }
    }
}

// The extension README's gold (diffuse black, specular 1 0.766 0.336) is a metal of that colour;
// a specular below a dielectric's 0.04 is no metal, its diffuse scaled by (1 - max specular) / 0.96.
TEST(SpecularGlossiness, GoldIsAMetalAndADarkSpecularADielectric) {
    SpecularGlossiness gold;
    gold.diffuse = glm::vec3(0.0f);
    gold.specular = {1.0f, 0.766f, 0.336f};
    gold.glossiness = 0.9f;
    const MetallicRoughness metal = gltf::metallicRoughnessFrom(gold);
    EXPECT_NEAR(metal.metallic, 1.0f, 1e-5f);
    EXPECT_NEAR(metal.baseColor.g, 0.766f, 1e-4f);
    EXPECT_NEAR(metal.roughness, 0.1f, 1e-6f);

    SpecularGlossiness matte;
    matte.diffuse = {0.5f, 0.4f, 0.3f};
    matte.specular = glm::vec3(0.02f);
    const MetallicRoughness dielectric = gltf::metallicRoughnessFrom(matte);
    EXPECT_EQ(dielectric.metallic, 0.0f);
    EXPECT_NEAR(dielectric.baseColor.r, 0.5f * 0.98f / 0.96f, 1e-6f);
    EXPECT_EQ(gltf::solveMetallic(0.5f, 0.039f, 0.96f), 0.0f);
    EXPECT_NEAR(gltf::perceivedBrightness(glm::vec3(1.0f)), 1.0f, 1e-6f);
}

class SpecGlossFile : public test::ScratchTest {};

// A file's factors convert once; with a diffuse map every texel converts into two new maps.
TEST_F(SpecGlossFile, FactorsConvertAndMapsConvertTexelByTexel) {
    test::GltfBuilder model = test::cubeModel();
    model.json["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
    model.json["materials"][0]["extensions"]["KHR_materials_pbrSpecularGlossiness"] = {
        {"diffuseFactor", {0.0, 0.0, 0.0, 1.0}}, {"specularFactor", {1.0, 0.766, 0.336}}, {"glossinessFactor", 0.9}};
    model.writeGltf(path("gold.gltf"));
    const Model gold = importGltfModel(path("gold.gltf"));
    EXPECT_NEAR(gold.materials[0].factors.metallic, 1.0f, 1e-5f);
    EXPECT_NEAR(gold.materials[0].factors.baseColor.b, 0.336f, 1e-4f);
    EXPECT_NEAR(gold.materials[0].factors.roughness, 0.1f, 1e-6f);
    ASSERT_EQ(gold.notes.size(), 1u);
    EXPECT_NE(gold.notes[0].find("converted to metallic-roughness by the Khronos conversion"), std::string::npos);

    // A grey diffuse map under a dielectric specular: the base colour map is the diffuse's
    // (0.96 / 0.96), the metallic-roughness map says metallic 0 and roughness 1 - 0.25.
    test::GltfBuilder::writeBytes(path("diffuse.png"), encodePng(LdrImage{2, 1, {128, 128, 128, 255, 255, 0, 0, 200}}));
    model.add("images", {{"uri", "diffuse.png"}});
    model.add("textures", {{"source", 0}});
    model.json["materials"][0]["extensions"]["KHR_materials_pbrSpecularGlossiness"] = {
        {"diffuseTexture", {{"index", 0}}}, {"specularFactor", {0.04, 0.04, 0.04}}, {"glossinessFactor", 0.25}};
    model.writeGltf(path("mapped.gltf"));
    const Model mapped = importGltfModel(path("mapped.gltf"));
    const ModelMaterial& material = mapped.materials[0];
    ASSERT_TRUE(material.baseColor.present());
    ASSERT_TRUE(material.metallicRoughness.present());
    EXPECT_EQ(material.factors.metallic, 1.0f);   // the maps carry it
    const ModelImage& base = mapped.images[size_t(material.baseColor.image)];
    const ModelImage& metalRough = mapped.images[size_t(material.metallicRoughness.image)];
    ASSERT_EQ(base.width, 2);
    EXPECT_NEAR(base.rgba[0], 128, 1);
    EXPECT_NEAR(base.rgba[4], 255, 1);
    EXPECT_EQ(base.rgba[7], 200);   // the diffuse's alpha
    EXPECT_EQ(metalRough.rgba[1], 191);   // roughness 0.75
    EXPECT_EQ(metalRough.rgba[2], 0);     // metallic 0
}

// Baked maps count against the model's image budget: past it the factors alone convert, said so.
TEST(SpecularGlossiness, MapsPastTheImageBudgetConvertByTheirFactors) {
    Model model;
    model.images.push_back({"diffuse", 64, 64, std::vector<uint8_t>(64 * 64 * 4, 200)});
    model.materials.push_back({});
    model.materials[0].name = "big";
    model.materials[0].baseColor.image = 0;   // the diffuse map, as the import leaves it
    gltf::SpecGlossMaterial source;
    source.factors.specular = glm::vec3(0.04f);
    gltf::convertSpecularGlossiness(model, {source}, 3 * 64 * 64 * 4 - 1);
    EXPECT_EQ(model.images.size(), 1u) << "nothing baked";
    EXPECT_FALSE(model.materials[0].baseColor.present());
    ASSERT_EQ(model.notes.size(), 1u);
    EXPECT_NE(model.notes[0].find("its factors alone"), std::string::npos) << model.notes[0];
    model.materials[0].baseColor.image = 0;   // the same material again, its map as read
    gltf::convertSpecularGlossiness(model, {source}, 3 * 64 * 64 * 4);
    EXPECT_EQ(model.images.size(), 3u) << "within the budget: baked";
}

}  // namespace
}  // namespace patina
