// EXT_meshopt_compression: files compressed here by meshoptimizer's own encoders, laid out as
// gltfpack lays them (the streams in buffers[0], a fallback buffer with no data), read back
// against the same files uncompressed: the test cube, its normals and positions through the
// extension's filters, and assimp's real models; broken extension objects refused by name.
// EXT_texture_webp: a WebP image made by libwebp's encoder taken in place of the fallback.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
#include <fstream>
#include <iterator>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <webp/encode.h>

#include "compressed_cube.h"
#include "gltf/glb.h"
#include "gltf_builder.h"
#include "scratch_test.h"

namespace patina {
namespace {

using test::Cube;
using test::GltfBuilder;
using test::kFloat;

constexpr const char* kMeshopt = "EXT_meshopt_compression";

// What an accessor of `componentType` and `type` takes an element.
size_t elementSize(int componentType, const std::string& type) {
    const size_t component = componentType == 5126 || componentType == 5125 ? 4
                             : componentType == 5120 || componentType == 5121 ? 1
                                                                               : 2;
    const size_t count = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "VEC4" ? 4 : 16;
    return component * count;
}

// Each view an accessor reads, as "indices" or "attributes", with the stride of its elements.
struct ViewUse {
    bool indices = false;
    size_t stride = 0;
};
std::map<int, ViewUse> viewUses(const Json& json) {
    std::map<int, ViewUse> uses;
    const auto use = [&](int accessorIndex, bool indices) {
        const Json& accessor = json["accessors"][size_t(accessorIndex)];
        if (!accessor.contains("bufferView")) {
            return;
        }
        const int view = accessor["bufferView"];
        const Json& bufferView = json["bufferViews"][size_t(view)];
        const size_t size = elementSize(accessor["componentType"], accessor["type"]);
        uses[view] = {indices, indices ? size : bufferView.value("byteStride", size)};
    };
    for (const Json& mesh : json.value("meshes", Json::array())) {
        for (const Json& primitive : mesh["primitives"]) {
            for (const auto& [name, accessor] : primitive["attributes"].items()) {
                use(accessor, false);
            }
            if (primitive.contains("indices")) {
                use(primitive["indices"], true);
            }
        }
    }
    return uses;
}

// One view's bytes as meshoptimizer's stream, with the extension's mode; empty where the view's
// form is not one the extension takes (elements not of 4 bytes, byte indices).
std::vector<uint8_t> encodeView(const uint8_t* bytes, size_t count, const ViewUse& use, std::string& mode) {
    std::vector<uint8_t> stream;
    if (!use.indices) {
        mode = "ATTRIBUTES";
        stream.resize(meshopt_encodeVertexBufferBound(count, use.stride));
        stream.resize(meshopt_encodeVertexBuffer(stream.data(), stream.size(), bytes, count, use.stride));
        return stream;
    }
    std::vector<unsigned int> indices(count);
    for (size_t i = 0; i < count; ++i) {
        uint16_t shortIndex = 0;
        if (use.stride == 4) {
            std::memcpy(&indices[i], bytes + 4 * i, 4);
        } else {
            std::memcpy(&shortIndex, bytes + 2 * i, 2);
            indices[i] = shortIndex;
        }
    }
    const size_t vertices = indices.empty() ? 0 : *std::max_element(indices.begin(), indices.end()) + 1;
    mode = count % 3 == 0 ? "TRIANGLES" : "INDICES";
    stream.resize(mode == "TRIANGLES" ? meshopt_encodeIndexBufferBound(count, vertices)
                                      : meshopt_encodeIndexSequenceBound(count, vertices));
    stream.resize(mode == "TRIANGLES" ? meshopt_encodeIndexBuffer(stream.data(), stream.size(), indices.data(), count)
                                      : meshopt_encodeIndexSequence(stream.data(), stream.size(), indices.data(), count));
    return stream;
}

// The glTF (`json` with its one buffer `bin`) with every view its meshes read compressed where
// the extension can: buffers[0] holds the streams and the views left as they were (images'),
// buffers[1] is the fallback, without data. The extension is required, as gltfpack makes it.
GltfBuilder meshoptCompressed(Json json, const std::vector<uint8_t>& bin) {
    GltfBuilder packed;
    const std::map<int, ViewUse> uses = viewUses(json);
    for (size_t v = 0; v < json["bufferViews"].size(); ++v) {
        Json& view = json["bufferViews"][v];
        const uint8_t* bytes = bin.data() + view.value("byteOffset", size_t(0));
        const size_t length = view["byteLength"];
        const auto use = uses.find(int(v));
        std::string mode;
        const bool fits = use != uses.end() && use->second.stride % (use->second.indices ? 2 : 4) == 0 &&
                          length % use->second.stride == 0;
        const std::vector<uint8_t> stream = fits ? encodeView(bytes, length / use->second.stride, use->second, mode)
                                                 : std::vector<uint8_t>(bytes, bytes + length);
        const size_t offset = (packed.bin.size() + 3) & ~size_t(3);
        packed.bin.resize(offset);
        packed.bin.insert(packed.bin.end(), stream.begin(), stream.end());
        if (fits) {
            view["buffer"] = 1;   // its place in the fallback: where it was
            view["extensions"][kMeshopt] = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", stream.size()},
                                            {"byteStride", use->second.stride}, {"count", length / use->second.stride},
                                            {"mode", mode}};
        } else {
            view["byteOffset"] = offset;
        }
    }
    json["buffers"] = Json::array({Json{{"byteLength", packed.bin.size()}},
                                   Json{{"byteLength", bin.size()}, {"extensions", {{kMeshopt, {{"fallback", true}}}}}}});
    for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
        json[list].push_back(kMeshopt);
    }
    packed.json = json;
    return packed;
}

// GltfBuilder writes its own buffers[0]; a packed file keeps its two.
void writePacked(const GltfBuilder& packed, const std::filesystem::path& path) {
    if (path.extension() == ".glb") {
        GltfBuilder::writeBytes(path, gltf::joinGlb(packed.json.dump(), packed.bin.data(), packed.bin.size()));
        return;
    }
    Json json = packed.json;
    json["buffers"][0]["uri"] = path.stem().string() + ".bin";
    GltfBuilder::writeBytes(path.parent_path() / (path.stem().string() + ".bin"), packed.bin);
    GltfBuilder::writeText(path, json.dump());
}

class GltfMeshopt : public test::ScratchTest {
protected:
    Cube cube;
    std::vector<glm::vec2> uvs = test::cubeUvs(cube);
    GltfBuilder plain = test::plainCube(cube, uvs);
    GltfBuilder packed = meshoptCompressed(plain.withBuffer("plain.bin"), plain.bin);

    std::string errorOf(const GltfBuilder& file) {
        const std::filesystem::path path = this->path("broken.glb");
        writePacked(file, path);
        return test::modelError(path);
    }
};

TEST_F(GltfMeshopt, ACompressedCubeReadsAsTheSameCubeFromAGltfAndAGlb) {
    plain.writeGltf(path("plain.gltf"));
    const Model uncompressed = importGltfModel(path("plain.gltf"));
    ASSERT_EQ(packed.json["bufferViews"][0]["extensions"][kMeshopt]["mode"], "ATTRIBUTES");
    ASSERT_EQ(packed.json["bufferViews"][3]["extensions"][kMeshopt]["mode"], "TRIANGLES");
    for (const char* name : {"meshopt.gltf", "meshopt.glb"}) {
        SCOPED_TRACE(name);
        writePacked(packed, path(name));
        const Model compressed = importGltfModel(path(name));
        ASSERT_EQ(compressed.primitives.size(), 1u);
        EXPECT_EQ(compressed.primitives[0].positions, uncompressed.primitives[0].positions);
        EXPECT_EQ(test::triangleSoup(compressed.primitives[0]), test::triangleSoup(uncompressed.primitives[0]));
        ASSERT_EQ(compressed.extensions.size(), 1u);
        EXPECT_EQ(compressed.extensions[0].name, kMeshopt);
        EXPECT_EQ(compressed.extensions[0].support, ExtensionSupport::Drawn);
        EXPECT_TRUE(compressed.notes.empty()) << compressed.notes.front();
    }
}

// The filters: normals as 8-bit octahedral (KHR_mesh_quantization's normalized bytes), positions
// as exponent and 16-bit mantissa; each decodes within its step.
TEST_F(GltfMeshopt, FilteredNormalsAndPositionsDecodeWithinTheirStep) {
    GltfBuilder gltf = plain;
    std::vector<float> normals4;
    for (const glm::vec3& n : cube.normals) {
        normals4.insert(normals4.end(), {n.x, n.y, n.z, 0.0f});
    }
    std::vector<int8_t> octahedral(normals4.size());
    meshopt_encodeFilterOct(octahedral.data(), cube.normals.size(), 4, 8, normals4.data());
    std::vector<float> positions = GltfBuilder::flatten(cube.positions);
    std::vector<uint32_t> exponential(positions.size());
    meshopt_encodeFilterExp(exponential.data(), cube.positions.size(), 12, 16, positions.data());
    // The filtered bytes go in the plain views' places; the encoder then compresses them.
    const int normalView = gltf.view(octahedral), positionView = gltf.view(exponential);
    gltf.json["accessors"][0]["bufferView"] = positionView;
    gltf.json["accessors"][1] = {{"bufferView", normalView}, {"componentType", 5120}, {"normalized", true},
                                 {"count", cube.normals.size()}, {"type", "VEC3"}};
    gltf.json["bufferViews"][size_t(normalView)]["byteStride"] = 4;
    gltf.json["extensionsUsed"] = {"KHR_mesh_quantization"};
    gltf.json["extensionsRequired"] = {"KHR_mesh_quantization"};
    GltfBuilder filtered = meshoptCompressed(gltf.withBuffer("f.bin"), gltf.bin);
    filtered.json["bufferViews"][size_t(normalView)]["extensions"][kMeshopt]["filter"] = "OCTAHEDRAL";
    filtered.json["bufferViews"][size_t(positionView)]["extensions"][kMeshopt]["filter"] = "EXPONENTIAL";
    writePacked(filtered, path("filtered.glb"));
    const Model model = importGltfModel(path("filtered.glb"));
    ASSERT_EQ(model.primitives.size(), 1u);
    const Mesh& mesh = model.primitives[0];
    ASSERT_EQ(mesh.positions.size(), cube.positions.size());
    for (size_t i = 0; i < cube.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(mesh.positions[i] - cube.positions[i]), 0.0f, 1e-4f) << i;
        EXPECT_NEAR(glm::length(mesh.normals[i] - cube.normals[i]), 0.0f, 2.0f / 127.0f) << i;
    }
    // Without the filter the same bytes are not the cube: the filter was applied.
    filtered.json["bufferViews"][size_t(positionView)]["extensions"][kMeshopt].erase("filter");
    writePacked(filtered, path("unfiltered.glb"));
    EXPECT_NE(importGltfModel(path("unfiltered.glb")).primitives[0].positions, mesh.positions);
}

TEST_F(GltfMeshopt, ABrokenStreamOrExtensionIsRefusedByName) {
    const std::string at = "/bufferViews/0/extensions/EXT_meshopt_compression";
    const auto broken = [&](const char* key, const Json& value) {
        GltfBuilder file = packed;
        file.json["bufferViews"][0]["extensions"][kMeshopt][key] = value;
        return errorOf(file);
    };
    EXPECT_ERROR(broken("byteOffset", 1u << 20), at + ": its stream");
    EXPECT_ERROR(broken("mode", "LINES"), at + "/mode: 'LINES': ATTRIBUTES, TRIANGLES or INDICES");
    EXPECT_ERROR(broken("byteStride", 6), at + "/byteStride: 6: ATTRIBUTES take a multiple of 4 up to 256");
    EXPECT_ERROR(broken("filter", "QUATERNION"), at + "/filter: 'QUATERNION' with a stride of 12");
    EXPECT_ERROR(broken("count", 1u << 30), at + "/count: 1073741824 elements of 12 bytes would take");
    EXPECT_ERROR(broken("byteLength", 5), at + ": the ATTRIBUTES stream does not decode");
    EXPECT_ERROR(broken("buffer", 7), "/bufferViews/0/extensions/EXT_meshopt_compression/buffer: buffer 7 does not exist");
    EXPECT_ERROR(broken("mode", 3), at + "/mode: must be a string");
    GltfBuilder triangles = packed;
    triangles.json["bufferViews"][3]["extensions"][kMeshopt]["count"] = 35;
    EXPECT_ERROR(errorOf(triangles), "/bufferViews/3/extensions/EXT_meshopt_compression/count: 35 is not a whole "
                                     "number of triangles");
    GltfBuilder noCount = packed;
    noCount.json["bufferViews"][0]["extensions"][kMeshopt].erase("count");
    EXPECT_ERROR(errorOf(noCount), at + ": has no count");
    // A buffer without data in a GLB that is no meshopt fallback still takes the BIN chunk's rule.
    GltfBuilder notFallback = packed;
    notFallback.json["buffers"][1]["extensions"][kMeshopt]["fallback"] = false;
    EXPECT_ERROR(errorOf(notFallback), "/buffers/1: only buffers[0] may take its data from the GLB's BIN chunk");
}

// assimp's real models, every mesh view compressed: the same triangles, the textured box's
// image (a view left uncompressed beside the streams) as before.
TEST_F(GltfMeshopt, RealModelsCompressedDrawTheirUncompressedTriangles) {
    const std::filesystem::path models = "/usr/share/assimp/models/glTF2";
    for (const char* name : {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "BoxTextured-glTF-Binary/BoxTextured.glb"}) {
        SCOPED_TRACE(name);
        const std::filesystem::path original = models / name;
        if (!std::filesystem::exists(original)) {
            GTEST_SKIP() << "assimp-testmodels is not installed";
        }
        std::ifstream in(original, std::ios::binary);
        const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
        const gltf::GlbChunks glb = gltf::splitGlb(bytes, name);
        const std::vector<uint8_t> bin(glb.bin, glb.bin + glb.binSize);
        const GltfBuilder packed = meshoptCompressed(parseJsonText(std::string(glb.json), name), bin);
        const std::filesystem::path path = this->path(original.filename().string());
        writePacked(packed, path);
        const Model compressed = importGltfModel(path), uncompressed = importGltfModel(original);
        ASSERT_EQ(compressed.primitives.size(), uncompressed.primitives.size());
        for (size_t i = 0; i < compressed.primitives.size(); ++i) {
            EXPECT_EQ(compressed.primitives[i].positions, uncompressed.primitives[i].positions) << i;
            EXPECT_EQ(test::triangleSoup(compressed.primitives[i]), test::triangleSoup(uncompressed.primitives[i])) << i;
        }
        ASSERT_EQ(compressed.images.size(), uncompressed.images.size());
        for (size_t i = 0; i < compressed.images.size(); ++i) {
            EXPECT_EQ(compressed.images[i].rgba, uncompressed.images[i].rgba) << i;
        }
    }
}

// A texture with EXT_texture_webp: its WebP image (lossless, so its pixels are known) is drawn,
// not the PNG fallback; a WebP that does not decode is a note and its map left out.
TEST_F(GltfMeshopt, AWebpTextureTakesItsWebpImageInPlaceOfTheFallback) {
    const std::vector<uint8_t> pixels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};
    uint8_t* encoded = nullptr;
    const size_t size = WebPEncodeLosslessRGBA(pixels.data(), 2, 2, 8, &encoded);
    ASSERT_GT(size, 0u);
    const std::vector<uint8_t> webp(encoded, encoded + size);
    WebPFree(encoded);
    GltfBuilder file = test::cubeModel();
    const int webpView = file.view(webp);
    const int webpImage = file.add("images", {{"bufferView", webpView}, {"mimeType", "image/webp"}});
    const int pngImage = file.add("images", {{"uri", "missing.png"}});
    file.add("textures", {{"source", pngImage}, {"extensions", {{"EXT_texture_webp", {{"source", webpImage}}}}}});
    file.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    file.json["extensionsUsed"] = {"EXT_texture_webp"};
    file.writeGlb(path("webp.glb"));
    const Model model = importGltfModel(path("webp.glb"));
    ASSERT_EQ(model.images.size(), 1u);
    EXPECT_EQ(model.images[0].width, 2);
    EXPECT_EQ(model.images[0].rgba, pixels);
    EXPECT_TRUE(model.materials[0].baseColor.present());
    ASSERT_EQ(model.extensions.size(), 1u);
    EXPECT_EQ(model.extensions[0].support, ExtensionSupport::Drawn);

    file.bin[file.json["bufferViews"][size_t(webpView)]["byteOffset"].get<size_t>() + 20] ^= 0xff;
    file.writeGlb(path("broken_webp.glb"));
    const Model broken = importGltfModel(path("broken_webp.glb"));
    EXPECT_TRUE(broken.images.empty());
    EXPECT_FALSE(broken.materials[0].baseColor.present());
    ASSERT_FALSE(broken.notes.empty());
    EXPECT_ERROR(broken.notes.front(), "/images/0");
}

}  // namespace
}  // namespace patina
