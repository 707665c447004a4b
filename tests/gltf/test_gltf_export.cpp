// glTF export (engine/gltf/export.h, `patina export`): the Khronos glTF-Validator finds no
// error and no warning, import gives back the material and the triangles, writes are atomic.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cli_runner.h"
#include "gltf_builder.h"
#include "gltf/export.h"
#include "image/image.h"
#include "io/json_writer.h"
#include "io/scene_file.h"
#include "scratch_test.h"
#include "validator.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

class GltfExport : public test::ScratchTest {
protected:
    test::CliRun run(const std::string& arguments) const { return test::runPatina(arguments, dir_); }

    Json validate(const fs::path& file) const { return test::validateGltf(file, dir_); }
    void expectValid(const fs::path& file) const { test::expectValidGltf(file, dir_); }
};

Material unusualMaterial() {
    Material material;
    material.name = "blue \"enamel\" \xc3\xa9";
    material.baseColor = {0.123456f, 0.5f, 0.987654f};
    material.roughness = 0.0123f;
    material.specular = 0.8312f;
    material.metallic = 0.25f;
    return material;
}

void expectSameMaterial(const Material& a, const Material& b) {
    EXPECT_EQ(a.name, b.name);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(a.baseColor[i], b.baseColor[i], 1e-6);
    }
    EXPECT_NEAR(a.roughness, b.roughness, 1e-6);
    EXPECT_NEAR(a.specular, b.specular, 1e-6);
    EXPECT_NEAR(a.metallic, b.metallic, 1e-6);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(a.specularTint[i], b.specularTint[i], 1e-6);
    }
    EXPECT_EQ(a.specularWeight, b.specularWeight);
}

TEST_F(GltfExport, ImportGivesBackTheMaterialAndTheTriangles) {
    Material black = unusualMaterial(), white = unusualMaterial(), tinted = unusualMaterial();
    black.specular = 0.0f;
    white.specular = 1.0f;
    tinted.specularTint = {0.25f, 1.0f, 0.5f};   // KHR_materials_specular's colour and factor
    tinted.specularWeight = 0.375f;
    const Mesh torus = makeTorus();
    for (const Material& material : {Material{}, unusualMaterial(), black, white, tinted}) {
        for (const auto& [name, buffer] : {std::pair{"t.gltf", GltfBuffer::Embedded},
                                           std::pair{"t b.gltf", GltfBuffer::BinFile},
                                           std::pair{"t.glb", GltfBuffer::Embedded}}) {
            exportGltf(path(name), torus, material, buffer);
            const std::shared_ptr<const LoadedModel> back = test::loadModel(path(name));
            expectSameMaterial(test::firstMaterial(back->model), material);
            EXPECT_EQ(back->mesh.indices, torus.indices) << name;
            EXPECT_EQ(back->mesh.positions, torus.positions) << name;
            ASSERT_EQ(back->mesh.normals.size(), torus.normals.size());
            for (size_t i = 0; i < torus.normals.size(); ++i) {   // normalised again on import
                ASSERT_NEAR(glm::distance(back->mesh.normals[i], torus.normals[i]), 0.0f, 1e-6f) << name << " " << i;
            }
        }
    }
    EXPECT_TRUE(fs::exists(path("t b.bin")));
}

TEST_F(GltfExport, SpecularIsWrittenSoThatF0Is008TimesSpecular) {
    Material material;
    material.specular = 0.3f;
    exportGltf(path("s.gltf"), makeUvSphere(4, 8), material);
    const Json json = readJsonFile(path("s.gltf"));
    const Json& extensions = json["materials"][0]["extensions"];
    EXPECT_EQ(extensions["KHR_materials_ior"]["ior"], 1.5);
    EXPECT_EQ(extensions["KHR_materials_specular"]["specularFactor"], 1.0);
    // ((1.5 - 1) / (1.5 + 1))^2 * colour = 0.04 * colour = 0.08 * 0.3
    for (const Json& channel : extensions["KHR_materials_specular"]["specularColorFactor"]) {
        EXPECT_NEAR(channel.get<double>(), 0.6, 1e-7);
    }
    EXPECT_EQ(json["extensionsUsed"], Json::array({"KHR_materials_specular", "KHR_materials_ior"}));
    // A tint beyond white (an F0 of 0.24, a gem's) and a weight: 2 * 0.3 * tint, specularFactor
    // the weight, validator-clean (the colour factor has no upper bound).
    material.specularTint = {12.5f, 1.0f, 0.0f};
    material.specularWeight = 0.5f;
    exportGltf(path("gem.gltf"), makeUvSphere(4, 8), material);
    const Json gem = readJsonFile(path("gem.gltf"))["materials"][0]["extensions"]["KHR_materials_specular"];
    EXPECT_EQ(gem["specularFactor"], 0.5);
    EXPECT_NEAR(gem["specularColorFactor"][0].get<double>(), 7.5, 1e-6);
    EXPECT_NEAR(gem["specularColorFactor"][1].get<double>(), 0.6, 1e-7);
    EXPECT_EQ(gem["specularColorFactor"][2].get<double>(), 0.0);
    expectValid(path("gem.gltf"));
    // A glass refracts by its ior in other viewers (a volume's): a grey F0 is written as its ior,
    // diamond's 2.42 as 2.42, the colour factor white; read back, the same F0.
    Material diamond;
    diamond.transmission = 1.0f;
    diamond.specular = 1.0f;
    const double diamondF0 = std::pow(1.42 / 3.42, 2.0);
    diamond.specularTint = glm::vec3(float(diamondF0 / 0.08));
    exportGltf(path("diamond.gltf"), makeUvSphere(4, 8), diamond);
    const Json glass = readJsonFile(path("diamond.gltf"))["materials"][0]["extensions"];
    EXPECT_NEAR(glass["KHR_materials_ior"]["ior"].get<double>(), 2.42, 1e-5);
    EXPECT_EQ(glass["KHR_materials_specular"]["specularColorFactor"], Json::array({1.0, 1.0, 1.0}));
    expectValid(path("diamond.gltf"));
    const Material back = test::firstMaterial(test::loadModel(path("diamond.gltf"))->model);
    EXPECT_NEAR(0.08 * back.specular * back.specularTint.r, diamondF0, 1e-6);
}

TEST_F(GltfExport, TheKhronosValidatorFindsNoErrorsOrWarnings) {
    const std::string material = path("m.json").string();
    write("m.json", prettyJson(materialToJson(unusualMaterial())));
    ASSERT_EQ(run("export --material " + material + " --out " + path("sphere.gltf").string()).exitCode, 0);
    ASSERT_EQ(run("export --mesh torus --out " + path("torus.glb").string()).exitCode, 0);
    ASSERT_EQ(run("export --mesh torus --bin --out '" + path("torus bin.gltf").string() + "'").exitCode, 0);
    // Generated normals too: a cube without normals, through import and export again.
    test::cubeModel(false).writeGltf(path("cube.gltf"));
    ASSERT_EQ(run("export --mesh " + path("cube.gltf").string() + " --out " + path("cube.glb").string()).exitCode, 0);
    for (const char* name : {"sphere.gltf", "torus.glb", "torus bin.gltf", "cube.glb"}) {
        expectValid(path(name));
    }
    // The check itself works: a file with a broken accessor has errors.
    Json broken = readJsonFile(path("sphere.gltf"));
    broken["accessors"][0]["count"] = 1;
    write("broken.gltf", broken.dump());
    EXPECT_GT(validate(path("broken.gltf"))["issues"]["numErrors"].get<int>(), 0);
}

TEST_F(GltfExport, TheCommandTakesAMeshFileAndRefusesBadArguments) {
    write("m.json", prettyJson(materialToJson(unusualMaterial())));
    ASSERT_EQ(run("export --mesh torus --out " + path("t.glb").string()).exitCode, 0);
    const test::CliRun again = run("export --material " + path("m.json").string() + " --mesh " +
                                   path("t.glb").string() + " --out " + path("again.gltf").string());
    ASSERT_EQ(again.exitCode, 0) << again.stderrText;
    const std::shared_ptr<const LoadedModel> back = test::loadModel(path("again.gltf"));
    EXPECT_EQ(back->mesh.indices, makeTorus().indices);
    // A model's part takes the material's factors and keeps its own name.
    Material expected = unusualMaterial();
    expected.name = defaultScene().material.name;
    expectSameMaterial(test::firstMaterial(back->model), expected);
    EXPECT_EQ(importGltfModel(path("t.glb")).materials.at(0).name, defaultScene().material.name);

    EXPECT_EQ(run("export --out " + path("x.obj").string()).exitCode, 2);
    EXPECT_EQ(run("export").exitCode, 2);
    const test::CliRun missing = run("export --mesh " + path("none.glb").string() + " --out " + path("x.glb").string());
    EXPECT_EQ(missing.exitCode, 3);
    EXPECT_NE(missing.stderrText.find("none.glb"), std::string::npos) << missing.stderrText;
    EXPECT_EQ(run("export --out " + path("no/such/dir/x.glb").string()).exitCode, 3);
    EXPECT_FALSE(fs::exists(path("x.glb")));
}

TEST_F(GltfExport, AFailedWriteLeavesNoFileBehind) {
    fs::create_directory(path("taken.gltf"));   // the .bin can be written, the .gltf cannot
    EXPECT_THROW(exportGltf(path("taken.gltf"), makeTorus(), Material{}, GltfBuffer::BinFile), std::runtime_error);
    EXPECT_FALSE(fs::exists(path("taken.bin")));
    EXPECT_THROW(encodeGltf(path("mesh.obj"), makeTorus(), Material{}), InputError);
    EXPECT_THROW(encodeGltf(path("empty.glb"), Mesh{}, Material{}), InputError);
    for (const fs::directory_entry& entry : fs::directory_iterator(dir_)) {
        EXPECT_EQ(entry.path().filename(), "taken.gltf");   // no temporary files either
    }
}

}  // namespace
}  // namespace patina
