// Whole glTF models (engine/gltf/model_import.h) from real files: the glTF 2.0 test models of
// Debian's assimp-testmodels (scripts/setup.sh installs it), written by other tools. Skipped,
// naming the package, where it is not installed.
#include <algorithm>
#include <map>
#include <optional>

#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>

#include "gltf/glb.h"
#include "gltf/model_import.h"
#include "gltf_builder.h"
#include "image/image.h"
#include "files/file_bytes.h"
#include "io/json_reader.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models/glTF2";

class GltfAssets : public ::testing::Test {
protected:
    void SetUp() override {
        if (!fs::is_directory(kModels)) {
            GTEST_SKIP() << "needs Debian's assimp-testmodels (" << kModels.string() << ")";
        }
    }
};

// The JSON of a .gltf, or of a .glb's JSON chunk.
Json documentOf(const fs::path& file) {
    const std::vector<uint8_t> bytes = readFileBytes(file);
    if (gltf::looksLikeGlb(bytes)) {
        return parseJsonText(std::string(gltf::splitGlb(bytes, file.string()).json), file.string());
    }
    return parseJsonText(std::string(bytes.begin(), bytes.end()), file.string());
}

// Everything but the images' names, which say where each image came from.
void expectSameModel(const Model& a, const Model& b, const std::string& what) {
    ASSERT_EQ(a.primitives.size(), b.primitives.size()) << what;
    for (size_t p = 0; p < a.primitives.size(); ++p) {
        EXPECT_EQ(a.primitives[p].positions, b.primitives[p].positions) << what;
        EXPECT_EQ(a.primitives[p].normals, b.primitives[p].normals) << what;
        EXPECT_EQ(a.primitives[p].uv0, b.primitives[p].uv0) << what;
        EXPECT_EQ(a.primitives[p].indices, b.primitives[p].indices) << what;
    }
    EXPECT_EQ(a.draws, b.draws) << what;
    ASSERT_EQ(a.images.size(), b.images.size()) << what;
    for (size_t i = 0; i < a.images.size(); ++i) {
        EXPECT_EQ(a.images[i].rgba, b.images[i].rgba) << what;
    }
    EXPECT_EQ(a.notes, b.notes) << what;
}

// assimp's Cameras.gltf: a perspective camera (yfov 0.7) and an orthographic one, both at
// (0.5, 0.5, 3) looking down -Z at a square.
TEST_F(GltfAssets, CamerasGltfListsItsTwoCameras) {
    const Model model = importGltfModel(kModels / "cameras" / "Cameras.gltf");
    ASSERT_EQ(model.cameras.size(), 2u);
    for (const ModelCamera& camera : model.cameras) {
        EXPECT_EQ(camera.position, glm::vec3(0.5f, 0.5f, 3.0f));
        EXPECT_EQ(camera.forward, glm::vec3(0.0f, 0.0f, -1.0f));
        EXPECT_EQ(camera.up, glm::vec3(0.0f, 1.0f, 0.0f));
    }
    EXPECT_EQ(model.cameras[0].name, "camera 0");
    EXPECT_TRUE(model.cameras[0].perspective);
    EXPECT_FLOAT_EQ(model.cameras[0].yfov, 0.7f);
    EXPECT_EQ(model.cameras[1].index, 1);
    EXPECT_FALSE(model.cameras[1].perspective);
}

TEST_F(GltfAssets, BoxTexturedIsTheSameModelFromGltfGlbAndEmbedded) {
    const fs::path folder = kModels / "BoxTextured-glTF";
    const Model gltf = importGltfModel(folder / "BoxTextured.gltf");
    ASSERT_EQ(gltf.draws.size(), 1u);
    // The root's matrix turns +y to -z (COLLADA2GLTF's z-up fix); the child has none.
    const std::vector<float> root{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1};
    EXPECT_EQ(gltf.draws[0].transform, glm::make_mat4(root.data()));
    EXPECT_EQ(gltf.draws[0].node, "node 1");
    ASSERT_EQ(gltf.materials.size(), 1u);
    const ModelMaterial& material = gltf.materials[0];
    EXPECT_EQ(material.name, "Texture");
    EXPECT_EQ(material.factors.metallic, 0.0f);
    ASSERT_TRUE(material.baseColor.present());
    EXPECT_EQ(material.baseColor.texCoord, 0);
    // Its sampler: wrapS 33648, wrapT 33071, magFilter 9729, minFilter 9986.
    EXPECT_EQ(material.baseColor.sampler,
              (TextureSampler{TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge, false, true, true}));
    ASSERT_EQ(gltf.images.size(), 1u);
    EXPECT_EQ(gltf.images[0].name, "CesiumLogoFlat.png");
    // The pixels as the project's own PNG reader gives them: rows top first, RGBA.
    const LdrImage png = decodePng(readFileBytes(folder / "CesiumLogoFlat.png"));
    EXPECT_EQ(gltf.images[0].width, png.width);
    EXPECT_EQ(gltf.images[0].height, png.height);
    EXPECT_EQ(gltf.images[0].rgba, png.rgba);
    EXPECT_EQ(gltf.primitives[0].uv0.size(), gltf.primitives[0].positions.size());

    const Model glb = importGltfModel(kModels / "BoxTextured-glTF-Binary/BoxTextured.glb");
    const Model embedded = importGltfModel(kModels / "BoxTextured-glTF-Embedded/BoxTextured.gltf");
    expectSameModel(glb, gltf, "glb");
    expectSameModel(embedded, gltf, "embedded");
    // These two give the sampler as wrapS = wrapT = 10497, minFilter 9986.
    const TextureSampler repeat{TextureWrap::Repeat, TextureWrap::Repeat, false, true, true};
    for (const Model* other : {&glb, &embedded}) {
        ASSERT_EQ(other->materials.size(), 1u);
        ModelMaterial expected = material;
        expected.baseColor.sampler = repeat;
        EXPECT_EQ(other->materials[0], expected);
    }
}

TEST_F(GltfAssets, TextureTransformTestReadsEachTransform) {
    const Model model = importGltfModel(kModels / "textureTransform/TextureTransformTest.gltf");
    std::map<std::string, TextureSlot> slots;
    for (const ModelMaterial& material : model.materials) {
        slots[material.name] = material.baseColor;
    }
    EXPECT_EQ(slots.at("Offset U").transform, (TextureTransform{{0.5f, 0.0f}, {1.0f, 1.0f}, 0.0f}));
    EXPECT_EQ(slots.at("Offset V").transform, (TextureTransform{{0.0f, 0.5f}, {1.0f, 1.0f}, 0.0f}));
    EXPECT_EQ(slots.at("Rotation").transform, (TextureTransform{{0.0f, 0.0f}, {1.0f, 1.0f}, 0.39269908169872414f}));
    EXPECT_EQ(slots.at("Scale").transform, (TextureTransform{{0.0f, 0.0f}, {1.5f, 1.5f}, 0.0f}));
    EXPECT_EQ(slots.at("All").transform, (TextureTransform{{-0.2f, -0.1f}, {1.5f, 1.5f}, 0.3f}));
    EXPECT_EQ(slots.at("Correct").transform, TextureTransform());
    // Sampler 0: clamped both ways, linear without mipmaps.
    EXPECT_EQ(slots.at("All").sampler, (TextureSampler{TextureWrap::ClampToEdge, TextureWrap::ClampToEdge, false,
                                                       false, false}));
    EXPECT_EQ(slots.at("Correct").sampler, TextureSampler());   // texture 2 has none
    for (const auto& [name, slot] : slots) {
        EXPECT_TRUE(slot.present()) << name;
    }
    EXPECT_TRUE(model.notes.empty());
    // "Rotation - Correct" is a child of "Rotation": translations add, its scale stays.
    for (const DrawItem& draw : model.draws) {
        if (draw.node == "Rotation - Correct") {
            EXPECT_NEAR(draw.transform[3].x, -1.1f - 0.07904822439840126f, 1e-6f);
            EXPECT_NEAR(draw.transform[3].y, -0.55f - 0.5162674857624154f, 1e-6f);
            EXPECT_NEAR(draw.transform[0].x, 0.15f, 1e-7f);
        }
    }
}

TEST_F(GltfAssets, BoxTexcoordsReadsTheSecondUvSet) {
    const Model model = importGltfModel(kModels / "BoxTexcoords-glTF/boxTexcoords.gltf");
    ASSERT_EQ(model.primitives.size(), 1u);
    const Mesh& box = model.primitives[0];
    EXPECT_EQ(box.uv0.size(), box.positions.size());
    EXPECT_EQ(box.uv1.size(), box.positions.size());
    EXPECT_NE(box.uv0, box.uv1);
    ASSERT_EQ(model.materials.size(), 1u);
    EXPECT_EQ(model.materials[0].baseColor.texCoord, 0);
    EXPECT_EQ(model.materials[0].metallicRoughness.texCoord, 1);
    EXPECT_EQ(model.materials[0].baseColor.image, model.materials[0].metallicRoughness.image);   // decoded once
    EXPECT_EQ(model.images.size(), 1u);
    EXPECT_TRUE(model.materials[0].doubleSided);
}

TEST_F(GltfAssets, ClearCoatReadsNormalMapsFromPngAndJpegAndMakesTheirTangents) {
    const Model model = importGltfModel(kModels / "ClearCoat-glTF/ClearCoatTest.gltf");
    std::map<std::string, const ModelMaterial*> materials;
    for (const ModelMaterial& material : model.materials) {
        materials[material.name] = &material;
    }
    const ModelMaterial& png = *materials.at("BaseNorm_Base");       // texture 3: RibsNormal.png
    const ModelMaterial& jpeg = *materials.at("CoatNorm_Coating");   // texture 5: PlasticWrap_normals.jpg
    for (const ModelMaterial* material : {&png, &jpeg}) {
        ASSERT_TRUE(material->normal.present()) << material->name;
        const ModelImage& image = model.images.at(size_t(material->normal.image));
        EXPECT_GT(image.width, 0);
        EXPECT_EQ(image.rgba.size(), size_t(image.width) * size_t(image.height) * 4);
        EXPECT_EQ(material->normalScale, 1.0f);
    }
    EXPECT_EQ(model.images.at(size_t(png.normal.image)).name, "RibsNormal.png");
    EXPECT_EQ(model.images.at(size_t(jpeg.normal.image)).name, "PlasticWrap_normals.jpg");
    EXPECT_EQ(materials.at("Partial_Coating")->alphaMode, AlphaMode::Blend);
    EXPECT_EQ(materials.at("LabelMaterial")->emissiveFactor, glm::vec3(1.0f));
    EXPECT_TRUE(materials.at("LabelMaterial")->emissive.present());
    // The file has no TANGENT: the normal-mapped primitives get MikkTSpace ones, the others none.
    for (const DrawItem& draw : model.draws) {
        const Mesh& primitive = model.primitives.at(size_t(draw.primitive));
        EXPECT_EQ(primitive.uv0.size(), primitive.positions.size());
        const bool normalMapped = draw.material >= 0 && (model.materials[size_t(draw.material)].normal.present() ||
                                                         model.materials[size_t(draw.material)].clearcoatNormal.present());
        ASSERT_EQ(primitive.tangents.size(), normalMapped ? primitive.positions.size() : 0u) << draw.node;
        for (size_t i = 0; i < primitive.tangents.size(); ++i) {
            const glm::vec4& tangent = primitive.tangents[i];
            EXPECT_NEAR(glm::length(glm::vec3(tangent)), 1.0f, 1e-4f);
            EXPECT_NEAR(glm::dot(glm::vec3(tangent), primitive.normals[i]), 0.0f, 1e-4f);
            EXPECT_EQ(std::abs(tangent.w), 1.0f);
        }
    }
    // The coat is drawn (KHR_materials_clearcoat), so no note of it; the one note is the partial
    // coating's BLEND layer, whose map's alpha Patina does not blend pixel by pixel.
    ASSERT_EQ(model.notes.size(), 1u) << model.notes.front();
    EXPECT_NE(model.notes[0].find("\"Partial_Coating\" is BLEND with a varying alpha"), std::string::npos)
        << model.notes[0];
}

// A node's own matrix: this file gives a matrix or nothing.
glm::dmat4 localMatrix(const Json& document, size_t node) {
    const Json matrix = document["nodes"][node].value("matrix", Json::array());
    return matrix.empty() ? glm::dmat4(1.0) : glm::make_mat4(matrix.get<std::vector<double>>().data());
}

// A node's world matrix the other way round from the import: up through its parents.
glm::mat4 worldByParents(const Json& document, size_t node) {
    std::map<size_t, size_t> parent;
    for (size_t n = 0; n < document["nodes"].size(); ++n) {
        for (const Json& child : document["nodes"][n].value("children", Json::array())) {
            parent[child.get<size_t>()] = n;
        }
    }
    glm::dmat4 world(1.0);
    for (auto n = std::optional<size_t>(node); n; n = parent.count(*n) ? std::optional(parent[*n]) : std::nullopt) {
        world = localMatrix(document, *n) * world;
    }
    return glm::mat4(world);
}

TEST_F(GltfAssets, TwoCylinderEngineHasEveryMaterialAndTheHierarchysTransforms) {
    const fs::path file = kModels / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    const Json document = documentOf(file);
    const Model model = importGltfModel(file);
    EXPECT_EQ(model.materials.size(), document["materials"].size());
    EXPECT_EQ(model.materials.size(), 34u);
    // Every node of the scene shows its mesh's primitives: the file's nodes all are in it.
    size_t expectedDraws = 0;
    for (const Json& node : document["nodes"]) {
        expectedDraws += node.contains("mesh") ? document["meshes"][node["mesh"].get<size_t>()]["primitives"].size() : 0;
    }
    EXPECT_EQ(model.draws.size(), expectedDraws);
    EXPECT_LT(model.primitives.size(), model.draws.size());   // meshes shown by several nodes
    size_t nested = 0;
    for (const DrawItem& draw : model.draws) {
        const size_t node = std::stoul(draw.node.substr(draw.node.find(' ') + 1));   // unnamed: "node N"
        const glm::mat4 expected = worldByParents(document, node);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) {
                ASSERT_NEAR(draw.transform[c][r], expected[c][r], 1e-3f) << draw.node;
            }
        }
        nested += draw.transform != glm::mat4(localMatrix(document, node));
    }
    EXPECT_GT(nested, 0u);   // some transforms come from parents too
}

// Files written by other tools say what they use when they open: ClearCoatTest's coat is drawn
// (no note of it; its partial coating's BLEND alpha is noted), the spec-gloss box's conversion is
// noted.
TEST_F(GltfAssets, ClearCoatTestIsDrawnAndTheSpecGlossBoxSaysItIsConverted) {
    const Model coat = importGltfModel(kModels / "ClearCoat-glTF/ClearCoatTest.gltf");
    ASSERT_EQ(coat.extensions.size(), 1u);
    EXPECT_EQ(coat.extensions[0].name, "KHR_materials_clearcoat");
    EXPECT_EQ(coat.extensions[0].support, ExtensionSupport::Drawn);
    for (const std::string& note : coat.notes) {   // the partial coating's BLEND alpha alone
        EXPECT_EQ(note.find("KHR_materials_clearcoat"), std::string::npos) << note;
        EXPECT_NE(note.find("is BLEND with a varying alpha"), std::string::npos) << note;
    }
    const Model box = importGltfModel(kModels / "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf");
    ASSERT_EQ(box.extensions.size(), 1u);
    EXPECT_EQ(box.extensions[0].name, "KHR_materials_pbrSpecularGlossiness");
    EXPECT_FALSE(box.notes.empty());
}

TEST_F(GltfAssets, BrokenFilesAreRefusedWithClearErrors) {
    const std::pair<std::string, std::string> cases[] = {
        {"RecursiveNodes/RecursiveNodes.gltf", "/nodes/0: is its own ancestor (a cycle in the node hierarchy)"},
        {"IndexOutOfRange/IndexOutOfRange.gltf", "/meshes/0/primitives/0/indices: element 0 is 255 but the primitive "
                                                 "has 24 vertices"},
        {"IndexOutOfRange/AllIndicesOutOfRange.gltf", "/meshes/0/primitives/0/indices: element 0 is 65535"},
        {"MissingBin/BoxTextured.gltf", "the buffer file 'BoxTextured0.bin' is not found in the model's folder"},
        {"wrongTypes/badArray.gltf", "/meshes/0/primitives: must be an array, not an object"},
        {"wrongTypes/badExtension.gltf", "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/"
                                         "KHR_texture_transform: must be an object, not a string"},
        {"wrongTypes/badNumber.gltf", "/materials/0/normalTexture/scale: must be a number, not a string"},
        {"wrongTypes/badObject.gltf", "/materials/0/pbrMetallicRoughness: must be an object, not an array"},
        {"wrongTypes/badString.gltf", "/scenes/0/name: must be a string, not 42"},
        {"wrongTypes/badUint.gltf", "/materials/0/pbrMetallicRoughness/baseColorTexture/index: texture -1 does not "
                                    "exist"},
    };
    for (const auto& [name, message] : cases) {
        const fs::path file = kModels / name;
        const std::string error = test::modelError(file);
        EXPECT_ERROR(error, file.string() + ": " );
        EXPECT_ERROR(error, message);
    }
}

}  // namespace
}  // namespace patina
