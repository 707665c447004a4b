// Blender 3.4's own export of every material layer Patina draws (tests/data/layers/layers.glb,
// made by its make_layers.py; issue 36, item 6): the file is validator-clean, every extension
// in it is one Patina draws, and each material's layer is read as the exporter wrote it.
#include <algorithm>

#include <gtest/gtest.h>

#include "blender_layers.h"
#include "gltf/model_import.h"
#include "scratch_test.h"
#include "shading/cpu_shading.h"
#include "shading/shading.h"
#include "validator.h"

namespace patina {
namespace {

using namespace test;

class BlenderLayers : public ScratchTest {};

TEST_F(BlenderLayers, TheFileIsValidatorCleanAndEveryExtensionInItIsDrawn) {
    expectValidGltf(blenderLayersFile(), dir_);
    const Model model = importGltfModel(blenderLayersFile());
    // Blender's tinted specular (F0 0.134 of three colours) and its ior 2.4 (F0 0.17) are drawn
    // as they are (SpecularAndIorAreTheDielectricsF0): nothing is noted.
    EXPECT_TRUE(model.notes.empty()) << model.notes.front();
    ASSERT_EQ(model.extensions.size(), 6u);
    for (const ModelExtension& extension : model.extensions) {
        EXPECT_EQ(extension.support, ExtensionSupport::Drawn) << extension.name;
    }
    ASSERT_EQ(model.materials.size(), 8u);
    ASSERT_EQ(model.draws.size(), 8u);
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(model.materials[size_t(i)].name, kBlenderLayerNames[i]);
        EXPECT_EQ(model.draws[size_t(i)].material, i);
    }
}

// Each layer as Blender's exporter wrote it, the plain twin with none of them: Clearcoat 1 at
// roughness 0.05; a Velvet BSDF's Color 0.9 and Sigma 0.5 as the sheen; Transmission 1; the
// "glTF Material Output" group's Thickness 1.5 and a Volume Absorption's colour (1, 0.6, 0.2)
// at density 2 (distance 0.5).
TEST_F(BlenderLayers, EachLayerIsReadAsBlenderWroteIt) {
    const Model model = importGltfModel(blenderLayersFile());
    ASSERT_EQ(model.materials.size(), 8u);
    auto factors = [&](BlenderLayer layer) { return model.materials[size_t(layer)].factors; };
    const MaterialParameters plain = factors(kPlain);
    EXPECT_EQ(plain.model, BrdfModelId::Gltf);
    EXPECT_EQ(plain.clearcoat, 0.0f);
    EXPECT_EQ(plain.sheenColor, glm::vec3(0.0f));
    EXPECT_EQ(plain.transmission, 0.0f);
    EXPECT_FLOAT_EQ(plain.specular, 0.5f);   // glTF's F0 0.04 at IOR 1.5
    EXPECT_EQ(factors(kClearcoat).clearcoat, 1.0f);
    EXPECT_FLOAT_EQ(factors(kClearcoat).clearcoatRoughness, 0.05f);
    EXPECT_FLOAT_EQ(factors(kSheen).sheenColor.g, 0.9f);
    EXPECT_EQ(factors(kSheen).sheenColor.r, factors(kSheen).sheenColor.b);
    EXPECT_EQ(factors(kSheen).sheenRoughness, 0.5f);
    for (BlenderLayer layer : {kTransmission, kRoughTransmission, kIor, kVolume}) {
        EXPECT_EQ(factors(layer).transmission, 1.0f) << kBlenderLayerNames[layer];
    }
    EXPECT_EQ(factors(kTransmission).thickness, 0.0f);   // thin: no volume
    EXPECT_EQ(factors(kVolume).thickness, 1.5f);
    EXPECT_FLOAT_EQ(factors(kVolume).attenuationColor.g, 0.6f);
    EXPECT_FLOAT_EQ(factors(kVolume).attenuationColor.b, 0.2f);
    EXPECT_EQ(factors(kVolume).attenuationDistance, 0.5f);
    // The layers stay on their own spheres.
    for (int i = 0; i < 8; ++i) {
        const MaterialParameters& m = model.materials[size_t(i)].factors;
        EXPECT_EQ(m.clearcoat > 0.0f, i == kClearcoat) << i;
        EXPECT_EQ(m.sheenColor != glm::vec3(0.0f), i == kSheen) << i;
        EXPECT_EQ(m.thickness > 0.0f, i == kVolume) << i;
    }
}

// KHR_materials_specular and _ior as Blender 3.4 writes them, drawn as the extensions define the
// dielectric's F0, min(((ior - 1) / (ior + 1))^2 specularColorFactor, 1) per channel. Specular 1
// and Specular Tint 0.5 on the red base become specularColorFactor (3.35, 1.44, 1.29) at glTF's
// IOR 1.5: an F0 of (0.134, 0.058, 0.052), Blender's own. IOR 2.4 beside a transmission is an F0
// of 0.17. The file's values (its JSON) against the F0 the shader derives from what was read.
TEST_F(BlenderLayers, SpecularAndIorAreTheDielectricsF0) {
    const Model model = importGltfModel(blenderLayersFile());
    ASSERT_EQ(model.materials.size(), 8u);
    auto f0Of = [&](BlenderLayer layer) { return surfaceMaterial(model.materials[size_t(layer)].factors).dielectricF0; };
    auto glTFsF0 = [](double ior, glm::dvec3 color) {
        const double r = (ior - 1.0) / (ior + 1.0);
        return glm::min(r * r * color, glm::dvec3(1.0));
    };
    const glm::dvec3 tinted = glTFsF0(1.5, {3.3529411610022546, 1.4411764786446586, 1.2941176451252816});
    const glm::dvec3 gem = glTFsF0(2.4000000953674316, glm::dvec3(1.0));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(f0Of(kSpecular)[c], tinted[c], 1e-6) << c;
        EXPECT_NEAR(f0Of(kIor)[c], gem[c], 1e-6) << c;
        EXPECT_NEAR(f0Of(kPlain)[c], 0.04, 1e-7) << c;
        EXPECT_NEAR(f0Of(kTransmission)[c], 0.04, 1e-7) << c;
    }
    EXPECT_NEAR(tinted.r, 0.134, 5e-4);   // Blender's own, as docs/SHADING.md quotes it
    EXPECT_NEAR(gem.r, 0.1696, 5e-4);
    // Neither has a specularFactor: the Fresnel's weight stays 1 (F90 1).
    EXPECT_EQ(model.materials[size_t(kSpecular)].factors.specularWeight, 1.0f);
}

}  // namespace
}  // namespace patina
