// glTF import of hand-made hostile files: every one is refused with an InputError that names
// the file and the problem, before anything outside the model's folder or past a buffer is
// read. (Sanitizer-free proof: a wrong read would load the bait files or crash the tests.)
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include <gtest/gtest.h>

#include "gltf_builder.h"
#include "image/image.h"
#include "scratch_test.h"
#include "files/file_bytes.h"

namespace patina {
namespace {

namespace fs = std::filesystem;
using test::cubeModel;
using test::GltfBuilder;
using test::importError;

class GltfHostile : public test::ScratchTest {
protected:
    void SetUp() override {
        ScratchTest::SetUp();
        fs::create_directories(model());
        // Bait outside the model's folder: the cube's own bytes, so following a bad URI would
        // load instead of failing.
        GltfBuilder::writeBytes(path("secret.bin"), cubeModel().bin);
    }
    fs::path model(const std::string& name = "") const { return dir_ / "model" / name; }

    // The cube whose buffer is at `uri` (its bytes are in model/cube.bin).
    std::string errorWithUri(const std::string& uri) const {
        const GltfBuilder cube = cubeModel();
        GltfBuilder::writeBytes(model("cube.bin"), cube.bin);
        GltfBuilder::writeText(model("cube.gltf"), cube.withBuffer(uri).dump());
        return importError(model("cube.gltf"));
    }
    // The cube with `value` at the JSON `pointer` (null: removed).
    std::string errorWith(const std::string& pointer, const Json& value) const {
        GltfBuilder cube = cubeModel();
        Json document = cube.withBuffer("cube.bin");
        const Json::json_pointer at(pointer);
        if (value.is_null()) {
            document[at.parent_pointer()].erase(at.back());
        } else {
            document[at] = value;
        }
        GltfBuilder::writeBytes(model("cube.bin"), cube.bin);
        GltfBuilder::writeText(model("cube.gltf"), document.dump());
        return importError(model("cube.gltf"));
    }
};

TEST_F(GltfHostile, TheUnchangedCubeLoads) {
    EXPECT_EQ(errorWithUri("cube.bin"), "(loaded)");
    EXPECT_EQ(errorWithUri("./sub/../cube.bin"), "(loaded)");   // `..` that stays inside is fine
}

TEST_F(GltfHostile, PathsLeavingTheFolderAreRefused) {
    const std::string file = model("cube.gltf").string();
    std::string error = errorWithUri("../secret.bin");
    EXPECT_ERROR(error, file + ": '../secret.bin' leads outside the model's folder");
    EXPECT_ERROR(errorWithUri("sub/../../secret.bin"), "leads outside the model's folder");
    EXPECT_ERROR(errorWithUri("%2E%2E/secret.bin"), "'../secret.bin' leads outside");   // decoded first
    EXPECT_ERROR(errorWithUri(path("secret.bin").string()), "is an absolute path");
    EXPECT_ERROR(errorWithUri("%2F" + path("secret.bin").string().substr(1)), "is an absolute path");
    EXPECT_ERROR(errorWithUri(std::string("cube.bin\0../x", 13)), "'cube.bin?../x' contains a NUL character");
}

TEST_F(GltfHostile, TheWorkingDirectoryIsNotSearched) {
    // tinygltf tries "./URI" when the file is not beside the model: that must not find bait.
    GltfBuilder::writeBytes(path("only-here.bin"), cubeModel().bin);
    const fs::path before = fs::current_path();
    fs::current_path(dir_);
    const std::string error = errorWithUri("only-here.bin");
    fs::current_path(before);
    EXPECT_ERROR(error, "only-here.bin");
    EXPECT_NE(error, "(loaded)");
}

TEST_F(GltfHostile, SymbolicLinksOutOfTheFolderAreRefused) {
    fs::create_symlink(path("secret.bin"), model("link.bin"));
    EXPECT_ERROR(errorWithUri("link.bin"), "'link.bin' leads outside the model's folder through a symbolic link");
    fs::create_directory_symlink(dir_, model("up"));
    EXPECT_ERROR(errorWithUri("up/secret.bin"), "through a symbolic link");
    // A folder whose name starts with the model folder's is still outside it.
    fs::create_directory(path("model-other"));
    fs::copy_file(path("secret.bin"), path("model-other/secret.bin"));
    fs::create_symlink(path("model-other/secret.bin"), model("sibling.bin"));
    EXPECT_ERROR(errorWithUri("sibling.bin"), "through a symbolic link");
    fs::create_symlink("cube.bin", model("alias.bin"));   // a link that stays inside is fine
    EXPECT_EQ(errorWithUri("alias.bin"), "(loaded)");
}

TEST_F(GltfHostile, RemoteAndOtherUrisAreRefused) {
    for (const std::string uri : {"http://example.com/cube.bin", "https://example.com/cube.bin",
                                  "file:///etc/passwd", "ftp://example.com/x", "data:text/html,hello",
                                  "data:application/octet-stream,raw", "c:cube.bin"}) {
        EXPECT_ERROR(errorWithUri(uri), "'" + uri + "' is a remote or non-file URI") << uri;
    }
}

TEST_F(GltfHostile, MissingAndNonRegularFilesAreNamed) {
    EXPECT_ERROR(errorWithUri("nothing.bin"), "nothing.bin");
    fs::create_directory(model("folder.bin"));
    EXPECT_ERROR(errorWithUri("folder.bin"), "'folder.bin' is not a regular file");
    EXPECT_ERROR(importError(model("folder.bin")), "a folder, not a file");
    EXPECT_ERROR(importError(model("absent.gltf")), model("absent.gltf").string() + ": cannot open");
}

TEST_F(GltfHostile, FilesAreLimitedInSizeBeforeTheyAreRead) {
    // Sparse files: their size is what counts, and they cost no disk.
    std::ofstream(model("huge.bin")).close();
    fs::resize_file(model("huge.bin"), (uint64_t(600) << 20));
    EXPECT_ERROR(errorWithUri("huge.bin"), "'huge.bin': the file is 600 MiB; files are limited to 512 MiB");
    std::ofstream(model("huge.gltf")).close();
    fs::resize_file(model("huge.gltf"), (uint64_t(600) << 20));
    EXPECT_ERROR(importError(model("huge.gltf")), "huge.gltf: the file is 600 MiB");
    // Three 400 MiB images (read, never decoded) pass the 1 GiB for all of a model's files.
    fs::resize_file(model("huge.bin"), (uint64_t(400) << 20));
    GltfBuilder cube = cubeModel();
    Json document = cube.withBuffer("cube.bin");
    document["images"] = Json::array({{{"uri", "huge.bin"}}, {{"uri", "huge.bin"}}, {{"uri", "huge.bin"}}});
    GltfBuilder::writeBytes(model("cube.bin"), cube.bin);
    GltfBuilder::writeText(model("cube.gltf"), document.dump());
    EXPECT_ERROR(importError(model("cube.gltf")), "passes the limit of 1024 MiB for all its files");
    // Images follow the same rules as buffers.
    document["images"] = Json::array({{{"uri", "../secret.bin"}}});
    GltfBuilder::writeText(model("cube.gltf"), document.dump());
    EXPECT_ERROR(importError(model("cube.gltf")), "'../secret.bin' leads outside");
}

TEST_F(GltfHostile, HugeDeclaredCountsAreRefusedBeforeAllocating) {
    EXPECT_ERROR(errorWith("/accessors/0/count", uint64_t(1) << 62),
                 "/accessors/0 (/meshes/0/primitives/0/attributes/POSITION): 4611686018427387904 elements");
    EXPECT_ERROR(errorWith("/accessors/2/count", std::numeric_limits<uint64_t>::max()), "run past the end");
    EXPECT_ERROR(errorWith("/bufferViews/0/byteLength", uint64_t(1) << 62), "/bufferViews/0: bytes 0 + ");
    EXPECT_ERROR(errorWith("/buffers/0/byteLength", uint64_t(1) << 40), "size mismatch");   // the .bin's size
    // Many nodes showing one big mesh would make billions of vertices: refused from the counts.
    GltfBuilder model;
    const int positions = model.positions(std::vector<glm::vec3>(size_t(1) << 16, glm::vec3(0.0f)));
    model.meshNode({{"attributes", {{"POSITION", positions}}}});
    for (int i = 0; i < 300; ++i) {
        model.json["scenes"][0]["nodes"].push_back(model.add("nodes", {{"mesh", 0}}));
    }
    model.writeGlb(path("instances.glb"));
    EXPECT_ERROR(importError(path("instances.glb")), "the scene has more than 16777216 vertices");
    // And triangles: 65536 indices (21845 triangles) over 3 vertices, in 800 primitive instances.
    GltfBuilder fan;
    const int three = fan.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int indices = fan.data(std::vector<uint8_t>(size_t(1) << 16, 0), test::kUnsignedByte, "SCALAR", 1);
    const Json primitive{{"attributes", {{"POSITION", three}}}, {"indices", indices}};
    fan.meshNode(primitive);
    fan.json["meshes"][0]["primitives"] = Json(std::vector<Json>(100, primitive));
    for (int i = 0; i < 7; ++i) {
        fan.json["scenes"][0]["nodes"].push_back(fan.add("nodes", {{"mesh", 0}}));
    }
    fan.writeGlb(path("triangles.glb"));
    EXPECT_ERROR(importError(path("triangles.glb")), "or 16777216 triangles (Patina's limit)");
    // Likewise many primitives: 2000 per mesh in 132 nodes.
    GltfBuilder many = cubeModel();
    Json& primitives = many.json["meshes"][0]["primitives"];
    while (primitives.size() < 2000) {
        primitives.push_back(primitives[0]);
    }
    for (int i = 0; i < 132; ++i) {
        many.json["scenes"][0]["nodes"].push_back(many.add("nodes", {{"mesh", 0}}));
    }
    many.writeGlb(path("primitives.glb"));
    EXPECT_ERROR(importError(path("primitives.glb")), "draws more than 262144 mesh primitives");
}

TEST_F(GltfHostile, AccessorsAndViewsPastTheirBuffersAreRefused) {
    EXPECT_ERROR(errorWith("/accessors/0/count", 25), "25 elements of 12 bytes, 12 apart, from byte 0 run past "
                                                       "the end of buffer view 0 (288 bytes)");
    EXPECT_ERROR(errorWith("/accessors/0/byteOffset", 4), "from byte 4 run past the end of buffer view 0");
    EXPECT_ERROR(errorWith("/accessors/0/byteOffset", 1000), "run past the end of buffer view 0");
    EXPECT_ERROR(errorWith("/bufferViews/2/byteOffset", 600), "/bufferViews/2: bytes 600 + 72 run past the end of "
                                                              "buffer 0");
    EXPECT_ERROR(errorWith("/bufferViews/0/byteStride", 4), "byteStride 4 is less than the 12 bytes");
    EXPECT_ERROR(errorWith("/bufferViews/0/byteStride", 16), "24 elements of 12 bytes, 16 apart");
}

TEST_F(GltfHostile, IndicesOutOfRangeAreRefused) {
    const std::vector<glm::vec3> triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (const int type : {test::kUnsignedByte, test::kUnsignedShort, test::kUnsignedInt}) {
        GltfBuilder model;
        const int positions = model.positions(triangle);
        const int indices = type == test::kUnsignedByte ? model.data(std::vector<uint8_t>{0, 1, 3}, type, "SCALAR", 1)
                            : type == test::kUnsignedShort
                                ? model.data(std::vector<uint16_t>{0, 1, 3}, type, "SCALAR", 1)
                                : model.data(std::vector<uint32_t>{0, 1, 3}, type, "SCALAR", 1);
        model.meshNode({{"attributes", {{"POSITION", positions}}}, {"indices", indices}});
        model.writeGlb(path("bad.glb"));
        EXPECT_ERROR(importError(path("bad.glb")),
                     "/meshes/0/primitives/0/indices: element 2 is 3 but the primitive has 3 vertices");
    }
}

TEST_F(GltfHostile, WrongTypesAreRefusedWithThePlace) {
    const struct {
        const char* pointer;
        Json value;
        const char* message;
    } cases[] = {
        {"/accessors/0/type", "VEC2", "/accessors/0 (/meshes/0/primitives/0/attributes/POSITION): must be VEC3 of "
                                      "FLOAT, not VEC2 of FLOAT"},
        {"/accessors/0/componentType", 5123, "not VEC3 of UNSIGNED_SHORT"},
        {"/accessors/0/normalized", true, "not normalized VEC3 of FLOAT"},
        {"/accessors/1/type", "VEC4", "/accessors/1 (/meshes/0/primitives/0/attributes/NORMAL): must be VEC3"},
        {"/accessors/2/componentType", 5126, "must be SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not "
                                             "SCALAR of FLOAT"},
        {"/accessors/2/type", "VEC3", "not VEC3 of UNSIGNED_SHORT"},
        {"/accessors/0/componentType", 5130, "not VEC3 of component type 5130"},
        {"/accessors/0/count", "24", "count"},
        {"/accessors/1/count", 23, "/meshes/0/primitives/0/attributes/NORMAL: 23 normals for 24 positions"},
        {"/accessors/0/sparse", {{"count", 25}, {"indices", {{"bufferView", 2}, {"componentType", 5123}}},
                                 {"values", {{"bufferView", 0}}}},
         "/accessors/0/sparse/count: 25 must be from 1 to the accessor's 24 elements"},
        {"/accessors/0/bufferView", 42, "/accessors/0 (/meshes/0/primitives/0/attributes/POSITION): buffer view 42"},
        {"/accessors/0/bufferView", nullptr, "buffer view -1 does not exist"},
        {"/bufferViews/0/buffer", 3, "/bufferViews/0: buffer 3 does not exist"},
        {"/meshes/0/primitives/0/mode", 9, "/meshes/0/primitives/0/mode: unknown mode 9"},
        {"/meshes/0/primitives/0/indices", 99, "primitive indices accessor out of bounds"},   // tinygltf's
        {"/meshes/0/primitives/0/indices", -2, "/meshes/0/primitives/0/indices: accessor -2 does not exist"},
        {"/meshes/0/primitives/0/attributes/POSITION", -2, "accessor -2 does not exist"},
        {"/nodes/0/mesh", 7, "/nodes/0/mesh: mesh 7 does not exist"},
        {"/nodes/0/matrix", Json::array({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0}),
         "/nodes/0/matrix: must have 16 numbers, not 15"},
        {"/nodes/0/translation", {1, 2}, "/nodes/0/translation: must have 3 numbers, not 2"},
        {"/nodes/0/rotation", {0, 0, 0, 0}, "/nodes/0/rotation: not a unit quaternion"},
        {"/nodes/0/rotation", {1e300, 1e300, 0, 0}, "/nodes/0/rotation: not a unit quaternion"},   // overflows
        {"/nodes/0/scale", {1, 2, 3, 4}, "/nodes/0/scale: must have 3 numbers"},
        {"/nodes/0/children", {0}, "/nodes/0: is its own ancestor (a cycle in the node hierarchy)"},
        {"/nodes/0/children", {5}, "/nodes/0/children: node 5 does not exist"},
        {"/scenes/0/nodes", {9}, "/scenes/0/nodes: node 9 does not exist"},
        {"/scenes/0/nodes", {0, 0}, "/scenes/0/nodes: node 0 is listed twice"},
        {"/scene", 4, "/scene: scene 4 does not exist"},
        {"/scene", -3, "/scene: scene -3 does not exist"},
        {"/materials/0/pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1}}}, "baseColorFactor"},
        {"/materials/0/extensions", {{"KHR_materials_ior", {{"ior", "glass"}}}},
         "/materials/0/extensions/KHR_materials_ior/ior: must be a number"},
        {"/materials/0/extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}, "/ior: 0.5 is below 1"},
        {"/materials/0/extensions", {{"KHR_materials_specular", {{"specularColorFactor", {1, 1}}}}},
         "/specularColorFactor: must be an array of 3 numbers"},
        {"/materials/0/extensions", {{"KHR_materials_specular", {{"specularColorFactor", {1, "x", 1}}}}},
         "/specularColorFactor/1: must be a number"},
        {"/materials/0/extensions", {{"KHR_materials_specular", {{"specularFactor", "1"}}}},
         "/specularFactor: must be a number"},
        {"/extensionsRequired", {"EXT_mesh_gpu_instancing"},
         "requires the extension EXT_mesh_gpu_instancing, which Patina does not draw"},
        {"/asset", nullptr, "asset"},
        {"/nodes/0/translation", {1e308, 0, 0}, "/nodes/0: its world transform is not finite in single precision"},
    };
    for (const auto& c : cases) {
        const std::string error = errorWith(c.pointer, c.value);
        EXPECT_ERROR(error, model("cube.gltf").string() + ": ") << c.pointer;
        EXPECT_ERROR(error, c.message) << c.pointer << " = " << c.value.dump();
    }
    EXPECT_EQ(errorWith("/extensionsRequired", {"KHR_materials_specular"}), "(loaded)");
    // ior 0: the schema's value for a converted specular-glossiness material (F0 1).
    EXPECT_EQ(errorWith("/materials/0/extensions", {{"KHR_materials_ior", {{"ior", 0}}}}), "(loaded)");
}

TEST_F(GltfHostile, NonFiniteBinaryValuesAreRefused) {
    for (const char* attribute : {"POSITION", "NORMAL"}) {
        GltfBuilder model = cubeModel();
        const size_t offset = std::string(attribute) == "POSITION" ? 0 : 288;
        const float nan = std::numeric_limits<float>::quiet_NaN();
        std::memcpy(model.bin.data() + offset + 12, &nan, sizeof nan);
        model.writeGlb(path("nan.glb"));
        EXPECT_ERROR(importError(path("nan.glb")), std::string(attribute) + ": element 1 is not finite");
    }
}

TEST_F(GltfHostile, JsonThatWouldExhaustTheParserIsRefused) {
    std::string deep = "0";
    for (int i = 0; i < 100; ++i) {
        deep = "[" + deep + "]";
    }
    EXPECT_ERROR(errorWith("/extras", Json::parse(deep)), "JSON nested deeper than 64 levels");
    EXPECT_ERROR(errorWith("/extras", Json(std::vector<int>(size_t(5) << 20, 0))), "more than 4194304 JSON values");
    EXPECT_ERROR(errorWith("/extras", Json::array({Json(std::vector<Json>(300000, Json::object()))})),
                 "more than 262144 objects");
    GltfBuilder::writeText(model("broken.gltf"), "{\"asset\": {\"version\": \"2.0\"},,}");
    EXPECT_ERROR(importError(model("broken.gltf")), "broken.gltf: invalid JSON: parse error at line 1, column 30");
    GltfBuilder::writeText(model("empty.gltf"), "");
    EXPECT_ERROR(importError(model("empty.gltf")), "empty.gltf: neither a glTF binary");
    // Bytes of another kind (a corrupt .glb, an image renamed) are said to be no glTF at all,
    // not a JSON syntax error at their first byte.
    GltfBuilder::writeText(model("noise.glb"), "JFIF\x01\x02 not a model");
    EXPECT_ERROR(importError(model("noise.glb")),
                 "noise.glb: neither a glTF binary (a .glb starts with \"glTF\") nor glTF JSON");
}

// A glTF 1.0 file breaks the 2.0 rules at its first dictionary ("/accessors: must be an
// array"), which does not say why: it is named for what it is, with what to do.
TEST_F(GltfHostile, AGltf1FileIsNamedForItsVersion) {
    GltfBuilder::writeText(model("old.gltf"), R"({"accessors": {"a": {"count": 3}}, "extras": [[[1]]],
        "asset": {"generator": "collada2gltf", "version": "1.0"}})");
    const std::string error = importError(model("old.gltf"));
    EXPECT_ERROR(error, "old.gltf: a glTF 1.0 file (asset.version \"1.0\"); Patina reads glTF 2.0 only");
    EXPECT_ERROR(error, "convert it to 2.0 first");
    // A 2.0 file that breaks the same rule keeps the rule's message.
    GltfBuilder::writeText(model("new.gltf"), R"({"accessors": {}, "asset": {"version": "2.0"}})");
    EXPECT_ERROR(importError(model("new.gltf")), "/accessors: must be an array, not an object");
    std::vector<uint8_t> glb1 = {'g', 'l', 'T', 'F', 1, 0, 0, 0, 20, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    GltfBuilder::writeBytes(model("old.glb"), glb1);
    EXPECT_ERROR(importError(model("old.glb")), "version 1 is not supported (only 2: this is a glTF 1.0 binary");
}

TEST_F(GltfHostile, AModelWithoutTrianglesIsRefused) {
    EXPECT_ERROR(errorWith("/scenes/0/nodes", Json::array()), "cube.gltf: the scene has no triangles");
    EXPECT_ERROR(errorWith("/meshes/0/primitives/0/mode", 1), "the scene has no triangles");   // lines only
}

// A valid GLB of the cube, to be broken.
std::vector<uint8_t> cubeGlb(const fs::path& file) {
    cubeModel().writeGlb(file);
    return readFileBytes(file);
}

void putU32(std::vector<uint8_t>& bytes, size_t offset, uint32_t value) {
    std::memcpy(bytes.data() + offset, &value, 4);
}

TEST_F(GltfHostile, TruncatedGlbIsRefusedAtEveryLength) {
    const std::vector<uint8_t> glb = cubeGlb(path("cube.glb"));
    for (size_t length = 0; length < glb.size(); ++length) {
        GltfBuilder::writeBytes(path("cut.glb"), std::vector<uint8_t>(glb.begin(), glb.begin() + long(length)));
        const std::string error = importError(path("cut.glb"));
        ASSERT_NE(error, "(loaded)") << length;
        if (length >= 12) {
            EXPECT_ERROR(error, "cut.glb: GLB: the header gives a length of " + std::to_string(glb.size()) +
                                    " bytes but the file has " + std::to_string(length) + " (truncated)");
        }
    }
}

TEST_F(GltfHostile, GlbLayoutIsCheckedBeforeAnyChunkIsRead) {
    const std::vector<uint8_t> glb = cubeGlb(path("cube.glb"));
    const uint32_t jsonLength = uint32_t(glb[12] | glb[13] << 8 | glb[14] << 16 | glb[15] << 24);
    const size_t binHeader = 20 + jsonLength;
    auto errorOf = [&](const std::function<void(std::vector<uint8_t>&)>& damage) {
        std::vector<uint8_t> bytes = glb;
        damage(bytes);
        GltfBuilder::writeBytes(path("bad.glb"), bytes);
        return importError(path("bad.glb"));
    };
    EXPECT_ERROR(errorOf([](auto& b) { putU32(b, 4, 1); }), "GLB: version 1 is not supported");
    EXPECT_ERROR(errorOf([](auto& b) { b.resize(b.size() + 4); }), "bytes but the file has");
    EXPECT_ERROR(errorOf([&](auto& b) { putU32(b, 12, jsonLength + 2); }), "is not a multiple of 4");
    EXPECT_ERROR(errorOf([&](auto& b) { putU32(b, 16, 0x004E4942); }), "the first chunk must be a non-empty JSON");
    // The BIN chunk's length counted without its own 8-byte header would still fit tinygltf's
    // check and let it copy 8 bytes past the end: refused here first.
    const uint32_t binLength = uint32_t(glb.size() - binHeader - 8);
    EXPECT_ERROR(errorOf([&](auto& b) { putU32(b, binHeader, binLength + 8); }), "run past the end of the file");
    EXPECT_ERROR(errorOf([&](auto& b) { putU32(b, binHeader + 4, 0x4E4F534A); }), "a second JSON chunk");
    // Unknown chunks are skipped, as the spec asks.
    std::vector<uint8_t> extra = glb;
    extra.insert(extra.end(), {4, 0, 0, 0, 'X', 'T', 'R', 'A', 1, 2, 3, 4});
    putU32(extra, 8, uint32_t(extra.size()));
    GltfBuilder::writeBytes(path("extra.glb"), extra);
    EXPECT_EQ(importError(path("extra.glb")), "(loaded)");
}

TEST_F(GltfHostile, OnlyTheFirstGlbBufferMayUseTheBinChunk) {
    // tinygltf would copy the whole BIN chunk once for every buffer without a uri.
    GltfBuilder cube = cubeModel();
    Json document = cube.json;
    document["buffers"] = Json::array({{{"byteLength", cube.bin.size()}}, {{"byteLength", cube.bin.size()}}});
    GltfBuilder::writeBytes(path("two.glb"), gltf::joinGlb(document.dump(), cube.bin.data(), cube.bin.size()));
    EXPECT_ERROR(importError(path("two.glb")),
                 "/buffers/1: only buffers[0] may take its data from the GLB's BIN chunk");
}

TEST_F(GltfHostile, ExceptionsInsideTinygltfBecomeInputErrors) {
    // An empty first buffer in a GLB makes tinygltf 2.7 throw std::out_of_range.
    GltfBuilder cube = cubeModel();
    Json document = cube.json;
    document["buffers"] = Json::array({{{"byteLength", 0}}});
    GltfBuilder::writeBytes(path("empty.glb"), gltf::joinGlb(document.dump(), cube.bin.data(), cube.bin.size()));
    EXPECT_ERROR(importError(path("empty.glb")), "empty.glb: ");
}

TEST_F(GltfHostile, NumbersTooLargeForADoubleAreRefused) {
    GltfBuilder cube = cubeModel();
    Json document = cube.withBuffer("cube.bin");
    document["materials"][0]["pbrMetallicRoughness"] = {{"metallicFactor", 12345}};
    std::string text = document.dump();
    text.replace(text.find("12345"), 5, "1e400");   // JSON allows it; a double cannot hold it
    GltfBuilder::writeBytes(model("cube.bin"), cube.bin);
    GltfBuilder::writeText(model("cube.gltf"), text);
    EXPECT_ERROR(importError(model("cube.gltf")), "cube.gltf: invalid JSON: number overflow parsing '1e400'");
}

TEST_F(GltfHostile, DamagedGlbBytesNeverCrash) {
    // Every byte of a small GLB flipped in turn: each load either works or is an InputError.
    const std::vector<uint8_t> glb = cubeGlb(path("cube.glb"));
    size_t refused = 0;
    for (size_t i = 0; i < glb.size(); ++i) {
        for (const uint8_t flip : {uint8_t(0x01), uint8_t(0x80), uint8_t(0xFF)}) {
            std::vector<uint8_t> bytes = glb;
            bytes[i] ^= flip;
            GltfBuilder::writeBytes(path("flip.glb"), bytes);
            refused += importError(path("flip.glb")) != "(loaded)";
        }
    }
    EXPECT_GT(refused, glb.size());
}

}  // namespace
}  // namespace patina
