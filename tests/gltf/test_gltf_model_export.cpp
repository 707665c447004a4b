// Whole-model export (engine/gltf/model_export.h, `patina export` of a model): the Khronos
// validator finds no error and no warning, importing the export gives back every draw,
// material, map and texel, renders the same image, and carries the scene's tuning.
#include <filesystem>
#include <fstream>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "cli_runner.h"
#include "gltf/model_export.h"
#include "gltf_builder.h"
#include "gltf/model_import.h"
#include "image/image.h"
#include "files/file_bytes.h"
#include "files/input_error.h"
#include "io/json_writer.h"
#include "io/scene_file.h"
#include "model/placement.h"
#include "scene/prepared_scene.h"
#include "scratch_test.h"
#include "test_support.h"
#include "validator.h"

namespace patina {
namespace {

namespace fs = std::filesystem;
const fs::path kModels = "/usr/share/assimp/models/glTF2";

void expectNear(const glm::mat4& a, const glm::mat4& b, const std::string& what) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            EXPECT_NEAR(a[c][r], b[c][r], 1e-5f * (1.0f + std::abs(a[c][r]))) << what << " [" << c << "][" << r << "]";
        }
    }
}

void expectSameSlot(const TextureSlot& a, const TextureSlot& b, const Model& modelA, const Model& modelB,
                    const std::string& what) {
    ASSERT_EQ(a.present(), b.present()) << what;
    if (!a.present()) {
        return;
    }
    EXPECT_EQ(a.texCoord, b.texCoord) << what;
    EXPECT_EQ(a.sampler, b.sampler) << what;
    EXPECT_NEAR(a.transform.offset.x, b.transform.offset.x, 1e-6f) << what;
    EXPECT_NEAR(a.transform.offset.y, b.transform.offset.y, 1e-6f) << what;
    EXPECT_NEAR(a.transform.scale.x, b.transform.scale.x, 1e-6f) << what;
    EXPECT_NEAR(a.transform.scale.y, b.transform.scale.y, 1e-6f) << what;
    EXPECT_NEAR(a.transform.rotation, b.transform.rotation, 1e-6f) << what;
    const ModelImage& imageA = modelA.images[size_t(a.image)];
    const ModelImage& imageB = modelB.images[size_t(b.image)];
    EXPECT_EQ(imageA.width, imageB.width) << what;
    EXPECT_EQ(imageA.height, imageB.height) << what;
    EXPECT_TRUE(imageA.rgba == imageB.rgba) << what << ": the texels differ";
}

void expectSameMaterial(const ModelMaterial& a, const ModelMaterial& b, const Model& modelA, const Model& modelB) {
    EXPECT_EQ(a.name, b.name);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(a.factors.baseColor[i], b.factors.baseColor[i], 1e-6f) << a.name;
        EXPECT_NEAR(a.emissiveFactor[i], b.emissiveFactor[i], 1e-5f * (1.0f + a.emissiveFactor[i])) << a.name;
    }
    EXPECT_NEAR(a.factors.roughness, b.factors.roughness, 1e-6f) << a.name;
    EXPECT_NEAR(a.factors.metallic, b.factors.metallic, 1e-6f) << a.name;
    EXPECT_NEAR(a.factors.specular, b.factors.specular, 1e-5f) << a.name;
    EXPECT_EQ(a.factors.clearcoat, b.factors.clearcoat) << a.name;
    EXPECT_EQ(a.factors.clearcoatRoughness, b.factors.clearcoatRoughness) << a.name;
    if (a.clearcoatNormal.present()) {
        EXPECT_NEAR(a.clearcoatNormalScale, b.clearcoatNormalScale, 1e-6f) << a.name;
    }
    EXPECT_EQ(a.factors.sheenColor, b.factors.sheenColor) << a.name;
    EXPECT_EQ(a.factors.sheenRoughness, b.factors.sheenRoughness) << a.name;
    EXPECT_EQ(a.factors.transmission, b.factors.transmission) << a.name;
    EXPECT_EQ(a.factors.thickness, b.factors.thickness) << a.name;
    EXPECT_EQ(a.factors.attenuationColor, b.factors.attenuationColor) << a.name;
    EXPECT_EQ(a.factors.attenuationDistance, b.factors.attenuationDistance) << a.name;
    EXPECT_EQ(a.transmissionMap.present(), b.transmissionMap.present()) << a.name;
    EXPECT_EQ(a.thicknessMap.present(), b.thicknessMap.present()) << a.name;
    EXPECT_EQ(a.factors.anisotropyStrength, b.factors.anisotropyStrength) << a.name;
    EXPECT_EQ(a.factors.anisotropyRotation, b.factors.anisotropyRotation) << a.name;
    EXPECT_EQ(a.anisotropyMap.present(), b.anisotropyMap.present()) << a.name;
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(a.factors.specularTint[i], b.factors.specularTint[i], 1e-5f * (1.0f + a.factors.specularTint[i]))
            << a.name;
    }
    EXPECT_EQ(a.factors.specularWeight, b.factors.specularWeight) << a.name;
    EXPECT_EQ(a.factors.iridescence, b.factors.iridescence) << a.name;
    if (a.factors.iridescence > 0.0f) {   // glTF holds the film's ior and thicknesses with its strength
        EXPECT_EQ(a.factors.iridescenceIor, b.factors.iridescenceIor) << a.name;
        EXPECT_EQ(a.factors.iridescenceThicknessMinimum, b.factors.iridescenceThicknessMinimum) << a.name;
        EXPECT_EQ(a.factors.iridescenceThicknessMaximum, b.factors.iridescenceThicknessMaximum) << a.name;
    }
    EXPECT_NEAR(a.baseAlpha, b.baseAlpha, 1e-6f) << a.name;
    // glTF holds the scale and the strength with their maps: without one they mean nothing.
    if (a.normal.present()) {
        EXPECT_NEAR(a.normalScale, b.normalScale, 1e-6f) << a.name;
    }
    if (a.occlusion.present()) {
        EXPECT_NEAR(a.occlusionStrength, b.occlusionStrength, 1e-6f) << a.name;
    }
    EXPECT_EQ(a.alphaMode, b.alphaMode) << a.name;
    EXPECT_NEAR(a.alphaCutoff, b.alphaCutoff, 1e-6f) << a.name;
    EXPECT_EQ(a.doubleSided, b.doubleSided) << a.name;
    const auto mapsA = mapsOf(a), mapsB = mapsOf(b);
    for (int m = 0; m < kMapCount; ++m) {
        expectSameSlot(*mapsA[size_t(m)].slot, *mapsB[size_t(m)].slot, modelA, modelB,
                       a.name + ": " + mapsA[size_t(m)].name);
    }
}

// What a draw shows: its triangles in world space with their attributes, and its material.
void expectSameModel(const Model& a, const Model& b) {
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i) {
        expectSameMaterial(a.materials[i], b.materials[i], a, b);
    }
    ASSERT_EQ(a.draws.size(), b.draws.size());
    for (size_t i = 0; i < a.draws.size(); ++i) {
        const DrawItem& da = a.draws[i];
        const DrawItem& db = b.draws[i];
        const std::string what = "draw " + std::to_string(i) + " (" + da.node + ")";
        EXPECT_EQ(da.node, db.node) << what;
        EXPECT_EQ(da.material, db.material) << what;
        EXPECT_EQ(da.mirrored, db.mirrored) << what;
        expectNear(da.transform, db.transform, what);
        const Mesh& ma = a.primitives[size_t(da.primitive)];
        const Mesh& mb = b.primitives[size_t(db.primitive)];
        EXPECT_EQ(ma.positions, mb.positions) << what;
        EXPECT_EQ(ma.indices, mb.indices) << what;
        EXPECT_EQ(ma.uv0, mb.uv0) << what;
        EXPECT_EQ(ma.uv1, mb.uv1) << what;
        EXPECT_EQ(ma.colors, mb.colors) << what;
        ASSERT_EQ(ma.normals.size(), mb.normals.size()) << what;
        for (size_t v = 0; v < ma.normals.size(); ++v) {
            EXPECT_LT(glm::length(ma.normals[v] - mb.normals[v]), 1e-6f) << what << " vertex " << v;
        }
        ASSERT_EQ(ma.tangents.size(), mb.tangents.size()) << what;
        for (size_t v = 0; v < ma.tangents.size(); ++v) {
            if (ma.tangents[v].w != 0.0f) {   // a vertex without one gets any tangent: see validTangents
                EXPECT_LT(glm::length(ma.tangents[v] - mb.tangents[v]), 1e-6f) << what << " vertex " << v;
            }
        }
    }
}

class GltfModelExport : public test::ScratchTest {
protected:
    void SetUp() override {
        test::ScratchTest::SetUp();
        if (!fs::is_directory(kModels)) {
            GTEST_SKIP() << "needs Debian's assimp-testmodels (" << kModels.string() << ")";
        }
    }
    test::CliRun run(const std::string& arguments) const { return test::runPatina(arguments, dir_); }

    // A scene file showing `model` in the default scene, with `edits`.
    fs::path sceneOf(const fs::path& model, const std::string& name,
                     const std::vector<ModelMaterialEdit>& edits = {}) const {
        Scene scene = defaultScene();
        scene.meshFile = model.string();
        scene.modelMaterials = edits;
        write(name, prettyJson(sceneToJson(scene)));
        return path(name);
    }
    LdrImage render(const fs::path& scene, const std::string& out) const {
        const test::CliRun result =
            run("render --scene '" + scene.string() + "' --width 96 --height 96 --out " + path(out).string());
        EXPECT_EQ(result.exitCode, 0) << result.stderrText;
        return decodePng(readFileBytes(path(out)));
    }
};

// Real models from other writers: every map, sampler and transform kind, a hierarchy of
// matrices, JPEG images, images from a GLB and a data: URI, texCoord 1.
const char* const kRealModels[] = {
    "BoxTextured-glTF-Binary/BoxTextured.glb",
    "BoxTextured-glTF-Embedded/BoxTextured.gltf",
    "BoxTexcoords-glTF/boxTexcoords.gltf",
    "textureTransform/TextureTransformTest.gltf",
    "ClearCoat-glTF/ClearCoatTest.gltf",
    "2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
};

TEST_F(GltfModelExport, RealModelsComeBackWholeAndTheValidatorFindsNothing) {
    for (const char* name : kRealModels) {
        SCOPED_TRACE(name);
        const Model model = importGltfModel(kModels / name);
        for (const char* out : {"out.glb", "out.gltf"}) {
            SCOPED_TRACE(out);
            exportGltfModel(path(out), model);
            test::expectValidGltf(path(out), dir_);
            expectSameModel(model, importGltfModel(path(out)));
        }
    }
}

// KHR_materials_sheen (tests/data/sheen/velvet.gltf, written by hand: Blender 3.4 exports no
// sheen): its factors and both maps, one through KHR_texture_transform on UV set 1, come back
// from .glb and .gltf, and the validator finds nothing in either.
TEST_F(GltfModelExport, TheSheenAndItsMapsComeBackValidatorClean) {
    const Model model = importGltfModel(fs::path(PATINA_SOURCE_DIR) / "tests/data/sheen/velvet.gltf");
    ASSERT_EQ(model.materials.size(), 2u);
    const ModelMaterial& velvet = model.materials[0];
    EXPECT_EQ(velvet.factors.sheenColor, glm::vec3(0.9f, 0.4f, 0.6f));
    EXPECT_EQ(velvet.factors.sheenRoughness, 0.5f);
    ASSERT_TRUE(velvet.sheenColor.present());
    ASSERT_TRUE(velvet.sheenRoughness.present());
    EXPECT_EQ(velvet.sheenRoughness.texCoord, 1);
    EXPECT_EQ(velvet.sheenRoughness.transform.scale, glm::vec2(2.0f));
    EXPECT_FALSE(model.materials[1].sheenColor.present());
    EXPECT_EQ(model.materials[1].factors.sheenColor, glm::vec3(1.0f));
    EXPECT_TRUE(model.notes.empty()) << model.notes.front();
    for (const char* out : {"velvet.glb", "velvet.gltf"}) {
        SCOPED_TRACE(out);
        exportGltfModel(path(out), model);
        test::expectValidGltf(path(out), dir_);
        expectSameModel(model, importGltfModel(path(out)));
    }
    // A material without a sheen writes no KHR_materials_sheen.
    Model bare = model;
    for (ModelMaterial& material : bare.materials) {
        material.factors.sheenColor = glm::vec3(0.0f);
        material.factors.sheenRoughness = 0.0f;
        material.sheenColor = {};
        material.sheenRoughness = {};
    }
    exportGltfModel(path("bare.gltf"), bare);
    const std::vector<uint8_t> bytes = readFileBytes(path("bare.gltf"));
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()).find("KHR_materials_sheen"), std::string::npos);
}

// COLOR_0 comes back as it was read (normalized bytes as the floats they stand for), from .glb
// and .gltf, validator-clean; a primitive without colours writes none.
TEST_F(GltfModelExport, VertexColoursComeBackValidatorClean) {
    test::GltfBuilder cube = test::cubeModel();
    std::vector<uint8_t> rgba;
    for (int v = 0; v < 24; ++v) {
        rgba.insert(rgba.end(), {uint8_t(v * 10), uint8_t(255 - v * 10), 128, uint8_t(255 - v)});
    }
    const int colours = cube.data(rgba, test::kUnsignedByte, "VEC4", 4);
    cube.json["accessors"][size_t(colours)]["normalized"] = true;
    cube.json["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = colours;
    cube.writeGlb(path("coloured.glb"));
    const Model model = importGltfModel(path("coloured.glb"));
    ASSERT_EQ(model.primitives.at(0).colors.size(), 24u);
    EXPECT_EQ(model.primitives[0].colors[3], glm::vec4(30, 225, 128, 252) / 255.0f);
    for (const char* out : {"again.glb", "again.gltf"}) {
        SCOPED_TRACE(out);
        exportGltfModel(path(out), model);
        test::expectValidGltf(path(out), dir_);
        expectSameModel(model, importGltfModel(path(out)));
    }
    test::cubeModel().writeGlb(path("plain.glb"));
    exportGltfModel(path("plain.gltf"), importGltfModel(path("plain.glb")));
    const std::vector<uint8_t> bytes = readFileBytes(path("plain.gltf"));
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()).find("COLOR_0"), std::string::npos);
}

// KHR_materials_transmission and KHR_materials_volume (tests/data/transmission/spheres.gltf, made
// by its script): the factors, the volume's colour and distance and both maps come back from
// .glb and .gltf, the validator finds nothing in either, and a material that passes no light
// writes neither extension.
TEST_F(GltfModelExport, TheTransmissionAndVolumeComeBackValidatorClean) {
    const Model model = importGltfModel(fs::path(PATINA_SOURCE_DIR) / "tests/data/transmission/spheres.gltf");
    ASSERT_EQ(model.materials.size(), 2u);
    const ModelMaterial& clear = model.materials[0];
    const ModelMaterial& amber = model.materials[1];
    EXPECT_EQ(clear.factors.transmission, 1.0f);
    EXPECT_TRUE(clear.transmissionMap.present());
    EXPECT_EQ(clear.factors.thickness, 0.0f);
    EXPECT_EQ(clear.factors.attenuationDistance, 0.0f);   // the extension's infinity
    EXPECT_EQ(amber.factors.thickness, 1.5f);
    EXPECT_EQ(amber.factors.attenuationColor, glm::vec3(1.0f, 0.6f, 0.2f));
    EXPECT_EQ(amber.factors.attenuationDistance, 0.5f);
    EXPECT_TRUE(amber.thicknessMap.present());
    EXPECT_FALSE(amber.transmissionMap.present());
    EXPECT_TRUE(model.notes.empty()) << model.notes.front();
    for (const char* out : {"spheres.glb", "spheres.gltf"}) {
        SCOPED_TRACE(out);
        exportGltfModel(path(out), model);
        test::expectValidGltf(path(out), dir_);
        expectSameModel(model, importGltfModel(path(out)));
    }
    Model opaque = model;
    for (ModelMaterial& material : opaque.materials) {
        material.factors.transmission = 0.0f;
    }
    exportGltfModel(path("opaque.gltf"), opaque);
    const std::vector<uint8_t> bytes = readFileBytes(path("opaque.gltf"));
    const std::string text(bytes.begin(), bytes.end());
    EXPECT_EQ(text.find("KHR_materials_transmission"), std::string::npos);
    EXPECT_EQ(text.find("KHR_materials_volume"), std::string::npos);
}

// KHR_materials_anisotropy (tests/data/anisotropy/spheres.gltf, made by its script): strength,
// rotation and map come back from .glb and .gltf, validator-clean; the sphere without TANGENT
// gets the importer's (its direction turns from them); no note says the extension is not drawn;
// a material without a strength writes no extension, and a rotation that is no angle is refused
// by name.
TEST_F(GltfModelExport, TheAnisotropyComesBackValidatorClean) {
    const fs::path source = fs::path(PATINA_SOURCE_DIR) / "tests/data/anisotropy/spheres.gltf";
    const Model model = importGltfModel(source);
    ASSERT_EQ(model.materials.size(), 2u);
    const ModelMaterial& brushed = model.materials[0];
    const ModelMaterial& satin = model.materials[1];
    EXPECT_EQ(brushed.factors.anisotropyStrength, 0.8f);
    EXPECT_EQ(brushed.factors.anisotropyRotation, 0.5f);
    EXPECT_TRUE(brushed.anisotropyMap.present());
    EXPECT_EQ(satin.factors.anisotropyStrength, 0.6f);
    EXPECT_EQ(satin.factors.anisotropyRotation, 0.0f);
    EXPECT_FALSE(satin.anisotropyMap.present());
    for (const Mesh& primitive : model.primitives) {
        EXPECT_EQ(primitive.tangents.size(), primitive.positions.size()) << "tangents, given or made";
    }
    EXPECT_TRUE(model.notes.empty()) << model.notes.front();
    for (const char* out : {"anisotropy.glb", "anisotropy.gltf"}) {
        SCOPED_TRACE(out);
        exportGltfModel(path(out), model);
        test::expectValidGltf(path(out), dir_);
        expectSameModel(model, importGltfModel(path(out)));
    }
    Model round = model;
    for (ModelMaterial& material : round.materials) {
        material.factors.anisotropyStrength = 0.0f;
    }
    exportGltfModel(path("round.gltf"), round);
    const std::vector<uint8_t> bytes = readFileBytes(path("round.gltf"));
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()).find("KHR_materials_anisotropy"), std::string::npos);

    const std::vector<uint8_t> original = readFileBytes(source);
    std::string broken(original.begin(), original.end());
    const std::string from = "\"anisotropyRotation\": 0.5";
    const size_t at = broken.find(from);
    ASSERT_NE(at, std::string::npos);
    broken.replace(at, from.size(), "\"anisotropyRotation\": 1e30");
    std::ofstream(path("broken.gltf")) << broken;
    try {
        importGltfModel(path("broken.gltf"));
        ADD_FAILURE() << "accepted a rotation of 1e30";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("/materials/0/extensions/KHR_materials_anisotropy/anisotropyRotation"),
                  std::string::npos)
            << error.what();
    }
}

// A volume's distance must be above 0 where the file gives one, and its thickness not below 0:
// refused naming the value's place.
TEST_F(GltfModelExport, AVolumesBadDistanceOrThicknessIsRefusedByName) {
    std::vector<uint8_t> bytes = readFileBytes(fs::path(PATINA_SOURCE_DIR) / "tests/data/transmission/spheres.gltf");
    const std::string text(bytes.begin(), bytes.end());
    for (const auto& [from, to, named] :
         {std::tuple<std::string, std::string, std::string>{"\"attenuationDistance\": 0.5", "\"attenuationDistance\": 0",
                                                            "/materials/1/extensions/KHR_materials_volume/attenuationDistance"},
          {"\"thicknessFactor\": 1.5", "\"thicknessFactor\": -1",
           "/materials/1/extensions/KHR_materials_volume/thicknessFactor"}}) {
        std::string broken = text;
        const size_t at = broken.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        broken.replace(at, from.size(), to);
        std::ofstream(path("broken.gltf")) << broken;
        try {
            importGltfModel(path("broken.gltf"));
            ADD_FAILURE() << "accepted " << to;
        } catch (const InputError& error) {
            EXPECT_NE(std::string(error.what()).find(named), std::string::npos) << error.what();
        }
    }
}

// The fuzzer's textured seed has what the sample models lack: MASK and BLEND, emission over 1,
// a texCoord 1 from a transform's override, a mirrored child node, a nearest mirrored-repeat
// sampler, and maps left out (a missing file, a Basis image), which stay out.
TEST_F(GltfModelExport, EveryMaterialFieldAndAMirroredChildComeBack) {
    for (const char* seed : {"gltf/textured.gltf", "glb/textured.glb"}) {
        SCOPED_TRACE(seed);
        const Model model = importGltfModel(fs::path(PATINA_SOURCE_DIR) / "tests/fuzz/corpus" / seed);
        ASSERT_EQ(model.materials.size(), 2u);
        EXPECT_EQ(model.materials[0].alphaMode, AlphaMode::Mask);
        EXPECT_EQ(model.materials[0].emissiveFactor.r, 3.0f);
        EXPECT_EQ(model.materials[0].baseColor.texCoord, 1);
        EXPECT_FALSE(model.materials[0].occlusion.present());
        ASSERT_EQ(model.draws.size(), 4u);   // two primitives, in a node and its mirrored child
        EXPECT_TRUE(model.draws[3].mirrored);
        exportGltfModel(path("seed.glb"), model);
        test::expectValidGltf(path("seed.glb"), dir_);
        expectSameModel(model, importGltfModel(path("seed.glb")));
    }
}

// KHR_materials_specular's tint, weight and two maps (on the seed's own image) come back as they
// were, validator-clean; a tint above white (a gem's F0) too, as specular 1 and the same tint; and
// KHR_materials_iridescence's film with its two maps.
TEST_F(GltfModelExport, TheSpecularTheFilmAndTheirMapsComeBackValidatorClean) {
    Model model = importGltfModel(fs::path(PATINA_SOURCE_DIR) / "tests/fuzz/corpus/gltf/textured.gltf");
    ASSERT_TRUE(model.materials[0].baseColor.present());
    ModelMaterial& tinted = model.materials[0];
    tinted.factors.specularTint = {1.0f, 0.5f, 0.25f};
    tinted.factors.specularWeight = 0.75f;
    tinted.specularColor = tinted.baseColor;
    tinted.specularColor.texCoord = 0;
    tinted.specular = tinted.baseColor;
    ModelMaterial& gem = model.materials[1];
    gem.factors.specular = 1.0f;
    gem.factors.specularTint = {2.125f, 2.0f, 1.5f};
    gem.factors.iridescence = 0.625f;
    gem.factors.iridescenceIor = 1.75f;
    gem.factors.iridescenceThicknessMinimum = 250.0f;
    gem.factors.iridescenceThicknessMaximum = 820.0f;
    gem.iridescenceMap = tinted.specularColor;   // UV set 0: the second part's mesh has no other
    gem.iridescenceThickness = tinted.specularColor;
    exportGltfModel(path("specular.glb"), model);
    test::expectValidGltf(path("specular.glb"), dir_);
    const Model back = importGltfModel(path("specular.glb"));
    expectSameModel(model, back);
    // Nothing lost on the way: the one note is the file's BLEND part's, whose map's alpha varies.
    ASSERT_EQ(back.notes.size(), 1u) << back.notes.front();
    EXPECT_NE(back.notes[0].find("\"blended\" is BLEND with a varying alpha"), std::string::npos) << back.notes[0];
}

TEST_F(GltfModelExport, AGltfHasItsImagesBesideItAndItsBufferWhereAsked) {
    const Model model = importGltfModel(kModels / "BoxTextured-glTF-Binary/BoxTextured.glb");
    exportGltfModel(path("box.gltf"), model, GltfBuffer::BinFile);
    EXPECT_TRUE(fs::is_regular_file(path("box.bin")));
    EXPECT_TRUE(fs::is_regular_file(path("box_0.png")));
    EXPECT_EQ(decodePng(readFileBytes(path("box_0.png"))).rgba, model.images[0].rgba);
    test::expectValidGltf(path("box.gltf"), dir_);
    const std::vector<OutputFile> glb = encodeGltfModel(path("box.glb"), model);
    ASSERT_EQ(glb.size(), 1u);   // the images inside it
    EXPECT_THROW(encodeGltfModel(path("box.obj"), model), InputError);
    EXPECT_THROW(encodeGltfModel(path("empty.glb"), Model{}), InputError);
}

// Every file told: a BLEND material whose alpha varies over the surface (its base colour map's
// alpha here) is drawn by its factor's alpha alone, and the model's notes say so, naming it; an
// opaque map, or the same map under MASK, says nothing.
TEST_F(GltfModelExport, ABlendedMaterialWhoseAlphaVariesIsToldItBlendsByItsFactor) {
    auto notesWith = [&](uint8_t alpha, AlphaMode mode) {
        Model model = test::twoBalls();
        model.images.push_back({"leaf", 2, 1, {200, 200, 200, 255, 200, 200, 200, alpha}});
        model.materials[0].baseColor.image = 0;
        model.materials[0].alphaMode = mode;
        model.materials[0].baseAlpha = 0.8f;
        exportGltfModel(path("blend.glb"), model);
        std::string notes;
        for (const std::string& note : importGltfModel(path("blend.glb")).notes) {
            notes += note + "\n";
        }
        return notes;
    };
    const std::string told = notesWith(40, AlphaMode::Blend);
    EXPECT_NE(told.find("material \"left\" is BLEND with a varying alpha: Patina blends it by its factor's alpha "
                        "(0.8) alone"),
              std::string::npos)
        << told;
    EXPECT_EQ(told.find("\"right\""), std::string::npos) << told;
    EXPECT_EQ(notesWith(255, AlphaMode::Blend).find("BLEND"), std::string::npos);
    EXPECT_EQ(notesWith(40, AlphaMode::Mask).find("BLEND"), std::string::npos);
}

// A map replaced in the editor by a picture the file already has (the model then holds the same
// pixels twice) is written once: one PNG, both maps reading it.
TEST_F(GltfModelExport, ThePixelsOfTwoModelImagesAlikeAreWrittenOnce) {
    Model model = importGltfModel(kModels / "BoxTextured-glTF-Binary/BoxTextured.glb");
    ASSERT_EQ(model.images.size(), 1u);
    model.images.push_back(model.images[0]);
    model.images.back().name = "the same picture, replaced";
    model.materials[0].emissive = model.materials[0].baseColor;
    model.materials[0].emissive.image = 1;
    model.materials[0].emissiveFactor = glm::vec3(0.2f);
    exportGltfModel(path("twice.gltf"), model, GltfBuffer::BinFile);
    EXPECT_TRUE(fs::is_regular_file(path("twice_0.png")));
    EXPECT_FALSE(fs::exists(path("twice_1.png")));
    test::expectValidGltf(path("twice.gltf"), dir_);
    const Model back = importGltfModel(path("twice.gltf"));
    ASSERT_EQ(back.images.size(), 1u);
    EXPECT_EQ(back.materials[0].emissive.image, back.materials[0].baseColor.image);
    EXPECT_EQ(back.images[0].rgba, model.images[0].rgba);
}

// A node matrix must be a translation, rotation and scale (glTF 5.25): a shear is baked into
// the vertices, which then stand where they stood, lit the same way.
TEST_F(GltfModelExport, AShearIsBakedIntoTheVerticesAndAMirrorKeepsItsFrontFaces) {
    Model model = importGltfModel(kModels / "BoxTextured-glTF-Binary/BoxTextured.glb");
    glm::mat4 shear(1.0f);
    shear[1][0] = 0.5f;   // x += 0.5 y
    model.draws = {model.draws[0], model.draws[0]};
    model.draws[0].transform = shear;
    model.draws[1].transform = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)) * shear;
    model.draws[1].mirrored = true;
    exportGltfModel(path("sheared.glb"), model);
    test::expectValidGltf(path("sheared.glb"), dir_);
    const Model back = importGltfModel(path("sheared.glb"));
    ASSERT_EQ(back.draws.size(), 2u);
    for (size_t d = 0; d < 2; ++d) {
        const DrawItem& before = model.draws[d];
        const DrawItem& after = back.draws[d];
        EXPECT_EQ(after.transform, glm::mat4(1.0f));
        EXPECT_FALSE(after.mirrored);   // the triangles are wound back instead
        const Mesh& source = model.primitives[size_t(before.primitive)];
        const Mesh& baked = back.primitives[size_t(after.primitive)];
        ASSERT_EQ(baked.indices.size(), source.indices.size());
        for (size_t t = 0; t < source.indices.size(); t += 3) {
            // The same corners, and each face's front where it was: its world normal (the
            // renderer's normal transform) on the side its winding now faces.
            const uint32_t* s = &source.indices[t];
            const uint32_t* b = &baked.indices[t];
            const glm::vec3 p0 = baked.positions[b[0]], p1 = baked.positions[b[1]], p2 = baked.positions[b[2]];
            const glm::vec3 facing = glm::cross(p1 - p0, p2 - p0);
            const glm::vec3 normal = normalTransform(before.transform) * source.normals[s[0]];
            EXPECT_GT(glm::dot(facing, normal), 0.0f) << "draw " << d << " triangle " << t / 3;
            EXPECT_LT(glm::length(glm::vec3(before.transform * glm::vec4(source.positions[s[0]], 1.0f)) - p0), 1e-5f);
            EXPECT_EQ(baked.uv0[b[0]], source.uv0[s[0]]);
        }
    }
}

// The command exports the scene's model with the scene's tuning, and --material puts a
// material on every part or on --part's; importing the export renders the same image.
TEST_F(GltfModelExport, TheCommandExportsTheTunedModelAndItRendersTheSame) {
    const fs::path box = kModels / "BoxTextured-glTF-Binary/BoxTextured.glb";
    const Model model = importGltfModel(box);
    ModelMaterialEdit edit{0, Material{}, Json::object()};
    edit.material.name = model.materials[0].name;
    edit.material.baseColor = {0.25f, 0.5f, 1.0f};
    edit.material.roughness = 0.125f;
    edit.material.metallic = 0.75f;
    edit.material.model = BrdfModelId::Gltf;   // the part's own, as the editor tunes it
    const fs::path tuned = sceneOf(box, "tuned.json", {edit});
    const test::CliRun exported = run("export --scene " + tuned.string() + " --out " + path("tuned.glb").string());
    ASSERT_EQ(exported.exitCode, 0) << exported.stderrText;
    EXPECT_EQ(exported.stderrText.find("another model"), std::string::npos) << exported.stderrText;
    test::expectValidGltf(path("tuned.glb"), dir_);
    const Model back = importGltfModel(path("tuned.glb"));
    EXPECT_EQ(back.materials[0].factors.baseColor, edit.material.baseColor);
    EXPECT_EQ(back.materials[0].factors.roughness, 0.125f);
    EXPECT_EQ(back.materials[0].factors.metallic, 0.75f);
    EXPECT_TRUE(back.materials[0].baseColor.present());   // the tuned factors still multiply the map

    // The export, shown in the same scene without the tuning, looks as the tuned original.
    const LdrImage original = render(tuned, "original.png");
    const LdrImage again = render(sceneOf(path("tuned.glb"), "again.json"), "again.png");
    ASSERT_EQ(original.rgba.size(), again.rgba.size());
    int largest = 0;
    for (size_t i = 0; i < original.rgba.size(); ++i) {
        largest = std::max(largest, std::abs(int(original.rgba[i]) - int(again.rgba[i])));
    }
    EXPECT_LE(largest, 1);
    const LdrImage untuned = render(sceneOf(box, "untuned.json"), "untuned.png");
    EXPECT_NE(untuned.rgba, original.rgba);   // the tuning shows, so the check above can fail
    // A part shaded here with another model than glTF's: its factors go as they are, and the
    // export says that a viewer will show them with glTF's BRDF.
    edit.material.model = BrdfModelId::Epic;
    const test::CliRun epic =
        run("export --scene " + sceneOf(box, "epic.json", {edit}).string() + " --out " + path("epic.glb").string());
    ASSERT_EQ(epic.exitCode, 0) << epic.stderrText;
    EXPECT_NE(epic.stderrText.find("\"" + edit.material.name + "\" (epic)"), std::string::npos) << epic.stderrText;

    write("m.json", prettyJson(materialToJson(edit.material)));
    const std::string material = " --material " + path("m.json").string();
    ASSERT_EQ(run("export --mesh " + box.string() + material + " --out " + path("every.gltf").string()).exitCode, 0);
    EXPECT_EQ(importGltfModel(path("every.gltf")).materials[0].factors.roughness, 0.125f);
    EXPECT_EQ(run("export --mesh " + box.string() + material + " --part " + model.materials[0].name + " --out " +
                  path("part.glb").string())
                  .exitCode,
              0);
    const test::CliRun wrongPart =
        run("export --mesh " + box.string() + material + " --part nothing --out " + path("x.glb").string());
    EXPECT_EQ(wrongPart.exitCode, 3);
    EXPECT_NE(wrongPart.stderrText.find(model.materials[0].name), std::string::npos) << wrongPart.stderrText;
    // --part without --material is a usage mistake (exit 2), told before anything is read.
    const test::CliRun noMaterial = run("export --part " + model.materials[0].name + " --out " + path("y.glb").string());
    EXPECT_EQ(noMaterial.exitCode, 2);
    EXPECT_NE(noMaterial.stderrText.find("--part requires --material"), std::string::npos) << noMaterial.stderrText;
    EXPECT_FALSE(fs::exists(path("x.glb")));
    EXPECT_FALSE(fs::exists(path("y.glb")));
}

// A map the scene leaves out is left out on the GPU as in the export: the box without its logo
// renders as the exported box that has none.
TEST_F(GltfModelExport, AMapLeftOutRendersAsTheExportWithoutIt) {
    const fs::path box = kModels / "BoxTextured-glTF-Binary/BoxTextured.glb";
    const Model model = importGltfModel(box);
    ModelMaterialEdit edit{0, Material{}, Json::object(), {"baseColorTexture"}};
    static_cast<MaterialParameters&>(edit.material) = model.materials[0].factors;
    edit.material.name = model.materials[0].name;
    const fs::path plain = sceneOf(box, "plain.json", {edit});
    ASSERT_EQ(run("export --scene " + plain.string() + " --out " + path("plain.glb").string()).exitCode, 0);
    EXPECT_FALSE(importGltfModel(path("plain.glb")).materials[0].baseColor.present());
    const LdrImage left = render(plain, "left.png");
    const LdrImage exported = render(sceneOf(path("plain.glb"), "exported.json"), "exported.png");
    int largest = 0;
    for (size_t i = 0; i < left.rgba.size(); ++i) {
        largest = std::max(largest, std::abs(int(left.rgba[i]) - int(exported.rgba[i])));
    }
    EXPECT_LE(largest, 1);
    EXPECT_NE(render(sceneOf(box, "logo.json"), "logo.png").rgba, left.rgba);
}

}  // namespace
}  // namespace patina
