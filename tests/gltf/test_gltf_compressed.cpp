// Compressed meshes. KHR_draco_mesh_compression: streams made here by libdraco's encoder from
// the test cube, read back against the same cube uncompressed; broken streams and extension
// objects refused by name; Draco files from other writers against their uncompressed twins.
// KHR_mesh_quantization: the cube's attributes as 8- and 16-bit integers.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <array>
#include <filesystem>
#include <memory>
#include <vector>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <glm/vec2.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "compressed_cube.h"
#include "gltf_builder.h"
#include "scratch_test.h"

namespace patina {
namespace {

using test::Corner;
using test::cubeUvs;
using test::expectNear;
using test::plainCube;
using test::triangleSoup;
using test::Cube;
using test::GltfBuilder;
using test::kFloat;
using test::kUnsignedByte;
using test::kUnsignedInt;
constexpr int kByte = 5120, kShort = 5122;

// The cube's triangles as one Draco stream (no quantization: lossless), and its attributes' ids.
struct Stream {
    std::vector<uint8_t> bytes;
    uint32_t position = 0, normal = 0, uv = 0;
    size_t points = 0, corners = 0;   // as a decoder reads them back
};

Stream encodeCube(const Cube& cube, const std::vector<glm::vec2>& uvs) {
    draco::TriangleSoupMeshBuilder builder;
    const size_t faces = cube.indices.size() / 3;
    builder.Start(int(faces));
    const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int normal = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
    const int uv = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
    for (size_t f = 0; f < faces; ++f) {
        const uint32_t* c = &cube.indices[3 * f];
        const draco::FaceIndex face{uint32_t(f)};
        builder.SetAttributeValuesForFace(position, face, &cube.positions[c[0]], &cube.positions[c[1]],
                                          &cube.positions[c[2]]);
        builder.SetAttributeValuesForFace(normal, face, &cube.normals[c[0]], &cube.normals[c[1]], &cube.normals[c[2]]);
        builder.SetAttributeValuesForFace(uv, face, &uvs[c[0]], &uvs[c[1]], &uvs[c[2]]);
    }
    const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    draco::Encoder encoder;
    draco::EncoderBuffer buffer;
    EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &buffer).ok());
    Stream stream{{buffer.data(), buffer.data() + buffer.size()},
                  mesh->attribute(position)->unique_id(),
                  mesh->attribute(normal)->unique_id(),
                  mesh->attribute(uv)->unique_id()};
    draco::DecoderBuffer in;
    in.Init(buffer.data(), buffer.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&in);
    EXPECT_TRUE(decoded.ok());
    stream.points = decoded.value()->num_points();
    stream.corners = size_t(decoded.value()->num_faces()) * 3;
    return stream;
}

// The compressed cube as glTF: accessors without views (0-2 the attributes, 3 the indices), the
// stream in a view, the extension required.
GltfBuilder dracoCube(const Stream& stream) {
    GltfBuilder gltf;
    const auto accessor = [&](size_t count, const char* type, int componentType) {
        return gltf.add("accessors", {{"componentType", componentType}, {"count", count}, {"type", type}});
    };
    const int position = accessor(stream.points, "VEC3", kFloat);
    const int normal = accessor(stream.points, "VEC3", kFloat);
    const int uv = accessor(stream.points, "VEC2", kFloat);
    const int indices = accessor(stream.corners, "SCALAR", kUnsignedInt);
    const int view = gltf.view(stream.bytes);
    gltf.meshNode({{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}},
                   {"indices", indices},
                   {"extensions",
                    {{"KHR_draco_mesh_compression",
                      {{"bufferView", view},
                       {"attributes",
                        {{"POSITION", stream.position}, {"NORMAL", stream.normal}, {"TEXCOORD_0", stream.uv}}}}}}}});
    gltf.json["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    gltf.json["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    return gltf;
}

// The sum of the mesh's triangles' areas.
float surfaceArea(const Mesh& mesh) {
    double area = 0.0;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                        c = mesh.positions[mesh.indices[t + 2]];
        area += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
    }
    return float(area);
}

class GltfCompressed : public test::ScratchTest {
protected:
    Cube cube;
    std::vector<glm::vec2> uvs = cubeUvs(cube);
    Stream stream = encodeCube(cube, uvs);

    std::string errorOf(GltfBuilder gltf) {
        const std::filesystem::path path = this->path("broken.gltf");
        gltf.writeGltf(path);
        try {
            importGltfModel(path);
        } catch (const InputError& error) {
            return error.what();
        }
        return "(no error)";
    }
};

TEST_F(GltfCompressed, ACompressedCubeReadsAsTheSameCubeUncompressedFromAGltfAndAGlb) {
    plainCube(cube, uvs).writeGltf(path("plain.gltf"));
    const Model plain = importGltfModel(path("plain.gltf"));
    ASSERT_EQ(plain.primitives.size(), 1u);
    dracoCube(stream).writeGltf(path("draco.gltf"));
    dracoCube(stream).writeGlb(path("draco.glb"));
    for (const char* name : {"draco.gltf", "draco.glb"}) {
        SCOPED_TRACE(name);
        const Model draco = importGltfModel(path(name));
        ASSERT_EQ(draco.primitives.size(), 1u);
        EXPECT_EQ(draco.primitives[0].indices.size(), cube.indices.size());
        EXPECT_EQ(triangleSoup(draco.primitives[0]), triangleSoup(plain.primitives[0]));
        ASSERT_FALSE(draco.extensions.empty());
        EXPECT_EQ(draco.extensions[0].support, ExtensionSupport::Drawn);
    }
}

TEST_F(GltfCompressed, ABrokenStreamOrExtensionIsRefusedByName) {
    const std::string at = "/meshes/0/primitives/0/extensions/KHR_draco_mesh_compression";
    GltfBuilder truncated = dracoCube(stream);
    truncated.json["bufferViews"][0]["byteLength"] = stream.bytes.size() / 2;
    EXPECT_ERROR(errorOf(truncated), at + ": the compressed mesh does not decode (Draco: ");

    GltfBuilder noSuchId = dracoCube(stream);
    noSuchId.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["NORMAL"] = 9;
    EXPECT_ERROR(errorOf(noSuchId), at + "/attributes/NORMAL: the compressed mesh has no attribute 9");

    GltfBuilder unnamed = dracoCube(stream);
    unnamed.json["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
    EXPECT_ERROR(errorOf(unnamed), at + "/attributes/NORMAL: the primitive has no attribute NORMAL");

    GltfBuilder miscounted = dracoCube(stream);
    for (int accessor = 0; accessor < 3; ++accessor) {   // the attributes agree, the stream does not
        miscounted.json["accessors"][accessor]["count"] = stream.points - 1;
    }
    EXPECT_ERROR(errorOf(miscounted), "/meshes/0/primitives/0/attributes/POSITION (compressed): the compressed mesh has " +
                                          std::to_string(stream.points) + " where the accessor says " +
                                          std::to_string(stream.points - 1));

    GltfBuilder outside = dracoCube(stream);
    outside.json["bufferViews"][0]["byteOffset"] = 1 << 20;
    EXPECT_ERROR(errorOf(outside), "/bufferViews/0: bytes 1048576 + " + std::to_string(stream.bytes.size()) +
                                       " run past the end of buffer 0");

    // Patina moves a primitive's `indices` into the extension for tinygltf; one a file put there
    // itself must name an accessor too.
    GltfBuilder strayIndices = dracoCube(stream);
    Json& primitive = strayIndices.json["meshes"][0]["primitives"][0];
    primitive.erase("indices");
    primitive["extensions"]["KHR_draco_mesh_compression"]["indices"] = "three";
    EXPECT_ERROR(errorOf(strayIndices), "/meshes/0/primitives/0/indices: not the index of an accessor");

    GltfBuilder noView = dracoCube(stream);
    noView.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] = "zero";
    EXPECT_ERROR(errorOf(noView), at + "/bufferView");
}

// An integer accessor over `numbers` times `scale`, rounded to `T`, each element on a 4-byte
// boundary (section 3.6.2.4).
template <typename T>
int quantized(GltfBuilder& gltf, const std::vector<float>& numbers, float scale, int componentType, bool normalized,
              const char* type, size_t components) {
    const size_t count = numbers.size() / components;
    const size_t elementBytes = components * sizeof(T), stride = (elementBytes + 3) & ~size_t(3);
    std::vector<uint8_t> bytes(count * stride, 0);
    for (size_t i = 0; i < numbers.size(); ++i) {
        const T value = T(std::lround(numbers[i] * scale));
        std::memcpy(bytes.data() + i / components * stride + i % components * sizeof(T), &value, sizeof(T));
    }
    const int view = gltf.view(bytes);
    gltf.json["bufferViews"][size_t(view)]["byteStride"] = stride;
    return gltf.add("accessors", {{"bufferView", view},
                                  {"componentType", componentType},
                                  {"normalized", normalized},
                                  {"count", count},
                                  {"type", type}});
}

// The cube with KHR_mesh_quantization: positions as normalized shorts (0.5 as 16384 of 32767),
// normals as normalized bytes, texture coordinates as unsigned bytes, not normalized.
GltfBuilder quantizedCube(const Cube& cube, const std::vector<glm::vec2>& uvs) {
    GltfBuilder gltf;
    std::vector<float> uvNumbers;
    for (const glm::vec2& uv : uvs) {
        uvNumbers.insert(uvNumbers.end(), {uv.x, uv.y});
    }
    const int position =
        quantized<int16_t>(gltf, GltfBuilder::flatten(cube.positions), 32768.0f, kShort, true, "VEC3", 3);
    const int normal = quantized<int8_t>(gltf, GltfBuilder::flatten(cube.normals), 127.0f, kByte, true, "VEC3", 3);
    const int uv = quantized<uint8_t>(gltf, uvNumbers, 1.0f, kUnsignedByte, false, "VEC2", 2);
    const int indices = gltf.data(cube.indices, kUnsignedInt, "SCALAR", 1);
    gltf.meshNode({{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}},
                   {"indices", indices}});
    gltf.json["extensionsUsed"] = {"KHR_mesh_quantization"};
    gltf.json["extensionsRequired"] = {"KHR_mesh_quantization"};
    return gltf;
}

TEST_F(GltfCompressed, AQuantizedCubeReadsAsTheCubeWithinItsStep) {
    plainCube(cube, uvs).writeGltf(path("plain.gltf"));
    const Model plain = importGltfModel(path("plain.gltf"));
    GltfBuilder gltf = quantizedCube(cube, uvs);
    gltf.writeGlb(path("quantized.glb"));
    const Model model = importGltfModel(path("quantized.glb"));
    ASSERT_EQ(model.primitives.size(), 1u);
    expectNear(triangleSoup(model.primitives[0]), triangleSoup(plain.primitives[0]), 1.0f / 32767.0f);
    ASSERT_FALSE(model.extensions.empty());
    EXPECT_EQ(model.extensions[0].support, ExtensionSupport::Drawn);

    // Without the extension, glTF 2.0 itself allows floats only for positions.
    gltf.json.erase("extensionsUsed");
    gltf.json.erase("extensionsRequired");
    EXPECT_ERROR(errorOf(gltf), "(/meshes/0/primitives/0/attributes/POSITION): must be VEC3 of FLOAT, not normalized VEC3 of SHORT");
}

// A file from Google's own writer: draco_transcoder (Debian's `draco`) made
// tests/fuzz/corpus/glb/exported_draco.glb from exported.glb beside it, quantizing positions to
// 11 bits and normals to 8 and indexing with UNSIGNED_BYTE. It draws the same triangles.
TEST(GltfCompressedAsset, TheTranscodersFileDrawsTheTrianglesOfTheFileItCameFrom) {
    const std::filesystem::path corpus = std::filesystem::path(PATINA_SOURCE_DIR) / "tests/fuzz/corpus/glb";
    const Model draco = importGltfModel(corpus / "exported_draco.glb");
    const Model plain = importGltfModel(corpus / "exported.glb");
    ASSERT_EQ(draco.primitives.size(), 1u);
    ASSERT_EQ(plain.primitives.size(), 1u);
    // Positions within 3/2^11 of the box's size, normals within 2/2^8.
    expectNear(triangleSoup(draco.primitives[0]), triangleSoup(plain.primitives[0]), 2.0f / 256.0f);
}

// assimp-testmodels holds 2CylinderEngine twice: Draco-compressed (positions and normals
// quantized) and plain. The compressed one draws the same primitives over the same bounds,
// within the quantization's step of the model's size.
TEST(GltfCompressedAsset, TheCompressed2CylinderEngineDrawsAsItsUncompressedTwin) {
    const std::filesystem::path models = "/usr/share/assimp/models/glTF2";
    const std::filesystem::path draco = models / "draco/2CylinderEngine.gltf";
    const std::filesystem::path plain = models / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    if (!std::filesystem::exists(draco) || !std::filesystem::exists(plain)) {
        GTEST_SKIP() << "assimp-testmodels is not installed";
    }
    const Model compressed = importGltfModel(draco);
    const Model uncompressed = importGltfModel(plain);
    ASSERT_EQ(compressed.primitives.size(), uncompressed.primitives.size());
    for (size_t i = 0; i < compressed.primitives.size(); ++i) {
        // Draco's encoder leaves out triangles of no area (2CylinderEngine has many: up to 22% of
        // a primitive's) and adds none: the same surface, as much of it, in fewer triangles.
        EXPECT_LE(compressed.primitives[i].indices.size(), uncompressed.primitives[i].indices.size()) << i;
        const float area = surfaceArea(uncompressed.primitives[i]);
        EXPECT_NEAR(surfaceArea(compressed.primitives[i]), area, 0.01f * area) << i;
        glm::vec3 low(1e30f), high(-1e30f), plainLow(1e30f), plainHigh(-1e30f);
        for (const glm::vec3& p : compressed.primitives[i].positions) {
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
        for (const glm::vec3& p : uncompressed.primitives[i].positions) {
            plainLow = glm::min(plainLow, p);
            plainHigh = glm::max(plainHigh, p);
        }
        const float step = 1e-3f * std::max(1.0f, glm::length(plainHigh - plainLow));
        EXPECT_NEAR(glm::length(low - plainLow), 0.0f, step) << i;
        EXPECT_NEAR(glm::length(high - plainHigh), 0.0f, step) << i;
    }
}

}  // namespace
}  // namespace patina
