// Blender 3.4's own export of every material layer Patina draws (tests/data/layers/layers.glb,
// made by its make_layers.py; issue 36, item 6): the file is validator-clean, every extension
// in it is one Patina draws, and each material's layer is read as the exporter wrote it.
#include <algorithm>

#include <gtest/gtest.h>

#include "blender_layers.h"
#include "gltf/model_import.h"
#include "scratch_test.h"
#include "shading/shading.h"
#include "validator.h"

namespace patina {
namespace {

using namespace test;

class BlenderLayers : public ScratchTest {};

TEST_F(BlenderLayers, TheFileIsValidatorCleanAndEveryExtensionInItIsDrawn) {
    expectValidGltf(blenderLayersFile(), dir_);
    const Model model = importGltfModel(blenderLayersFile());
    // Blender's tinted specular (F0 0.134 of three colours) and its ior 2.4 (F0 0.17) are more than
    // Patina's grey F0 of at most 0.08 shows: said, each once, and nothing else.
    ASSERT_EQ(model.notes.size(), 2u) << model.notes.front();
    EXPECT_NE(model.notes[0].find("material \"specular\" (/materials/3): "), std::string::npos) << model.notes[0];
    EXPECT_NE(model.notes[0].find("is drawn grey, at its largest"), std::string::npos) << model.notes[0];
    EXPECT_NE(model.notes[1].find("material \"ior\" (/materials/6): "), std::string::npos) << model.notes[1];
    EXPECT_NE(model.notes[1].find("its F0 of 0.17 (ior 2.4) is drawn as 0.08"), std::string::npos) << model.notes[1];
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

// KHR_materials_specular and _ior as Blender 3.4 writes them. Specular 1 and Specular Tint 0.5
// on the red base become specularColorFactor (3.35, 1.44, 1.29) at glTF's IOR 1.5: an F0 of
// (0.134, 0.058, 0.052), Blender's own. Patina's F0 is grey and at most 0.08 (specular 1): the
// sphere shows 0.08, above the plain twin's 0.04 but short of the red channel's 0.134. IOR 2.4
// beside a transmission is an F0 of 0.17, also held at 0.08 (docs/SHADING.md, "Blender's layers").
TEST_F(BlenderLayers, SpecularAndIorRaiseTheF0UpToPatinasHighest) {
    const Model model = importGltfModel(blenderLayersFile());
    ASSERT_EQ(model.materials.size(), 8u);
    auto specular = [&](BlenderLayer layer) { return model.materials[size_t(layer)].factors.specular; };
    EXPECT_EQ(specular(kSpecular), 1.0f);
    EXPECT_EQ(specular(kIor), 1.0f);
    EXPECT_FLOAT_EQ(specular(kTransmission), 0.5f);
    EXPECT_FLOAT_EQ(shader::F0_PER_SPECULAR * specular(kSpecular), 0.08f);
}

}  // namespace
}  // namespace patina
