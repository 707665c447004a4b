// PBR validation (engine/model/pbr_validation.h): the ranges at their edges, and a map's texels
// counted as the shader reads them.
#include <gtest/gtest.h>

#include "model/pbr_validation.h"
#include "shading/shading.h"

namespace patina {
namespace {

// The grey whose luminance encodes to `srgb` of 255.
glm::vec3 grey(int srgb) {
    return glm::vec3(shader::srgbDecode(float(srgb) / 255.0f));
}

TEST(PbrValidation, DielectricAlbedoAndMetalReflectanceAtTheirEdges) {
    const PbrRanges ranges;
    EXPECT_EQ(checkBaseColor(grey(30), 0.0f, 0.0f, ranges).verdict, PbrVerdict::Ok);
    EXPECT_EQ(checkBaseColor(grey(30), 0.0f, 0.0f, ranges).value, 30);
    EXPECT_EQ(checkBaseColor(grey(29), 0.0f, 0.0f, ranges).verdict, PbrVerdict::DielectricTooDark);
    EXPECT_EQ(checkBaseColor(grey(240), 0.0f, 0.0f, ranges).verdict, PbrVerdict::Ok);
    EXPECT_EQ(checkBaseColor(grey(241), 0.0f, 0.0f, ranges).verdict, PbrVerdict::DielectricTooBright);
    EXPECT_EQ(checkBaseColor(grey(155), 1.0f, 0.0f, ranges).verdict, PbrVerdict::Ok);
    EXPECT_EQ(checkBaseColor(grey(154), 1.0f, 0.0f, ranges).verdict, PbrVerdict::MetalTooDark);
    EXPECT_EQ(checkBaseColor(grey(255), 1.0f, 0.0f, ranges).verdict, PbrVerdict::Ok);   // no upper bound for metals
    // Metal from metallic 0.5 up; strict ranges move the lower edges.
    EXPECT_TRUE(checkBaseColor(grey(100), 0.5f, 0.0f, ranges).metal);
    EXPECT_FALSE(checkBaseColor(grey(100), 0.49f, 0.0f, ranges).metal);
    EXPECT_EQ(checkBaseColor(grey(45), 0.0f, 0.0f, PbrRanges::strict()).verdict, PbrVerdict::DielectricTooDark);
    EXPECT_EQ(checkBaseColor(grey(170), 1.0f, 0.0f, PbrRanges::strict()).verdict, PbrVerdict::MetalTooDark);
    // The value is the luminance (Rec. 709): saturated green is lighter than saturated blue.
    EXPECT_GT(checkBaseColor({0.0f, 0.5f, 0.0f}, 0.0f, 0.0f, ranges).value,
              checkBaseColor({0.0f, 0.0f, 0.5f}, 0.0f, 0.0f, ranges).value);
}

// KHR_materials_transmission: what a thin wall passes is not albedo. A dielectric's bright end is
// the share it reflects, c_base (1 - transmission); its dark end the whole colour; a metal's as
// ever.
TEST(PbrValidation, ATransmittingDielectricsBrightEndIsTheShareItReflects) {
    const PbrRanges ranges;
    const PbrCheck glass = checkBaseColor(glm::vec3(1.0f), 0.0f, 1.0f, ranges);
    EXPECT_EQ(glass.verdict, PbrVerdict::Ok);
    EXPECT_EQ(glass.value, 255);
    EXPECT_EQ(glass.reflected, 0);
    EXPECT_EQ(checkBaseColor(grey(255), 0.0f, 0.0f, ranges).verdict, PbrVerdict::DielectricTooBright);
    // c_base (1 - t) at the edge: 240 passes, 241 does not.
    const float white = shader::srgbDecode(1.0f);
    EXPECT_EQ(checkBaseColor(glm::vec3(white), 0.0f, 1.0f - grey(240).x, ranges).verdict, PbrVerdict::Ok);
    EXPECT_EQ(checkBaseColor(glm::vec3(white), 0.0f, 1.0f - grey(241).x, ranges).verdict,
              PbrVerdict::DielectricTooBright);
    EXPECT_EQ(checkBaseColor(grey(29), 0.0f, 1.0f, ranges).verdict, PbrVerdict::DielectricTooDark);
    EXPECT_EQ(checkBaseColor(grey(154), 1.0f, 1.0f, ranges).verdict, PbrVerdict::MetalTooDark);
}

TEST(PbrValidation, TexelsAreTheFactorTimesTheDecodedMapWithTheMetallicMapsBlue) {
    Model model;
    // Base colour: a black texel, a mid grey, white, and mid grey again; metallic map (2 x 1):
    // dielectric on the left half, metal on the right.
    model.images.push_back({"base", 4, 1, {0, 0, 0, 255, 128, 128, 128, 255, 255, 255, 255, 255, 128, 128, 128, 255}});
    model.images.push_back({"mr", 2, 1, {0, 255, 0, 255, 0, 255, 255, 255}});
    ModelMaterial material;
    material.factors.baseColor = glm::vec3(1.0f);
    material.factors.metallic = 1.0f;
    material.baseColor.image = 0;
    material.metallicRoughness.image = 1;
    const PbrTally tally = checkBaseColorTexels(model, material, PbrRanges{});
    EXPECT_EQ(tally.texels, 4u);
    EXPECT_EQ(tally.dielectricDark, 1u);     // black, dielectric
    EXPECT_EQ(tally.dielectricBright, 0u);   // the grey on the left is in range
    EXPECT_EQ(tally.metalDark, 1u);          // the grey on the right, as a metal, is too dark
    // Without the metallic map the factor alone: all metal; black and both greys too dark.
    material.metallicRoughness = {};
    EXPECT_EQ(checkBaseColorTexels(model, material, PbrRanges{}).metalDark, 3u);
    material.baseColor = {};
    EXPECT_EQ(checkBaseColorTexels(model, material, PbrRanges{}).texels, 0u);   // no map, nothing counted
}

// A white map over a transmission map (R): the texels that pass all their light are in range,
// those that pass none brighter than snow.
TEST(PbrValidation, TexelsReadTheTransmissionMapsRed) {
    Model model;
    model.images.push_back({"base", 2, 1, {255, 255, 255, 255, 255, 255, 255, 255}});
    model.images.push_back({"transmission", 2, 1, {255, 0, 0, 255, 0, 0, 0, 255}});
    ModelMaterial material;
    material.factors.baseColor = glm::vec3(1.0f);
    material.factors.metallic = 0.0f;
    material.factors.transmission = 1.0f;
    material.baseColor.image = 0;
    material.transmissionMap.image = 1;
    EXPECT_EQ(checkBaseColorTexels(model, material, PbrRanges{}).dielectricBright, 1u);
    material.transmissionMap = {};
    EXPECT_EQ(checkBaseColorTexels(model, material, PbrRanges{}).dielectricBright, 0u);   // the factor passes all
}

}  // namespace
}  // namespace patina
