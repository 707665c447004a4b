// Whole glTF models (engine/gltf/model_import.h) built here with known values: the scene graph
// as draw items, shared primitives with UVs and tangents, materials with their maps, samplers
// and transforms, images decoded or left out with a note. Real files from Debian's
// assimp-testmodels are in test_gltf_assets.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <thread>

#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>

#include "gltf/export.h"
#include "gltf/images.h"
#include "gltf/model_import.h"
#include "gltf_builder.h"
#include "image/image.h"
#include "scratch_test.h"
#include "shading/cpu_shading.h"

namespace patina {
namespace {

using test::Cube;
using test::cubeModel;
using test::GltfBuilder;
using test::modelError;

// Every note, a line each: what a failed expectation shows.
std::string allNotes(const Model& model) {
    std::string text;
    for (const std::string& note : model.notes) {
        text += note + "\n";
    }
    return text;
}

void expectNear(const glm::mat4& actual, const glm::mat4& expected, float tolerance) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            EXPECT_NEAR(actual[c][r], expected[c][r], tolerance) << "column " << c << ", row " << r;
        }
    }
}

// A 2 x 2 PNG: red and green on the top row, blue and white below.
LdrImage fourPixels() {
    return {2, 2, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255}};
}

// The cube whose material's maps (pbrMetallicRoughness/baseColorTexture by default) use
// texture 0 of image 0 (`image`).
GltfBuilder texturedCube(const Json& image, const Json& textureInfo = {{"index", 0}}) {
    GltfBuilder model = cubeModel();
    model.add("images", image);
    model.add("textures", {{"source", 0}});
    model.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = textureInfo;
    return model;
}

class GltfModel : public test::ScratchTest {
protected:
    // `model` written as NAME.gltf (with map.png, the four pixels, beside it) and imported.
    Model load(GltfBuilder& model, const std::string& name = "model.gltf") const {
        GltfBuilder::writeBytes(path("map.png"), encodePng(fourPixels()));
        model.writeGltf(path(name));
        return importGltfModel(path(name));
    }
    std::string errorOf(GltfBuilder& model) const {
        model.writeGltf(path("bad.gltf"));
        return modelError(path("bad.gltf"));
    }
};

// glTF 2.0 section 3.5.3: world = parent's world * T * R * S.
TEST_F(GltfModel, ANodeHierarchyWithTrsGivesTheWorldMatrix) {
    GltfBuilder model = cubeModel();
    model.json["nodes"][0]["translation"] = {0, 0, 1};
    model.json["nodes"][0]["name"] = "child";
    const double h = std::sqrt(0.5);   // 90 degrees about +y
    model.add("nodes", {{"children", {0}}, {"translation", {1, 2, 3}}, {"rotation", {0, h, 0, h}}, {"scale", {2, 2, 2}}});
    model.json["scenes"][0]["nodes"] = {1};
    const Model imported = load(model);
    ASSERT_EQ(imported.draws.size(), 1u);
    // By hand: the child's origin (0, 0, 1) is scaled to (0, 0, 2), turned to (2, 0, 0) and moved
    // to (3, 2, 3); its x axis becomes (0, 0, -2), y (0, 2, 0), z (2, 0, 0).
    const glm::mat4 expected(glm::vec4(0, 0, -2, 0), glm::vec4(0, 2, 0, 0), glm::vec4(2, 0, 0, 0), glm::vec4(3, 2, 3, 1));
    expectNear(imported.draws[0].transform, expected, 1e-6f);
    EXPECT_EQ(imported.draws[0].node, "child");
    EXPECT_EQ(imported.draws[0].material, 0);
    EXPECT_FALSE(imported.draws[0].mirrored);
    EXPECT_EQ(imported.primitives[0].positions, Cube().positions);   // in the mesh's own space

    // A matrix is column-major, as GLM's.
    const std::vector<float> matrix{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 5, 6, 7, 1};
    model.json["nodes"][1] = {{"children", {0}}, {"matrix", matrix}};
    model.json["nodes"][0].erase("translation");
    EXPECT_EQ(load(model).draws[0].transform, glm::make_mat4(matrix.data()));
}

// Section 3.10: a camera node looks down its -Z with +Y up from its origin, placed by its
// world transform (the parent's too); its scale is no part of the camera. Listed in node order,
// named by the camera, else its node; an orthographic one is listed as such; a node whose
// camera is not there, or whose transform has no direction, is left out with a note.
TEST_F(GltfModel, CameraNodesAreListedWhereTheirNodesPlaceThem) {
    GltfBuilder model = cubeModel();
    const double h = std::sqrt(0.5);   // 90 degrees about +y: -Z turns to -X, +Y stays
    model.add("cameras", {{"type", "perspective"}, {"name", "side"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}});
    model.add("cameras", {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0}, {"zfar", 9}}}});
    const int side = model.add("nodes", {{"camera", 0}, {"rotation", {0, h, 0, h}}, {"scale", {3, 3, 3}}});
    const int plan = model.add("nodes", {{"camera", 1}, {"name", "plan node"}, {"translation", {0, 5, 0}}});
    const int missing = model.add("nodes", {{"camera", 7}});
    const int flat = model.add("nodes", {{"camera", 0}, {"scale", {1, 1, 0}}});
    model.add("nodes", {{"children", {side, plan, missing, flat}}, {"translation", {4, 2, 1}}});
    model.json["scenes"][0]["nodes"].push_back(int(model.json["nodes"].size()) - 1);
    const Model imported = load(model);
    ASSERT_EQ(imported.cameras.size(), 2u) << allNotes(imported);
    const ModelCamera& a = imported.cameras[0];
    EXPECT_EQ(a.name, "side");
    EXPECT_EQ(a.node, "node 1");
    EXPECT_EQ(a.index, 0);
    EXPECT_TRUE(a.perspective);
    EXPECT_FLOAT_EQ(a.yfov, 0.5f);
    EXPECT_EQ(a.position, glm::vec3(4.0f, 2.0f, 1.0f));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(a.forward[c], glm::vec3(-1, 0, 0)[c], 1e-6f) << c;
        EXPECT_NEAR(a.up[c], glm::vec3(0, 1, 0)[c], 1e-6f) << c;
    }
    const ModelCamera& b = imported.cameras[1];
    EXPECT_EQ(b.name, "plan node");
    EXPECT_EQ(b.index, 1);
    EXPECT_FALSE(b.perspective);
    EXPECT_EQ(b.position, glm::vec3(4.0f, 7.0f, 1.0f));
    const std::string notes = allNotes(imported);
    EXPECT_NE(notes.find("/nodes/3/camera: camera 7 does not exist, left out"), std::string::npos) << notes;
    EXPECT_NE(notes.find("camera \"side\" (/nodes/4): its node's transform has no direction"), std::string::npos)
        << notes;
    // Properties of the wrong type are refused by name (tinygltf would drop them quietly).
    GltfBuilder typed = model;
    typed.json["nodes"][1]["camera"] = "0";
    EXPECT_ERROR(errorOf(typed), "/nodes/1/camera: must be the index of a camera");
    typed = model;
    typed.json["cameras"][0]["perspective"]["yfov"] = "wide";
    EXPECT_ERROR(errorOf(typed), "/cameras/0/perspective/yfov: must be a number");
    // A camera node outside the default scene is not the scene's.
    model.json["scenes"][0]["nodes"] = {0};
    EXPECT_TRUE(load(model).cameras.empty());
}

TEST_F(GltfModel, InstancesShareTheirPrimitive) {
    GltfBuilder model = cubeModel();
    model.json["scenes"][0]["nodes"].push_back(model.add("nodes", {{"mesh", 0}, {"translation", {4, 0, 0}}}));
    const Model imported = load(model);
    ASSERT_EQ(imported.primitives.size(), 1u);
    ASSERT_EQ(imported.draws.size(), 2u);
    EXPECT_EQ(imported.draws[0].primitive, 0);
    EXPECT_EQ(imported.draws[1].primitive, 0);
    EXPECT_EQ(imported.draws[1].transform[3], glm::vec4(4, 0, 0, 1));
    EXPECT_EQ(imported.draws[0].node, "node 0");   // no names: the index
    EXPECT_EQ(imported.draws[1].node, "node 1");
}

TEST_F(GltfModel, ACycleOrASecondParentIsRefusedNamingTheNode) {
    GltfBuilder cycle = cubeModel();   // 0 -> 2 -> 1 -> 0
    cycle.add("nodes", {{"children", {0}}});
    cycle.add("nodes", {{"children", {1}}});
    cycle.json["nodes"][0]["children"] = {2};
    EXPECT_ERROR(errorOf(cycle), "bad.gltf: /nodes/0: is its own ancestor (a cycle in the node hierarchy)");
    cycle.json.erase("scenes");   // a cycle has no root: refused all the same
    EXPECT_ERROR(errorOf(cycle), "/nodes/0: is its own ancestor");

    GltfBuilder twoParents = cubeModel();
    twoParents.json["scenes"][0]["nodes"] = {twoParents.add("nodes", {{"children", {0}}}),
                                             twoParents.add("nodes", {{"children", {0}}})};
    EXPECT_ERROR(errorOf(twoParents), "bad.gltf: /nodes/0: has two parents, nodes 1 and 2");
    twoParents.json["nodes"][2]["children"] = Json::array();
    twoParents.json["nodes"][1]["children"] = {0, 0};
    EXPECT_ERROR(errorOf(twoParents), "/nodes/0: listed twice in the children of node 1");
    twoParents.json["nodes"][1]["children"] = {0};
    twoParents.json["scenes"][0]["nodes"] = {0, 1};
    EXPECT_ERROR(errorOf(twoParents), "/scenes/0/nodes: node 0 is a child of node 1, not a root");
}

TEST_F(GltfModel, AHierarchyAHundredThousandNodesDeepLoads) {
    constexpr int kDepth = 100000;
    GltfBuilder model = cubeModel();   // node 0, the deepest
    for (int n = 1; n <= kDepth; ++n) {
        model.add("nodes", {{"children", {n - 1}}, {"translation", {0, 1, 0}}});
    }
    model.json["scenes"][0]["nodes"] = {kDepth};
    const Model imported = load(model);
    ASSERT_EQ(imported.draws.size(), 1u);
    EXPECT_EQ(imported.draws[0].transform[3], glm::vec4(0, float(kDepth), 0, 1));
}

TEST_F(GltfModel, AMirroringTransformMarksTheDrawAndKeepsThePrimitive) {
    GltfBuilder model = cubeModel();
    model.json["nodes"][0]["scale"] = {-1, 1, 1};
    for (const Json& scale : {Json{1, 1, 1}, Json{-1, -1, 1}, Json{1, 1, -2}}) {
        model.json["scenes"][0]["nodes"].push_back(model.add("nodes", {{"mesh", 0}, {"scale", scale}}));
    }
    const Model imported = load(model);
    ASSERT_EQ(imported.draws.size(), 4u);
    EXPECT_TRUE(imported.draws[0].mirrored);
    EXPECT_FALSE(imported.draws[1].mirrored);
    EXPECT_FALSE(imported.draws[2].mirrored);   // two mirrors make a turn
    EXPECT_TRUE(imported.draws[3].mirrored);
    EXPECT_EQ(imported.primitives[0].indices, Cube().indices);   // shared: never reversed
}

// The same triangle: the same corners in the same turning order, from any first corner.
bool sameTriangle(const uint32_t* a, std::array<uint32_t, 3> b) {
    for (int shift = 0; shift < 3; ++shift) {
        if (a[0] == b[shift] && a[1] == b[(shift + 1) % 3] && a[2] == b[(shift + 2) % 3]) {
            return true;
        }
    }
    return false;
}

// Section 3.7.2.1: strip triangle i is (v_i, v_{i+1+i%2}, v_{i+2-i%2}), fan triangle i is
// (v_{i+1}, v_{i+2}, v_0), v_i the i-th index.
TEST_F(GltfModel, StripsAndFansFollowTheSpecsOrder) {
    GltfBuilder model;
    // With normals: no vertex is copied for flat normals, the indices stay the file's.
    const Json attributes{{"POSITION", model.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 1, 0}})},
                          {"NORMAL", model.positions(std::vector<glm::vec3>(5, glm::vec3(0, 0, 1)))}};
    const std::vector<uint8_t> v{4, 0, 3, 1, 2};
    const int indices = model.data(v, test::kUnsignedByte, "SCALAR", 1);
    model.meshNode({{"attributes", attributes}, {"indices", indices}, {"mode", 5}});
    model.meshNode({{"attributes", attributes}, {"indices", indices}, {"mode", 6}});
    const Model imported = load(model);
    ASSERT_EQ(imported.primitives.size(), 2u);
    const Mesh& strip = imported.primitives[0];
    const Mesh& fan = imported.primitives[1];
    ASSERT_EQ(strip.indices.size(), 9u);
    ASSERT_EQ(fan.indices.size(), 9u);
    for (uint32_t i = 0; i < 3; ++i) {
        EXPECT_TRUE(sameTriangle(&strip.indices[3 * i], {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]})) << "strip " << i;
        EXPECT_TRUE(sameTriangle(&fan.indices[3 * i], {v[i + 1], v[i + 2], v[0]})) << "fan " << i;
    }
}

TEST_F(GltfModel, SparseAccessorsSubstituteTheirValues) {
    GltfBuilder model;
    const int base = model.view(GltfBuilder::flatten({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    const int indices = model.view(std::vector<uint8_t>{2});
    const int values = model.view(GltfBuilder::flatten({{0, 0, 7}}));
    const Json sparse{{"count", 1},
                      {"indices", {{"bufferView", indices}, {"componentType", test::kUnsignedByte}}},
                      {"values", {{"bufferView", values}}}};
    const int positions = model.add("accessors", {{"bufferView", base}, {"componentType", test::kFloat}, {"count", 3},
                                                  {"type", "VEC3"}, {"sparse", sparse}});
    model.meshNode({{"attributes", {{"POSITION", positions}}}});
    // Without a buffer view the elements start as zeros (section 3.6.2.3).
    const int zeros = model.add("accessors", {{"componentType", test::kFloat}, {"count", 3}, {"type", "VEC3"},
                                              {"sparse", sparse}});
    model.meshNode({{"attributes", {{"POSITION", zeros}}}});
    const Model imported = load(model);
    EXPECT_EQ(imported.primitives[0].positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 0, 7}}));
    EXPECT_EQ(imported.primitives[1].positions, (std::vector<glm::vec3>{{0, 0, 0}, {0, 0, 0}, {0, 0, 7}}));

    model.bin[model.json["bufferViews"][indices]["byteOffset"].get<size_t>()] = 3;   // past the 3 elements
    EXPECT_ERROR(errorOf(model), "/accessors/0 (/meshes/0/primitives/0/attributes/POSITION): sparse index 0 is 3 "
                                 "but the accessor has 3 elements");
}

// Section 3.11: a normalized UNSIGNED_BYTE c is c / 255, an UNSIGNED_SHORT c / 65535.
TEST_F(GltfModel, NormalizedTexCoordsAreMappedToZeroOne) {
    GltfBuilder model;
    const int positions = model.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int bytes = model.data(std::vector<uint8_t>{0, 255, 51, 102, 255, 0, 0, 0}, test::kUnsignedByte, "VEC2", 2);
    const int shorts = model.data(std::vector<uint16_t>{0, 65535, 13107, 26214, 65535, 0}, test::kUnsignedShort, "VEC2", 2);
    model.json["accessors"][bytes]["count"] = 3;   // the last two bytes pad the view to 4
    model.json["accessors"][bytes]["normalized"] = true;
    model.json["accessors"][shorts]["normalized"] = true;
    model.meshNode({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", bytes}, {"TEXCOORD_1", shorts}}}});
    const Model imported = load(model);
    const std::vector<glm::vec2> expected{{0, 1}, {0.2f, 0.4f}, {1, 0}};
    for (const std::vector<glm::vec2>* uv : {&imported.primitives[0].uv0, &imported.primitives[0].uv1}) {
        ASSERT_EQ(uv->size(), 3u);
        for (size_t i = 0; i < 3; ++i) {
            EXPECT_NEAR(glm::distance((*uv)[i], expected[i]), 0.0f, 1e-7f) << i;
        }
    }
    model.json["accessors"][bytes]["normalized"] = false;   // integer UVs are KHR_mesh_quantization's
    EXPECT_ERROR(errorOf(model), "/accessors/1 (/meshes/0/primitives/0/attributes/TEXCOORD_0): must be VEC2 of FLOAT, "
                                 "normalized UNSIGNED_BYTE or normalized UNSIGNED_SHORT, not VEC2 of UNSIGNED_BYTE");
    model.json["accessors"][bytes]["normalized"] = true;
    model.json["accessors"][shorts]["count"] = 2;
    EXPECT_ERROR(errorOf(model), "/meshes/0/primitives/0/attributes/TEXCOORD_1: 2 texture coordinates for 3 positions");
}

TEST_F(GltfModel, TangentsAreReadWithNormalsAndIgnoredWithout) {
    GltfBuilder model;
    const int positions = model.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int normals = model.positions({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int tangents = model.data(std::vector<float>{2, 0, 0, -1, 0, 3, 0, 1, 1, 1, 0, -1}, test::kFloat, "VEC4", 4);
    model.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}, {"TANGENT", tangents}}}});
    model.meshNode({{"attributes", {{"POSITION", positions}, {"TANGENT", tangents}}}});
    const Model imported = load(model);
    const float h = std::sqrt(0.5f);
    const std::vector<glm::vec4> expected{{1, 0, 0, -1}, {0, 1, 0, 1}, {h, h, 0, -1}};
    ASSERT_EQ(imported.primitives[0].tangents.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(glm::distance(imported.primitives[0].tangents[i], expected[i]), 0.0f, 1e-6f) << i;
    }
    // Section 3.7.2.1: without normals, flat normals, and the tangents are ignored.
    EXPECT_TRUE(imported.primitives[1].tangents.empty());
    EXPECT_EQ(imported.primitives[1].normals, std::vector<glm::vec3>(3, glm::vec3(0, 0, 1)));
}

// Section 3.7.2.1: COLOR_0 is RGB or RGBA, float or normalized unsigned byte or short; an RGB
// one's alpha is 1. A copy for a flat normal takes its colour along.
TEST_F(GltfModel, VertexColoursAreReadInEveryFormTheSpecAllows) {
    GltfBuilder model;
    const int positions = model.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int normals = model.positions({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int floats = model.data(std::vector<float>{1, 0.5f, 0, 0, 1, 0.25f, 0.2f, 0.4f, 0.6f}, test::kFloat, "VEC3", 3);
    const int bytes = model.data(std::vector<uint8_t>{255, 0, 51, 102, 0, 255, 0, 255, 10, 20, 30, 40}, test::kUnsignedByte,
                                 "VEC4", 4);
    const int shorts = model.data(std::vector<uint16_t>{65535, 0, 0, 65535, 0, 65535, 0, 0, 0, 0, 0, 32768},
                                  test::kUnsignedShort, "VEC4", 4);
    model.json["accessors"][size_t(bytes)]["normalized"] = true;
    model.json["accessors"][size_t(shorts)]["normalized"] = true;
    for (const int colors : {floats, bytes, shorts}) {
        model.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}, {"COLOR_0", colors}}}});
    }
    const Model imported = load(model);
    const std::vector<std::vector<glm::vec4>> expected{
        {{1, 0.5f, 0, 1}, {0, 1, 0.25f, 1}, {0.2f, 0.4f, 0.6f, 1}},
        {{1, 0, 0.2f, 0.4f}, {0, 1, 0, 1}, {10 / 255.0f, 20 / 255.0f, 30 / 255.0f, 40 / 255.0f}},
        {{1, 0, 0, 1}, {0, 1, 0, 0}, {0, 0, 0, 32768 / 65535.0f}}};
    ASSERT_EQ(imported.primitives.size(), 3u);
    for (size_t p = 0; p < 3; ++p) {
        ASSERT_EQ(imported.primitives[p].colors.size(), 3u) << p;
        for (size_t i = 0; i < 3; ++i) {
            EXPECT_NEAR(glm::distance(imported.primitives[p].colors[i], expected[p][i]), 0.0f, 1e-6f) << p << " " << i;
        }
    }
    // A signed or unnormalized integer colour is not glTF's: refused, naming the accessor.
    GltfBuilder wrong = model;
    wrong.json["accessors"][size_t(bytes)]["normalized"] = false;
    EXPECT_ERROR(errorOf(wrong), "/meshes/1/primitives/0/attributes/COLOR_0");
    GltfBuilder flat;   // two triangles on vertex 0, one facing +z, one +x: vertex 0 is copied
    const int corners = flat.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}});
    const int colours = flat.data(std::vector<float>{0.1f, 0.2f, 0.3f, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1},
                                  test::kFloat, "VEC3", 3);
    const int indices = flat.data(std::vector<uint16_t>{0, 1, 2, 0, 3, 4}, test::kUnsignedShort, "SCALAR", 1);
    flat.meshNode({{"attributes", {{"POSITION", corners}, {"COLOR_0", colours}}}, {"indices", indices}});
    const Mesh mesh = load(flat).primitives[0];
    ASSERT_EQ(mesh.colors.size(), mesh.positions.size());
    EXPECT_EQ(mesh.colors[mesh.indices[3]], glm::vec4(0.1f, 0.2f, 0.3f, 1));
}

// KHR_materials_specular and _ior as the extensions define the dielectric (docs/FORMATS.md):
// F0 = min(((ior - 1) / (ior + 1))^2 specularColorFactor, 1) specularFactor per channel and
// F90 = specularFactor, read into specular, specularTint and specularWeight so that the shader's
// F0 and F90 are the file's. Only the two maps, not read, are noted.
TEST_F(GltfModel, SpecularAndIorAreReadAsTheDielectricsF0AndF90) {
    GltfBuilder model = cubeModel();
    struct Case {
        Json extensions;
        double ior;
        glm::dvec3 color;
        double factor;
    };
    const Case cases[] = {
        {Json::object(), 1.5, glm::dvec3(1.0), 1.0},
        {{{"KHR_materials_specular", {{"specularColorFactor", {1.0, 0.6, 0.5}}}}}, 1.5, {1.0, 0.6, 0.5}, 1.0},
        {{{"KHR_materials_ior", {{"ior", 2.4}}}}, 2.4, glm::dvec3(1.0), 1.0},
        {{{"KHR_materials_specular", {{"specularFactor", 0.5}}}}, 1.5, glm::dvec3(1.0), 0.5},
        {{{"KHR_materials_specular", {{"specularColorFactor", {30.0, 1.8, 0.0}}, {"specularFactor", 0.25}}},
          {"KHR_materials_ior", {{"ior", 1.33}}}},
         1.33,
         {30.0, 1.8, 0.0},
         0.25},
        {{{"KHR_materials_ior", {{"ior", 0.0}}}, {"KHR_materials_specular", {{"specularColorFactor", {0.9, 0.5, 0.1}}}}},
         0.0,
         {0.9, 0.5, 0.1},
         1.0},   // the spec-gloss conversion: ior 0 is F0 1, the colour F0 itself
        {{{"KHR_materials_ior", {{"ior", 1.0}}}}, 1.0, glm::dvec3(1.0), 1.0},   // no reflection
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.extensions.dump());
        model.json["materials"][0]["extensions"] = c.extensions;
        const Model loaded = load(model);
        const MaterialParameters& factors = loaded.materials[0].factors;
        const shader::SurfaceMaterial surface = surfaceMaterial(factors);
        const double r = (c.ior - 1.0) / (c.ior + 1.0);
        for (int channel = 0; channel < 3; ++channel) {
            const double f0 = std::min(r * r * c.color[channel], 1.0);
            EXPECT_NEAR(surface.dielectricF0[channel] * surface.specularWeight, f0 * c.factor, 1e-6) << channel;
        }
        // F90: the dielectric's weight, the metal's 1, mixed by metallic (the cube's is glTF's default 1).
        const float m = factors.metallic;
        EXPECT_FLOAT_EQ(surface.f90, float(c.factor) * (1.0f - m) + m);
        EXPECT_EQ(surface.specularWeight, float(c.factor));
        EXPECT_LE(factors.specular, 1.0f);
        EXPECT_EQ(allNotes(loaded).find("KHR_materials_specular"), std::string::npos) << allNotes(loaded);
    }
    // Patina's own dielectric comes back as it was: specular 0.5, no tint, no weight.
    model.json["materials"][0]["extensions"] = Json::object();
    const MaterialParameters plain = load(model).materials[0].factors;
    EXPECT_EQ(plain.specular, 0.5f);
    EXPECT_EQ(plain.specularTint, glm::vec3(1.0f));
    EXPECT_EQ(plain.specularWeight, 1.0f);
    // The two maps are read as the core maps are: the colour's with its UV set.
    model.add("images", {{"uri", "map.png"}});
    model.add("textures", {{"source", 0}});
    model.json["materials"][0]["extensions"] = {
        {"KHR_materials_specular",
         {{"specularTexture", {{"index", 0}}}, {"specularColorTexture", {{"index", 0}, {"texCoord", 1}}}}}};
    const Model mapped = load(model);
    EXPECT_EQ(mapped.materials[0].specular.image, 0);
    EXPECT_EQ(mapped.materials[0].specularColor.image, 0);
    EXPECT_EQ(mapped.materials[0].specularColor.texCoord, 1);
    EXPECT_TRUE(hasSpecularMaps(mapped.materials[0]));
}

// KHR_materials_iridescence: the four factors (the extension's defaults for what the file leaves
// out), its two maps, the extension drawn (no note); an ior below 1 or a negative thickness is
// refused naming its place.
TEST_F(GltfModel, IridescenceIsReadWithItsMapsAndItsBadValuesNamed) {
    GltfBuilder model = cubeModel();
    model.add("images", {{"uri", "map.png"}});
    model.add("textures", {{"source", 0}});
    model.json["extensionsUsed"] = {"KHR_materials_iridescence"};
    model.json["materials"][0]["extensions"] = {
        {"KHR_materials_iridescence",
         {{"iridescenceFactor", 0.75}, {"iridescenceThicknessMaximum", 600.0}, {"iridescenceTexture", {{"index", 0}}},
          {"iridescenceThicknessTexture", {{"index", 0}}}}}};
    const Model loaded = load(model);
    const ModelMaterial& film = loaded.materials[0];
    EXPECT_EQ(film.factors.iridescence, 0.75f);
    EXPECT_EQ(film.factors.iridescenceIor, 1.3f);
    EXPECT_EQ(film.factors.iridescenceThicknessMinimum, 100.0f);
    EXPECT_EQ(film.factors.iridescenceThicknessMaximum, 600.0f);
    EXPECT_TRUE(film.iridescenceMap.present());
    EXPECT_TRUE(film.iridescenceThickness.present());
    ASSERT_EQ(loaded.extensions.size(), 1u);
    EXPECT_EQ(loaded.extensions[0].support, ExtensionSupport::Drawn);
    EXPECT_EQ(allNotes(loaded).find("iridescence"), std::string::npos) << allNotes(loaded);
    model.json["materials"][0]["extensions"]["KHR_materials_iridescence"]["iridescenceIor"] = 0.5;
    EXPECT_ERROR(errorOf(model), "/materials/0/extensions/KHR_materials_iridescence/iridescenceIor: 0.5 is not an ior");
    model.json["materials"][0]["extensions"]["KHR_materials_iridescence"]["iridescenceIor"] = 1.5;
    model.json["materials"][0]["extensions"]["KHR_materials_iridescence"]["iridescenceThicknessMinimum"] = -10;
    EXPECT_ERROR(errorOf(model),
                 "/materials/0/extensions/KHR_materials_iridescence/iridescenceThicknessMinimum: -10 is not a thickness");
}

TEST_F(GltfModel, FlatNormalsCopyASharedVertexWithItsTexCoords) {
    GltfBuilder model;   // two triangles on vertex 0, one facing +z, one +x
    const int positions = model.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}});
    const int uvs = model.data(std::vector<float>{0.5f, 0.25f, 1, 0, 0, 1, 1, 1, 0, 0}, test::kFloat, "VEC2", 2);
    const int indices = model.data(std::vector<uint16_t>{0, 1, 2, 0, 3, 4}, test::kUnsignedShort, "SCALAR", 1);
    model.meshNode({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"indices", indices}});
    const Mesh mesh = load(model).primitives[0];
    ASSERT_EQ(mesh.positions.size(), 6u);
    ASSERT_EQ(mesh.uv0.size(), 6u);
    const uint32_t copy = mesh.indices[3];
    EXPECT_EQ(copy, 5u);
    EXPECT_EQ(mesh.positions[copy], glm::vec3(0, 0, 0));
    EXPECT_EQ(mesh.uv0[copy], glm::vec2(0.5f, 0.25f));
    EXPECT_EQ(mesh.normals[copy], glm::vec3(1, 0, 0));
    EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));
}

TEST_F(GltfModel, PointsLinesAndPrimitivesWithoutPositionsAreSkippedWithANote) {
    GltfBuilder model = cubeModel();
    Json& primitives = model.json["meshes"][0]["primitives"];
    const Json triangles = primitives[0];
    for (const int mode : {1, 3, 0}) {
        Json other = triangles;
        other["mode"] = mode;
        primitives.push_back(other);
    }
    primitives.push_back({{"attributes", {{"NORMAL", 1}}}});
    const Model imported = load(model);
    EXPECT_EQ(imported.draws.size(), 1u);
    EXPECT_EQ(imported.notes, (std::vector<std::string>{
                                  "/meshes/0/primitives/1 and 1 more: lines, not drawn (Patina draws triangles)",
                                  "/meshes/0/primitives/4: no POSITION, not drawn",
                                  "/meshes/0/primitives/3: points, not drawn (Patina draws triangles)"}));
}

TEST_F(GltfModel, TheLimitsCountEveryInstance) {
    GltfBuilder model;
    const int positions = model.positions(std::vector<glm::vec3>(size_t(1) << 16, glm::vec3(0.0f)));
    model.meshNode({{"attributes", {{"POSITION", positions}}}});
    for (int i = 0; i < 300; ++i) {
        model.json["scenes"][0]["nodes"].push_back(model.add("nodes", {{"mesh", 0}}));
    }
    EXPECT_ERROR(errorOf(model), "the scene has more than 16777216 vertices");
}

// The mesh a model opens with (AssetCache::model) is the model's draws in world space: the same
// traversal, the same primitives.
TEST_F(GltfModel, TheFlattenedMeshIsTheDrawsInWorldSpace) {
    GltfBuilder model = cubeModel();
    model.json["nodes"][0]["rotation"] = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};
    model.json["scenes"][0]["nodes"] = {
        model.add("nodes", {{"children", {0}}, {"translation", {0, 3, 0}}, {"scale", {2, 2, 2}}}),
        model.add("nodes", {{"mesh", 0}, {"scale", {1, -1, 1}}})};
    const Model imported = load(model);
    const Mesh flat = test::flatMesh(path("model.gltf"));
    std::vector<glm::vec3> expected;
    for (const DrawItem& draw : imported.draws) {
        for (const glm::vec3& p : imported.primitives[size_t(draw.primitive)].positions) {
            expected.push_back(glm::vec3(draw.transform * glm::vec4(p, 1.0f)));
        }
    }
    ASSERT_EQ(flat.positions.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(glm::distance(flat.positions[i], expected[i]), 0.0f, 1e-6f) << i;
    }
}

// --- Images ---

// Section 3.7.2.1: "When tangents are not specified, client implementations SHOULD calculate
// tangents using default MikkTSpace algorithms": only where a normal map will read them.
TEST_F(GltfModel, ANormalMappedPrimitiveWithoutTangentsGetsMikkTSpaceOnes) {
    GltfBuilder model;
    const int positions = model.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int normals = model.positions({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    // v grows down the image: the image's +x along +x, its up (+Y) along +y.
    const int uvs = model.data(std::vector<float>{0, 1, 1, 1, 0, 0}, test::kFloat, "VEC2", 2);
    model.add("images", {{"uri", "map.png"}});
    model.add("textures", {{"source", 0}});
    const int mapped = model.add("materials", {{"normalTexture", {{"index", 0}}}});
    const int plain = model.add("materials", {{"name", "plain"}});
    const Json attributes{{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}};
    model.meshNode({{"attributes", attributes}, {"material", mapped}});
    model.meshNode({{"attributes", attributes}, {"material", plain}});
    const Model imported = load(model);
    ASSERT_EQ(imported.primitives.size(), 2u);
    ASSERT_EQ(imported.primitives[0].tangents.size(), 3u);
    for (const glm::vec4& tangent : imported.primitives[0].tangents) {
        EXPECT_NEAR(glm::distance(tangent, glm::vec4(1, 0, 0, 1)), 0.0f, 1e-6f);
    }
    EXPECT_TRUE(imported.primitives[1].tangents.empty()) << "no normal map, no tangents made";
}

TEST_F(GltfModel, ImagesDecodeFromAFileADataUriAndABufferViewTopRowFirst) {
    const LdrImage pixels = fourPixels();
    const std::vector<uint8_t> png = encodePng(pixels);
    GltfBuilder file = texturedCube({{"uri", "map.png"}});
    GltfBuilder dataUri = texturedCube({{"uri", "data:image/png;base64," + base64(png)}, {"name", "inline"}});
    GltfBuilder view = texturedCube(Json::object());
    view.json["images"][0] = {{"bufferView", view.view(png)}, {"mimeType", "image/png"}};
    const std::pair<GltfBuilder*, std::string> cases[] = {{&file, "map.png"}, {&dataUri, "inline"}, {&view, "image 0"}};
    for (const auto& [model, name] : cases) {
        const Model imported = load(*model);
        ASSERT_EQ(imported.images.size(), 1u) << name << "\n" << allNotes(imported);
        EXPECT_EQ(imported.images[0].name, name);
        EXPECT_EQ(imported.images[0].width, 2);
        EXPECT_EQ(imported.images[0].height, 2);
        EXPECT_EQ(imported.images[0].rgba, pixels.rgba) << name;
        EXPECT_EQ(imported.materials[0].baseColor.image, 0);
        EXPECT_TRUE(imported.notes.empty()) << allNotes(imported);
    }
    // The view in a GLB's BIN chunk.
    view.writeGlb(path("view.glb"));
    EXPECT_EQ(importGltfModel(path("view.glb")).images.at(0).rgba, pixels.rgba);
}

TEST_F(GltfModel, AMissingOrBrokenImageLeavesItsMapOutWithANote) {
    const std::vector<uint8_t> png = encodePng(LdrImage{64, 64, std::vector<uint8_t>(64 * 64 * 4, 77)});
    GltfBuilder::writeBytes(path("cut.png"), std::vector<uint8_t>(png.begin(), png.begin() + long(png.size() / 2)));
    GltfBuilder::writeText(path("text.png"), "not an image at all");
    const std::pair<std::string, std::string> cases[] = {
        {"absent.png", "/images/0 (absent.png): is not found in the model's folder; the maps that use it are left out"},
        {"cut.png", "/images/0 (cut.png): cannot be decoded: "},
        {"text.png", "/images/0 (text.png): is neither PNG, JPEG nor WebP; the maps that use it are left out"},
    };
    for (const auto& [uri, note] : cases) {
        GltfBuilder model = texturedCube({{"uri", uri}});
        const Model imported = load(model);
        ASSERT_EQ(imported.notes.size(), 1u) << uri << "\n" << allNotes(imported);
        EXPECT_ERROR(imported.notes[0], note);
        EXPECT_TRUE(imported.images.empty());
        EXPECT_FALSE(imported.materials[0].baseColor.present());
        EXPECT_EQ(imported.draws.size(), 1u);
    }
    // An image no material uses is not decoded at all: no note.
    GltfBuilder unused = texturedCube({{"uri", "map.png"}});
    unused.add("images", {{"uri", "absent.png"}});
    const Model imported = load(unused);
    EXPECT_TRUE(imported.notes.empty()) << allNotes(imported);
    EXPECT_EQ(imported.images.size(), 1u);
}

// A PNG's signature and IHDR chunk only: what the size check reads before anything is decoded.
std::vector<uint8_t> pngHeader(uint32_t width, uint32_t height) {
    std::vector<uint8_t> bytes{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
    for (const uint32_t value : {width, height}) {
        bytes.insert(bytes.end(), {uint8_t(value >> 24), uint8_t(value >> 16), uint8_t(value >> 8), uint8_t(value)});
    }
    bytes.insert(bytes.end(), {8, 6, 0, 0, 0, 0, 0, 0, 0});   // 8-bit RGBA, then the CRC (unchecked)
    return bytes;
}

// stb_image fails on a deflate block of the reserved type 3 without setting its per-thread reason,
// so a fresh thread's first such failure has none: decodePng on one, and the glTF decoding workers
// (five images, so that some reach them), still say why.
TEST_F(GltfModel, AnImageStbImageFailsWithoutAReasonStillMakesANote) {
    std::vector<uint8_t> png = pngHeader(1, 1);
    // IDAT: a zlib header, then one final block of type 3 (bits 1, 11). The CRC is not checked.
    png.insert(png.end(), {0, 0, 0, 3, 'I', 'D', 'A', 'T', 0x78, 0x01, 0x07, 0, 0, 0, 0});
    png.insert(png.end(), {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82});
    std::string message;
    std::thread([&] {
        try {
            decodePng(png);
        } catch (const std::runtime_error& error) {
            message = error.what();
        }
    }).join();
    EXPECT_EQ(message, "not a readable PNG: corrupt data");

    GltfBuilder model = texturedCube({{"uri", "type3-0.png"}});
    Json& material = model.json["materials"][0];
    const char* slots[] = {"normalTexture", "occlusionTexture", "emissiveTexture", "metallicRoughnessTexture"};
    for (int i = 1; i <= 4; ++i) {
        model.add("images", {{"uri", "type3-" + std::to_string(i) + ".png"}});
        model.add("textures", {{"source", i}});
        Json& slot = i < 4 ? material[slots[i - 1]] : material["pbrMetallicRoughness"][slots[i - 1]];
        slot = {{"index", i}};
    }
    for (int i = 0; i <= 4; ++i) {
        GltfBuilder::writeBytes(path("type3-" + std::to_string(i) + ".png"), png);
    }
    const Model imported = load(model);
    ASSERT_EQ(imported.notes.size(), 5u) << allNotes(imported);
    for (const std::string& note : imported.notes) {
        EXPECT_ERROR(note, ".png): cannot be decoded: ");
    }
    EXPECT_TRUE(imported.images.empty());
}

TEST_F(GltfModel, ImagesOverTheLimitsAreLeftOutWithANote) {
    const int wide = gltf::kGltfMaxImageSide + 1;
    GltfBuilder::writeBytes(path("wide.png"), encodePng(LdrImage{wide, 1, std::vector<uint8_t>(size_t(wide) * 4, 9)}));
    // 16384 x 8193 RGBA is over 512 MiB.
    GltfBuilder::writeBytes(path("huge.png"), pngHeader(uint32_t(gltf::kGltfMaxImageSide), 8193));
    GltfBuilder model = texturedCube({{"uri", "wide.png"}});
    model.add("images", {{"uri", "huge.png"}});
    model.add("textures", {{"source", 1}});
    model.json["materials"][0]["emissiveTexture"] = {{"index", 1}};
    const Model imported = load(model);
    EXPECT_EQ(imported.notes, (std::vector<std::string>{
                                  "/images/0 (wide.png): is 16385 x 1 pixels, over Patina's limit of 16384 a side; "
                                  "the maps that use it are left out",
                                  "/images/1 (huge.png): would take the model's decoded images past Patina's limit "
                                  "of 512 MiB; the maps that use it are left out"}));
    EXPECT_FALSE(imported.materials[0].baseColor.present());
    EXPECT_FALSE(imported.materials[0].emissive.present());
}

// --- Materials, textures, samplers ---

// Section 3.8.4: the WebGL enums; no sampler is repeat with linear, mipmapped filtering.
TEST_F(GltfModel, SamplersMapWrapAndFilterEnums) {
    GltfBuilder model = texturedCube({{"uri", "map.png"}});
    model.json["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}, {"minFilter", 9984}},
                              {{"wrapS", 10497}, {"minFilter", 9729}},
                              {{"minFilter", 9986}, {"magFilter", 9729}},
                              Json::object()};
    model.json["textures"] = {{{"source", 0}, {"sampler", 0}}, {{"source", 0}, {"sampler", 1}},
                              {{"source", 0}, {"sampler", 2}}, {{"source", 0}, {"sampler", 3}}, {{"source", 0}}};
    Json& material = model.json["materials"][0];
    material["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {{"index", 1}};
    material["normalTexture"] = {{"index", 2}};
    material["occlusionTexture"] = {{"index", 3}};
    material["emissiveTexture"] = {{"index", 4}};
    const ModelMaterial imported = load(model).materials.at(0);
    using W = TextureWrap;
    EXPECT_EQ(imported.baseColor.sampler, (TextureSampler{W::ClampToEdge, W::MirroredRepeat, true, true, true}));
    EXPECT_EQ(imported.metallicRoughness.sampler, (TextureSampler{W::Repeat, W::Repeat, false, false, false}));
    EXPECT_EQ(imported.normal.sampler, (TextureSampler{W::Repeat, W::Repeat, false, true, true}));
    EXPECT_EQ(imported.occlusion.sampler, TextureSampler());
    EXPECT_EQ(imported.emissive.sampler, TextureSampler());
    EXPECT_EQ(TextureSampler(), (TextureSampler{W::Repeat, W::Repeat, false, false, true}));

    model.json["samplers"][0]["wrapS"] = 1234;
    EXPECT_ERROR(errorOf(model), "/samplers/0/wrapS: 1234 is not 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or 33648");
    model.json["samplers"][0]["wrapS"] = 33071;
    model.json["samplers"][0]["minFilter"] = 9730;
    EXPECT_ERROR(errorOf(model), "/samplers/0/minFilter: 9730 is not 9728, 9729 or 9984 to 9987");
    model.json["samplers"][0]["minFilter"] = 9729;
    model.json["samplers"][0]["magFilter"] = 9984;
    EXPECT_ERROR(errorOf(model), "/samplers/0/magFilter: 9984 is not 9728 (NEAREST) or 9729 (LINEAR)");
}

TEST_F(GltfModel, TexCoordAndTheTextureTransformAreRead) {
    GltfBuilder model = texturedCube(
        {{"uri", "map.png"}},
        {{"index", 0},
         {"texCoord", 1},
         {"extensions",
          {{"KHR_texture_transform", {{"offset", {0.5, -0.25}}, {"rotation", 0.3}, {"scale", {2, 3}}, {"texCoord", 0}}}}}});
    model.json["materials"][0]["emissiveTexture"] = {{"index", 0}, {"texCoord", 1}};
    const ModelMaterial imported = load(model).materials.at(0);
    EXPECT_EQ(imported.baseColor.texCoord, 0);   // the transform's texCoord overrides
    EXPECT_EQ(imported.baseColor.transform, (TextureTransform{{0.5f, -0.25f}, {2.0f, 3.0f}, 0.3f}));
    EXPECT_EQ(imported.emissive.texCoord, 1);
    EXPECT_EQ(imported.emissive.transform, TextureTransform());

    model.json["materials"][0]["emissiveTexture"]["texCoord"] = 2;
    EXPECT_ERROR(errorOf(model), "bad.gltf: /materials/0/emissiveTexture/texCoord: 2: Patina reads TEXCOORD_0 and "
                                 "TEXCOORD_1 only");
    model.json["materials"][0]["emissiveTexture"]["texCoord"] = 0;
    Json& transform = model.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]
                                ["KHR_texture_transform"];
    transform["texCoord"] = 3;
    EXPECT_ERROR(errorOf(model), "/baseColorTexture/extensions/KHR_texture_transform/texCoord: 3: Patina reads");
    transform["texCoord"] = 1;
    transform["offset"] = {1, 2, 3};
    EXPECT_ERROR(errorOf(model), "/KHR_texture_transform/offset: must be an array of 2 numbers");
    transform["offset"] = "left";
    EXPECT_ERROR(errorOf(model), "/KHR_texture_transform/offset: must be an array, not a string");
}

TEST_F(GltfModel, MaterialFactorsAndFieldsAreRead) {
    GltfBuilder model = texturedCube({{"uri", "map.png"}});
    model.json["materials"][0] = {
        {"name", "lacquer"},
        {"pbrMetallicRoughness",
         {{"baseColorFactor", {0.5, 0.25, 1, 0.4}}, {"metallicFactor", 0.3}, {"roughnessFactor", 0.6}}},
        {"normalTexture", {{"index", 0}, {"scale", 0.7}}},
        {"occlusionTexture", {{"index", 0}, {"strength", 0.25}}},
        {"emissiveFactor", {1, 0.5, 0.25}},
        {"alphaMode", "MASK"},
        {"alphaCutoff", 0.3},
        {"doubleSided", true},
        {"extensions",
         {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}},
          {"KHR_materials_specular", {{"specularFactor", 0.5}}}}}};
    model.add("materials", Json::object());
    const Model imported = load(model);
    ASSERT_EQ(imported.materials.size(), 2u);
    const ModelMaterial& m = imported.materials[0];
    EXPECT_EQ(m.name, "lacquer");
    EXPECT_EQ(m.factors.baseColor, glm::vec3(0.5f, 0.25f, 1.0f));   // linear, as given
    EXPECT_EQ(m.baseAlpha, 0.4f);
    EXPECT_EQ(m.factors.metallic, 0.3f);
    EXPECT_EQ(m.factors.roughness, 0.6f);
    // material.h's mapping: F0 0.04 (specular 0.5), its Fresnel weighted by specularFactor.
    EXPECT_NEAR(m.factors.specular, 0.5f, 1e-6f);
    EXPECT_EQ(m.factors.specularWeight, 0.5f);
    EXPECT_EQ(m.factors.model, BrdfModelId::Gltf);   // shaded as glTF 2.0's Appendix B defines
    EXPECT_TRUE(m.normal.present());
    EXPECT_EQ(m.normalScale, 0.7f);
    EXPECT_TRUE(m.occlusion.present());
    EXPECT_EQ(m.occlusionStrength, 0.25f);
    EXPECT_EQ(m.emissiveFactor, glm::vec3(4.0f, 2.0f, 1.0f));
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_TRUE(m.doubleSided);
    // glTF's defaults (section 3.9), and a name for a material without one.
    ModelMaterial defaults;
    defaults.name = "material 1";
    defaults.factors = MaterialParameters{glm::vec3(1.0f), 1.0f, 0.5f, 1.0f, BrdfModelId::Gltf};
    EXPECT_EQ(imported.materials[1], defaults);

    model.json["materials"][0]["alphaMode"] = "GLASS";
    EXPECT_ERROR(errorOf(model), "/materials/0/alphaMode: \"GLASS\" is not OPAQUE, MASK or BLEND");
    model.json["materials"][0]["alphaMode"] = "BLEND";
    model.json["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = -1;
    EXPECT_ERROR(errorOf(model), "/materials/0/extensions/KHR_materials_emissive_strength/emissiveStrength: "
                                 "-1 is below 0");
}

// KHR_materials_clearcoat: its two factors into the material's, its three maps as the core maps
// are read (UV set, KHR_texture_transform), the coat normal's scale; a coat without maps, and
// the extension's defaults (no coat) where a material lacks it.
TEST_F(GltfModel, TheClearcoatsFactorsAndMapsAreRead) {
    GltfBuilder model = texturedCube({{"uri", "map.png"}});
    model.json["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_texture_transform"};
    model.json["materials"][0]["extensions"]["KHR_materials_clearcoat"] = {
        {"clearcoatFactor", 0.75},
        {"clearcoatRoughnessFactor", 0.25},
        {"clearcoatTexture", {{"index", 0}, {"texCoord", 0}}},
        {"clearcoatRoughnessTexture",
         {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {2, 3}}, {"texCoord", 0}}}}}}},
        {"clearcoatNormalTexture", {{"index", 0}, {"scale", 0.5}}}};
    model.add("materials", {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 2.0}}}}}});
    model.add("materials", Json::object());
    const Model imported = load(model);
    ASSERT_EQ(imported.materials.size(), 3u);
    const ModelMaterial& coated = imported.materials[0];
    EXPECT_EQ(coated.factors.clearcoat, 0.75f);
    EXPECT_EQ(coated.factors.clearcoatRoughness, 0.25f);
    EXPECT_TRUE(coated.clearcoat.present());
    EXPECT_EQ(coated.clearcoat.image, coated.baseColor.image);
    EXPECT_TRUE(coated.clearcoatRoughness.present());
    EXPECT_EQ(coated.clearcoatRoughness.transform.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_TRUE(coated.clearcoatNormal.present());
    EXPECT_EQ(coated.clearcoatNormalScale, 0.5f);
    // (The cube has no UVs, so no tangents: GltfAssets.ClearCoatReadsNormalMaps... sees a coat
    // normal map's primitive get them.)
    EXPECT_EQ(imported.extensions[0].support, ExtensionSupport::Drawn);
    EXPECT_TRUE(imported.notes.empty()) << allNotes(imported);
    // Factors clamped to [0, 1] as every factor; roughness 0 by the extension's default.
    EXPECT_EQ(imported.materials[1].factors.clearcoat, 1.0f);
    EXPECT_EQ(imported.materials[1].factors.clearcoatRoughness, 0.0f);
    EXPECT_FALSE(imported.materials[1].clearcoat.present());
    EXPECT_EQ(imported.materials[2].factors.clearcoat, 0.0f);

    model.json["materials"][0]["extensions"]["KHR_materials_clearcoat"]["clearcoatTexture"]["index"] = 9;
    EXPECT_ERROR(errorOf(model), "/materials/0/extensions/KHR_materials_clearcoat/clearcoatTexture/index: texture 9 "
                                 "does not exist");
    model.json["materials"][0]["extensions"]["KHR_materials_clearcoat"]["clearcoatFactor"] = "thick";
    EXPECT_ERROR(errorOf(model), "/materials/0/extensions/KHR_materials_clearcoat/clearcoatFactor: must be a number");
}

TEST_F(GltfModel, IndicesOutOfRangeAreRefusedNamingThem) {
    const struct {
        const char* pointer;
        Json value;
        const char* message;
    } cases[] = {
        {"/materials/0/pbrMetallicRoughness/baseColorTexture/index", 5,
         "/materials/0/pbrMetallicRoughness/baseColorTexture/index: texture 5 does not exist"},
        {"/materials/0/pbrMetallicRoughness/baseColorTexture/index", -1,
         "/materials/0/pbrMetallicRoughness/baseColorTexture/index: texture -1 does not exist"},
        {"/textures/0/source", 7, "/textures/0/source: image 7 does not exist"},
        {"/textures/0/sampler", 3, "/textures/0/sampler: sampler 3 does not exist"},
        {"/meshes/0/primitives/0/material", 4, "/meshes/0/primitives/0/material: material 4 does not exist"},
        {"/images/0", {{"bufferView", 9}, {"mimeType", "image/png"}}, "bufferView"},
    };
    for (const auto& c : cases) {
        GltfBuilder model = texturedCube({{"uri", "map.png"}});
        model.json[Json::json_pointer(c.pointer)] = c.value;
        EXPECT_ERROR(errorOf(model), c.message) << c.pointer;
    }
}

TEST_F(GltfModel, ExtensionsPatinaDoesNotReadAreNotedOrRefused) {
    GltfBuilder basisu = texturedCube({{"uri", "map.png"}});
    basisu.json["textures"][0] = {{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}};
    const Model imported = load(basisu);
    EXPECT_EQ(imported.notes, std::vector<std::string>{"/textures/0: its image is in KHR_texture_basisu, which Patina "
                                                       "does not read; the materials that use it take their factors "
                                                       "alone"});
    EXPECT_FALSE(imported.materials[0].baseColor.present());
    // With a fallback image, as the extension asks writers to give: that one, and no note.
    basisu.json["textures"][0]["source"] = 0;
    EXPECT_TRUE(load(basisu).materials[0].baseColor.present());
    EXPECT_TRUE(load(basisu).notes.empty());

    basisu.json["extensionsRequired"] = {"KHR_materials_emissive_strength", "KHR_texture_transform",
                                        "KHR_materials_specular", "KHR_materials_ior"};
    EXPECT_EQ(errorOf(basisu), "(loaded)");
    basisu.json["extensionsRequired"] = {"KHR_texture_basisu"};
    EXPECT_ERROR(errorOf(basisu), "requires the extension KHR_texture_basisu, which Patina does not draw (KTX2 images "
                                  "are not decoded); the file cannot be shown without it");
}

// Every extension a file uses is listed with what Patina draws of it, and each whose effect the
// picture lacks is a note (the editor's status line, render and validate print them).
TEST_F(GltfModel, EveryExtensionTheFileUsesIsToldWithWhatIsDrawnOfIt) {
    GltfBuilder model = cubeModel();
    model.json["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_diffuse_transmission", "EXT_made_up",
                                    "KHR_xmp_json_ld"};
    model.json["materials"][0]["extensions"]["KHR_materials_diffuse_transmission"] = {{"diffuseTransmissionFactor", 1.0}};
    const Model loaded = load(model);
    ASSERT_EQ(loaded.extensions.size(), 4u);
    EXPECT_EQ(loaded.extensions[0].name, "KHR_texture_transform");
    EXPECT_EQ(loaded.extensions[0].support, ExtensionSupport::Drawn);
    EXPECT_EQ(loaded.extensions[1].support, ExtensionSupport::NotDrawn);
    EXPECT_EQ(loaded.extensions[2].support, ExtensionSupport::Unknown);
    EXPECT_EQ(loaded.extensions[3].support, ExtensionSupport::Metadata);
    EXPECT_FALSE(loaded.extensions[1].required);
    EXPECT_EQ(loaded.notes,
              (std::vector<std::string>{
                  "uses KHR_materials_diffuse_transmission (not drawn): light through the surface is left out; the material shows opaque",
                  "uses EXT_made_up (unknown to Patina): whatever it adds is left out"}))
        << allNotes(loaded);
    // A required extension the file forgot to list as used is listed all the same.
    model.json["extensionsRequired"] = {"KHR_texture_transform"};
    model.json["extensionsUsed"] = Json::array();
    const Model required = load(model);
    ASSERT_EQ(required.extensions.size(), 1u);
    EXPECT_TRUE(required.extensions[0].required);
    EXPECT_TRUE(required.notes.empty()) << allNotes(required);
}

// A required extension Patina cannot draw is named before the parser trips on what it changed
// (a Draco mesh's accessors without a bufferView, before Draco was decoded, made tinygltf say
// "accessor[0] invalid bufferView").
TEST_F(GltfModel, ARequiredExtensionPatinaCannotDrawIsRefusedByItsName) {
    GltfBuilder model = cubeModel();
    model.json["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    model.json["extensionsRequired"] = {"EXT_mesh_gpu_instancing"};
    EXPECT_ERROR(errorOf(model), "requires the extension EXT_mesh_gpu_instancing, which Patina does not draw "
                                 "(each mesh is drawn once, at its node, without its instances); the file cannot be "
                                 "shown without it");
    model.json["extensionsRequired"] = {"KHR_xmp_json_ld"};   // metadata: nothing to draw, nothing missing
    model.json["extensionsUsed"] = {"KHR_xmp_json_ld"};
    EXPECT_EQ(errorOf(model), "(loaded)");
}

}  // namespace
}  // namespace patina
