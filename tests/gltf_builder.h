#pragma once
// Hand-made glTF files for the tests: a JSON document and one binary buffer, written as a
// .gltf with a .bin beside it, a .gltf with a data: URI, or a .glb. Nothing is checked here:
// the tests break these files on purpose.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include "assets/asset_cache.h"
#include "gltf/glb.h"
#include "gltf/model_import.h"
#include "files/input_error.h"
#include "io/json_reader.h"

// `message` (an error) contains `part`; else the test fails, showing the message.
#define EXPECT_ERROR(message, part) \
    EXPECT_NE(std::string(message).find(part), std::string::npos) << "message: " << (message)

namespace patina::test {

// glTF component types.
constexpr int kUnsignedByte = 5121;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;

class GltfBuilder {
public:
    Json json{{"asset", {{"version", "2.0"}}}};
    std::vector<uint8_t> bin;

    // A buffer view of the values, 4-byte aligned in the buffer.
    template <typename T>
    int view(const std::vector<T>& values) {
        const size_t offset = (bin.size() + 3) & ~size_t(3);
        bin.resize(offset + values.size() * sizeof(T));
        std::memcpy(bin.data() + offset, values.data(), values.size() * sizeof(T));
        return add("bufferViews", {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
    }
    int accessor(int view, int componentType, size_t count, const char* type) {
        return add("accessors",
                   {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}});
    }
    // A view and an accessor over all the values: `components` numbers per element.
    template <typename T>
    int data(const std::vector<T>& values, int componentType, const char* type, size_t components) {
        return accessor(view(values), componentType, values.size() / components, type);
    }
    int positions(const std::vector<glm::vec3>& points) {
        return data(flatten(points), kFloat, "VEC3", 3);
    }
    // A mesh of one primitive, a node showing it, and that node in scene 0.
    int meshNode(const Json& primitive, Json node = Json::object()) {
        const int mesh = add("meshes", {{"primitives", Json::array({primitive})}});
        node["mesh"] = mesh;
        const int index = add("nodes", node);
        if (!json.contains("scenes")) {
            json["scenes"] = Json::array({Json{{"nodes", Json::array()}}});
        }
        json["scenes"][0]["nodes"].push_back(index);
        return index;
    }
    int add(const char* collection, const Json& value) {
        if (!json.contains(collection)) {
            json[collection] = Json::array();
        }
        json[collection].push_back(value);
        return int(json[collection].size()) - 1;
    }

    // The buffer as `binName` beside the .gltf (default: PATH.bin).
    void writeGltf(const std::filesystem::path& path, std::string binName = "") {
        if (binName.empty()) {
            binName = std::filesystem::path(path).replace_extension(".bin").filename().string();
        }
        writeBytes(path.parent_path() / binName, bin);
        writeText(path, withBuffer(binName).dump());
    }
    void writeGlb(const std::filesystem::path& path) const {
        Json document = json;
        document["buffers"] = Json::array({Json{{"byteLength", bin.size()}}});
        writeBytes(path, gltf::joinGlb(document.dump(), bin.data(), bin.size()));
    }
    // The document with buffers[0] = {byteLength, uri}.
    Json withBuffer(const std::string& uri) const {
        Json document = json;
        document["buffers"] = Json::array({Json{{"byteLength", bin.size()}, {"uri", uri}}});
        return document;
    }

    static std::vector<float> flatten(const std::vector<glm::vec3>& points) {
        std::vector<float> numbers;
        for (const glm::vec3& p : points) {
            numbers.insert(numbers.end(), {p.x, p.y, p.z});
        }
        return numbers;
    }
    // Each a new file: ext4 flushes a file truncated and written again, which costs
    // milliseconds in the tests that write thousands.
    static void writeText(const std::filesystem::path& path, const std::string& text) {
        writeBytes(path, std::vector<uint8_t>(text.begin(), text.end()));
    }
    static void writeBytes(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
        std::filesystem::remove(path);
        std::ofstream(path, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    }
};

// A unit cube centred at the origin: 24 vertices (4 per face, so each face has its own normal)
// and 12 counter-clockwise triangles.
struct Cube {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> indices;

    Cube() {
        for (int axis = 0; axis < 3; ++axis) {
            for (const float sign : {1.0f, -1.0f}) {
                glm::vec3 n(0.0f), u(0.0f), v(0.0f);
                n[axis] = sign;
                u[(axis + 1) % 3] = sign;
                v[(axis + 2) % 3] = 1.0f;   // u x v = n
                const uint32_t first = uint32_t(positions.size());
                for (const auto& [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
                    positions.push_back(0.5f * (n + float(a) * u + float(b) * v));
                    normals.push_back(n);
                }
                indices.insert(indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
            }
        }
    }
};

// The cube as a document: accessor 0 positions, 1 normals (when asked for), then the indices
// of `indexType` (0: none, the vertices repeated per corner instead), in one node of scene 0,
// with one material.
inline GltfBuilder cubeModel(bool withNormals = true, int indexType = kUnsignedShort) {
    const Cube cube;
    GltfBuilder model;
    std::vector<glm::vec3> positions = cube.positions, normals = cube.normals;
    if (indexType == 0) {
        positions.clear();
        normals.clear();
        for (const uint32_t i : cube.indices) {
            positions.push_back(cube.positions[i]);
            normals.push_back(cube.normals[i]);
        }
    }
    Json primitive{{"attributes", {{"POSITION", model.positions(positions)}}}};
    if (withNormals) {
        primitive["attributes"]["NORMAL"] = model.positions(normals);
    }
    if (indexType == kUnsignedByte) {
        primitive["indices"] = model.data(std::vector<uint8_t>(cube.indices.begin(), cube.indices.end()),
                                          kUnsignedByte, "SCALAR", 1);
    } else if (indexType == kUnsignedShort) {
        primitive["indices"] = model.data(std::vector<uint16_t>(cube.indices.begin(), cube.indices.end()),
                                          kUnsignedShort, "SCALAR", 1);
    } else if (indexType == kUnsignedInt) {
        primitive["indices"] = model.data(cube.indices, kUnsignedInt, "SCALAR", 1);
    }
    primitive["material"] = model.add("materials", {{"name", "cube"}});
    model.meshNode(primitive);
    return model;
}

// Two quads, red at x = -3 and green at x = +3, both facing +Z, and two cameras looking down -Z
// from 4 in front of each ("left" at index 0, "right" at 1); a third camera, orthographic.
inline GltfBuilder twoQuadsAndTheirCameras() {
    GltfBuilder model;
    const int positions = model.positions({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
    const int normals = model.positions({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int indices = model.data(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, kUnsignedShort, "SCALAR", 1);
    for (const auto& [x, colour] : {std::pair{-3, Json::array({1, 0, 0, 1})}, std::pair{3, Json::array({0, 1, 0, 1})}}) {
        const int material = model.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", colour}}}});
        model.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}, {"indices", indices},
                        {"material", material}},
                       {{"translation", {x, 0, 0}}});
    }
    for (const auto& [name, x] : {std::pair{"left", -3}, std::pair{"right", 3}}) {
        const int camera = model.add("cameras", {{"type", "perspective"}, {"name", name},
                                                 {"perspective", {{"yfov", 0.4}, {"znear", 0.1}}}});
        model.json["scenes"][0]["nodes"].push_back(
            model.add("nodes", {{"camera", camera}, {"translation", {x, 0, 4}}}));
    }
    model.add("cameras", {{"type", "orthographic"}, {"name", "plan"},
                          {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0}, {"zfar", 9}}}});
    model.json["scenes"][0]["nodes"].push_back(model.add("nodes", {{"camera", 2}}));
    return model;
}

// The InputError `load` throws, or "(loaded)"; any other exception fails the test.
template <typename Load>
std::string errorOf(const Load& load) {
    try {
        load();
    } catch (const InputError& error) {
        return error.what();
    }
    return "(loaded)";
}

// The model at `path` as a model opens (AssetCache::model, through a cache of its own): what it
// draws and its draws flattened into one world-space mesh.
inline std::shared_ptr<const LoadedModel> loadModel(const std::filesystem::path& path) {
    return AssetCache().model(path);
}
// The flattened mesh of the model at `path` (loadModel).
inline Mesh flatMesh(const std::filesystem::path& path) {
    return loadModel(path)->mesh;
}
// The model's first material as a Patina material: its factors under its name.
inline Material firstMaterial(const Model& model) {
    Material material;
    static_cast<MaterialParameters&>(material) = model.materials.at(0).factors;
    material.name = model.materials[0].name;
    return material;
}

// The InputError loading the model at `path` as a model opens (loadModel) / importGltfModel
// throws, or "(loaded)".
inline std::string importError(const std::filesystem::path& path) {
    return errorOf([&] { loadModel(path); });
}
inline std::string modelError(const std::filesystem::path& path) {
    return errorOf([&] { importGltfModel(path); });
}

}  // namespace patina::test
