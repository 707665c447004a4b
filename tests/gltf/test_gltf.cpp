// glTF import of valid files, as a model opens (assets/asset_cache.h: gltf/model_import.h and
// its draws flattened, gltf/flatten.h): geometry through the node hierarchy, index widths, strips and fans, flat normals, the material mapping, framing and speed.
// Hostile files are in test_gltf_hostile.cpp, export in test_gltf_export.cpp.
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "gltf_builder.h"
#include "gltf/export.h"
#include "scratch_test.h"

namespace patina {
namespace {

namespace fs = std::filesystem;
using test::Cube;
using test::cubeModel;
using test::GltfBuilder;

class Gltf : public test::ScratchTest {};

// The corners of each triangle as positions: independent of how vertices are shared.
std::vector<glm::vec3> trianglePoints(const Mesh& mesh) {
    std::vector<glm::vec3> points;
    for (const uint32_t i : mesh.indices) {
        points.push_back(mesh.positions[i]);
    }
    return points;
}

// Every triangle faces the way its vertex normals do (counter-clockwise from outside).
void expectOutwardWinding(const Mesh& mesh) {
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                        c = mesh.positions[mesh.indices[t + 2]];
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), mesh.normals[mesh.indices[t]]), 0.0f) << "triangle " << t / 3;
    }
}

TEST_F(Gltf, CubeWithNormalsFromGltfGlbAndDataUri) {
    GltfBuilder model = cubeModel();
    model.writeGltf(path("cube.gltf"));
    model.writeGlb(path("cube.glb"));
    const Cube cube;
    for (const char* name : {"cube.gltf", "cube.glb"}) {
        const std::shared_ptr<const LoadedModel> imported = test::loadModel(path(name));
        EXPECT_EQ(imported->mesh.positions, cube.positions) << name;
        EXPECT_EQ(imported->mesh.normals, cube.normals) << name;
        EXPECT_EQ(imported->mesh.indices, cube.indices) << name;
        ASSERT_EQ(imported->model.materials.size(), 1u);
        EXPECT_EQ(imported->model.materials[0].name, "cube");
    }
}

// glTF 2.0 section 3.7.2.1: without NORMAL, flat normals.
TEST_F(Gltf, MissingNormalsAreFlat) {
    cubeModel(false).writeGltf(path("cube.gltf"));
    const Mesh mesh = test::flatMesh(path("cube.gltf"));
    const Cube cube;
    ASSERT_EQ(mesh.normals.size(), cube.normals.size());   // split by face already: no copies
    for (size_t i = 0; i < cube.normals.size(); ++i) {
        EXPECT_NEAR(glm::distance(mesh.normals[i], cube.normals[i]), 0.0f, 1e-6f) << i;
    }
    // A vertex shared by a big and a small triangle facing apart: each triangle keeps its own
    // plane's normal, through a copy of the vertex.
    GltfBuilder model;
    const int positions = model.positions({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 0.1f}, {0, -0.1f, 0}});
    const int indices = model.data(std::vector<uint16_t>{0, 1, 2, 0, 3, 4}, test::kUnsignedShort, "SCALAR", 1);
    model.meshNode({{"attributes", {{"POSITION", positions}}}, {"indices", indices}});
    model.writeGltf(path("fan.gltf"));
    const Mesh fan = test::flatMesh(path("fan.gltf"));
    ASSERT_EQ(fan.positions.size(), 6u);
    EXPECT_EQ(fan.normals[fan.indices[0]], glm::vec3(0, 0, 1));
    EXPECT_EQ(fan.normals[fan.indices[3]], glm::vec3(1, 0, 0));
    EXPECT_EQ(fan.positions[fan.indices[3]], glm::vec3(0, 0, 0));
    // A vertex on no triangle of any area still gets a unit normal.
    GltfBuilder point;
    point.meshNode({{"attributes", {{"POSITION", point.positions({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}})}}}});
    point.writeGltf(path("point.gltf"));
    EXPECT_EQ(test::flatMesh(path("point.gltf")).normals, std::vector<glm::vec3>(3, glm::vec3(0, 1, 0)));
}

TEST_F(Gltf, EveryIndexWidthAndNoIndicesGiveTheSameTriangles) {
    cubeModel(true, test::kUnsignedShort).writeGltf(path("reference.gltf"));
    const std::vector<glm::vec3> expected = trianglePoints(test::flatMesh(path("reference.gltf")));
    for (const int type : {test::kUnsignedByte, test::kUnsignedShort, test::kUnsignedInt, 0}) {
        const fs::path file = path("cube" + std::to_string(type) + ".glb");
        cubeModel(true, type).writeGlb(file);
        const Mesh mesh = test::flatMesh(file);
        EXPECT_EQ(trianglePoints(mesh), expected) << type;
        EXPECT_EQ(mesh.indices.size(), 36u) << type;
    }
}

TEST_F(Gltf, NodeTransformsMoveTheVertices) {
    GltfBuilder model = cubeModel();
    model.json["nodes"][0]["translation"] = {5, 0, 0};
    model.writeGltf(path("moved.gltf"));
    const Mesh moved = test::flatMesh(path("moved.gltf"));
    const Cube cube;
    for (size_t i = 0; i < cube.positions.size(); ++i) {
        EXPECT_EQ(moved.positions[i], cube.positions[i] + glm::vec3(5, 0, 0));
    }
    // A parent's matrix (a translation up), then the child's rotation of 90 degrees about z.
    model.json["nodes"][0].erase("translation");
    model.json["nodes"][0]["rotation"] = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};
    model.add("nodes", {{"children", {0}}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 10, 0, 1}}});
    model.json["scenes"][0]["nodes"] = {1};
    model.writeGltf(path("nested.gltf"));
    const Mesh nested = test::flatMesh(path("nested.gltf"));
    for (size_t i = 0; i < cube.positions.size(); ++i) {
        const glm::vec3 p = cube.positions[i];
        EXPECT_NEAR(glm::distance(nested.positions[i], glm::vec3(-p.y, p.x + 10.0f, p.z)), 0.0f, 1e-5f) << i;
        const glm::vec3 n = cube.normals[i];
        EXPECT_NEAR(glm::distance(nested.normals[i], glm::vec3(-n.y, n.x, n.z)), 0.0f, 1e-5f) << i;
    }
}

TEST_F(Gltf, NormalsGoThroughTheInverseTransposeAndMirrorsKeepWindingOutward) {
    GltfBuilder model = cubeModel();
    model.json["nodes"][0]["scale"] = {3, 1, 0.5};
    model.writeGltf(path("squashed.gltf"));
    const Mesh squashed = test::flatMesh(path("squashed.gltf"));
    for (size_t i = 0; i < squashed.normals.size(); ++i) {   // axis normals stay axis normals
        EXPECT_NEAR(glm::distance(squashed.normals[i], Cube().normals[i]), 0.0f, 1e-6f);
    }
    // A sloped face: x + y = 1, scaled by 2 in x. Its normal must stay perpendicular.
    GltfBuilder slope;
    const int positions = slope.positions({{1, 0, 0}, {0, 1, 0}, {0, 1, 1}});
    const int normals = slope.positions({{std::sqrt(0.5f), std::sqrt(0.5f), 0}, {std::sqrt(0.5f), std::sqrt(0.5f), 0},
                                         {std::sqrt(0.5f), std::sqrt(0.5f), 0}});
    slope.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}}, {{"scale", {2, 1, 1}}});
    slope.writeGltf(path("slope.gltf"));
    const Mesh sloped = test::flatMesh(path("slope.gltf"));
    const glm::vec3 edge = sloped.positions[1] - sloped.positions[0];
    EXPECT_NEAR(glm::dot(sloped.normals[0], edge), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(sloped.normals[0]), 1.0f, 1e-6f);
    // A mirror (negative determinant) reverses the triangles so they still face outward.
    for (const bool withNormals : {true, false}) {
        GltfBuilder mirrored = cubeModel(withNormals);
        mirrored.json["nodes"][0]["scale"] = {-1, 1, 1};
        mirrored.writeGltf(path("mirrored.gltf"));
        const Mesh mesh = test::flatMesh(path("mirrored.gltf"));
        expectOutwardWinding(mesh);
        EXPECT_GT(glm::dot(mesh.normals[0], mesh.positions[0]), 0.0f);   // points away from the centre
    }
}

// A float squares 1e-22 into a denormal with a few bits left, 1e-30 into zero and 1e25 into
// infinity; each normal still comes out as its own direction at length 1 (the fuzzer's find).
TEST_F(Gltf, NormalsOfAnySizeKeepTheirDirectionAtUnitLength) {
    for (const float size : {1e-22f, 1e-30f, 1e-44f, 1e25f, 3e38f}) {
        GltfBuilder given;
        const int positions = given.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        const int normals = given.positions({{size, 0, 0}, {0, size, size}, {0, 0, -size}});
        given.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}});
        given.writeGltf(path("given.gltf"));
        const std::vector<glm::vec3> expected{{1, 0, 0}, {0, std::sqrt(0.5f), std::sqrt(0.5f)}, {0, 0, -1}};
        const Mesh mesh = test::flatMesh(path("given.gltf"));
        for (size_t i = 0; i < expected.size(); ++i) {
            EXPECT_NEAR(glm::distance(mesh.normals[i], expected[i]), 0.0f, 1e-6f) << size << ", normal " << i;
        }
    }
    // Through a node scaled by 1e20 or 1e-20 (finite positions; the normal matrix grows as the
    // square of the scale), a mirror included.
    for (const float scale : {1e20f, -1e-20f}) {
        GltfBuilder scaled;
        const int positions = scaled.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        const int normals = scaled.positions({{1, 0, 0}, {0, 1, 1}, {0, 0, -1}});
        scaled.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}},
                        {{"scale", {scale, std::abs(scale), std::abs(scale)}}});
        scaled.writeGltf(path("scaled.gltf"));
        const float x = scale < 0.0f ? -1.0f : 1.0f;
        const std::vector<glm::vec3> expected{{x, 0, 0}, {0, std::sqrt(0.5f), std::sqrt(0.5f)}, {0, 0, -1}};
        const Mesh mesh = test::flatMesh(path("scaled.gltf"));
        for (size_t i = 0; i < expected.size(); ++i) {
            EXPECT_NEAR(glm::distance(mesh.normals[i], expected[i]), 0.0f, 1e-6f) << scale << ", normal " << i;
        }
        // A mirror reverses the triangle: its first corner stays, the other two swap.
        const std::vector<uint32_t> corners = scale < 0.0f ? std::vector<uint32_t>{0, 2, 1} : std::vector<uint32_t>{0, 1, 2};
        EXPECT_EQ(mesh.indices, corners) << scale;
    }
    // Generated: a triangle's cross product is its size squared.
    for (const float size : {1e-11f, 1e-15f, 1e15f}) {
        GltfBuilder generated;
        generated.meshNode(
            {{"attributes", {{"POSITION", generated.positions({{0, 0, 0}, {size, 0, 0}, {0, size, 0}})}}}});
        generated.writeGltf(path("generated.gltf"));
        EXPECT_EQ(test::flatMesh(path("generated.gltf")).normals, std::vector<glm::vec3>(3, glm::vec3(0, 0, 1)))
            << size;
    }
}

TEST_F(Gltf, StripsAndFansBecomeTrianglesAndPointsAndLinesAreSkipped) {
    GltfBuilder model;
    // A unit square in z = 0, as a strip (0 1 2 3) and as a fan (0 1 2 3 in a circle).
    const int strip = model.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    const int fan = model.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    model.meshNode({{"attributes", {{"POSITION", strip}}}, {"mode", 5}});
    model.meshNode({{"attributes", {{"POSITION", fan}}}, {"mode", 6}});
    for (const int mode : {0, 1, 2, 3}) {
        model.meshNode({{"attributes", {{"POSITION", strip}}}, {"mode", mode}});
    }
    model.writeGltf(path("modes.gltf"));
    const Mesh mesh = test::flatMesh(path("modes.gltf"));
    EXPECT_EQ(mesh.indices.size(), 12u);   // two triangles from each of the strip and the fan
    for (const glm::vec3& n : mesh.normals) {
        EXPECT_NEAR(glm::distance(n, glm::vec3(0, 0, 1)), 0.0f, 1e-6f);   // all counter-clockwise
    }
    expectOutwardWinding(mesh);
}

TEST_F(Gltf, TheDefaultSceneOrElseTheRootNodesAreDrawn) {
    GltfBuilder model = cubeModel();
    model.add("nodes", {{"mesh", 0}, {"translation", {0, 7, 0}}});   // in no scene: not drawn
    model.writeGltf(path("scene0.gltf"));
    EXPECT_EQ(test::flatMesh(path("scene0.gltf")).positions.size(), 24u);
    model.json["scenes"].push_back({{"nodes", {1}}});
    model.json["scene"] = 1;
    model.writeGltf(path("scene1.gltf"));
    const Mesh second = test::flatMesh(path("scene1.gltf"));
    EXPECT_EQ(second.positions[0], Cube().positions[0] + glm::vec3(0, 7, 0));
    model.json.erase("scene");
    model.json.erase("scenes");   // both nodes are roots
    model.writeGltf(path("roots.gltf"));
    EXPECT_EQ(test::flatMesh(path("roots.gltf")).positions.size(), 48u);
}

TEST_F(Gltf, BoundingSphereFramesTheModel) {
    GltfBuilder model = cubeModel();
    model.json["nodes"][0]["translation"] = {1, 2, 3};
    model.writeGlb(path("cube.glb"));
    const BoundingSphere sphere = boundingSphere(test::flatMesh(path("cube.glb")));
    EXPECT_NEAR(glm::distance(sphere.center, glm::vec3(1, 2, 3)), 0.0f, 1e-6f);
    EXPECT_NEAR(sphere.radius, std::sqrt(3.0f) / 2.0f, 1e-6f);
}

// The material mapping of docs/FORMATS.md, case by case.
Material importMaterial(const fs::path& file, const Json& material) {
    GltfBuilder model = cubeModel();
    model.json["materials"][0] = material;
    model.writeGltf(file);
    return test::firstMaterial(importGltfModel(file));
}

TEST_F(Gltf, MaterialFactorsAndSpecularMapping) {
    const fs::path file = path("m.gltf");
    const Material plain = importMaterial(file, Json::object());   // glTF's defaults
    EXPECT_EQ(plain.name, "material 0");   // no name: its index
    EXPECT_EQ(plain.baseColor, glm::vec3(1.0f));
    EXPECT_EQ(plain.metallic, 1.0f);
    EXPECT_EQ(plain.roughness, 1.0f);
    EXPECT_NEAR(plain.specular, 0.5f, 1e-6f);   // F0 0.04 at ior 1.5

    const Material factors = importMaterial(
        file, {{"name", "brass"},
               {"pbrMetallicRoughness",
                {{"baseColorFactor", {0.9, 0.6, 0.2, 0.5}}, {"metallicFactor", 0.7}, {"roughnessFactor", 0.25}}}});
    EXPECT_EQ(factors.name, "brass");
    EXPECT_EQ(factors.baseColor, glm::vec3(0.9f, 0.6f, 0.2f));
    EXPECT_EQ(factors.metallic, 0.7f);
    EXPECT_EQ(factors.roughness, 0.25f);

    auto materialOf = [&](const Json& extensions) { return importMaterial(file, {{"extensions", extensions}}); };
    auto specularOf = [&](const Json& extensions) { return materialOf(extensions).specular; };
    const double water = std::pow(0.33 / 2.33, 2);
    EXPECT_NEAR(specularOf({{"KHR_materials_ior", {{"ior", 1.33}}}}), water / 0.08, 1e-6);
    // specularFactor is the Fresnel's weight (F0 and F90), not folded into specular.
    const Material weighted = materialOf({{"KHR_materials_specular", {{"specularFactor", 0.5}}}});
    EXPECT_NEAR(weighted.specular, 0.5, 1e-6);
    EXPECT_EQ(weighted.specularWeight, 0.5f);
    EXPECT_EQ(weighted.specularTint, glm::vec3(1.0f));
    // The largest channel of F0 = 0.04 specularColorFactor is specular (1.5 * 0.04 = 0.06: 0.75),
    // the colour the tint: (0.2, 1.5, 0.7) / 1.5.
    const Material coloured = materialOf({{"KHR_materials_specular", {{"specularColorFactor", {0.2, 1.5, 0.7}}}}});
    EXPECT_NEAR(coloured.specular, 0.75, 1e-6);
    EXPECT_NEAR(coloured.specularTint.r, 0.2 / 1.5, 1e-6);
    EXPECT_EQ(coloured.specularTint.g, 1.0f);
    EXPECT_NEAR(coloured.specularTint.b, 0.7 / 1.5, 1e-6);
    // Past F0 0.08 (diamond, ior 2.42): specular 1 and the rest in the tint, F0 0.172 itself.
    const Material diamond = materialOf({{"KHR_materials_ior", {{"ior", 2.42}}}});
    EXPECT_EQ(diamond.specular, 1.0f);
    EXPECT_NEAR(0.08 * diamond.specularTint.r, std::pow(1.42 / 3.42, 2), 1e-6);
    EXPECT_EQ(materialOf({{"KHR_materials_specular", {{"specularFactor", 0}}}}).specularWeight, 0.0f);
    EXPECT_NEAR(specularOf({{"KHR_materials_specular", {{"specularFactor", 0.5}, {"specularColorFactor", {2, 2, 2}}}},
                            {"KHR_materials_ior", {{"ior", 1.5}}}}),
                1.0, 1e-6);
    // Factors outside [0, 1] are clamped.
    const Material clamped = importMaterial(
        file, {{"pbrMetallicRoughness", {{"baseColorFactor", {2, -1, 0.5, 1}}, {"metallicFactor", 3}}}});
    EXPECT_EQ(clamped.baseColor, glm::vec3(1.0f, 0.0f, 0.5f));
    EXPECT_EQ(clamped.metallic, 1.0f);
}

TEST_F(Gltf, AMillionTrianglesLoadInSeconds) {
    const Mesh sphere = makeUvSphere(500, 1000);
    ASSERT_EQ(sphere.indices.size(), 3u * 1000000u);
    GltfBuilder model;
    const int positions = model.positions(sphere.positions), normals = model.positions(sphere.normals);
    const int indices = model.data(sphere.indices, test::kUnsignedInt, "SCALAR", 1);
    model.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}, {"indices", indices}});
    model.writeGlb(path("big.glb"));
    const auto start = std::chrono::steady_clock::now();
    const Mesh mesh = test::flatMesh(path("big.glb"));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(mesh.indices, sphere.indices);
    EXPECT_LT(seconds, 5.0);
    std::cout << "1M triangles loaded in " << seconds << " s\n";
}

}  // namespace
}  // namespace patina
