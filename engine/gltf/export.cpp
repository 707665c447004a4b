#include "gltf/export.h"

#include <algorithm>
#include <cstring>

#include <glm/common.hpp>

#include "gltf/glb.h"
#include "gltf/import.h"
#include "gltf/material.h"
#include "io/input_error.h"

namespace patina {

namespace fs = std::filesystem;

namespace {

constexpr int kFloat = 5126;            // glTF componentType FLOAT
constexpr int kUnsignedInt = 5125;      // UNSIGNED_INT
constexpr int kArrayBuffer = 34962;     // bufferView targets
constexpr int kElementArrayBuffer = 34963;


template <typename T>
void append(std::vector<uint8_t>& bin, const std::vector<T>& values) {
    const size_t offset = bin.size();
    bin.resize(offset + values.size() * sizeof(T));
    std::memcpy(bin.data() + offset, values.data(), values.size() * sizeof(T));
}

Json vec3Json(const glm::vec3& v) { return Json::array({double(v.x), double(v.y), double(v.z)}); }

}  // namespace

std::vector<OutputFile> encodeGltf(const fs::path& path, const Mesh& mesh, const Material& material,
                                   GltfBuffer buffer) {
    const std::string extension = gltfExtension(path);
    const bool glb = extension == ".glb";
    if (extension.empty()) {
        throw InputError(path.string() + ": a glTF file must end in .gltf or .glb");
    }
    if (mesh.positions.empty() || mesh.indices.empty() || mesh.normals.size() != mesh.positions.size()) {
        throw InputError(path.string() + ": nothing to export: the mesh has no triangles");
    }
    glm::vec3 low = mesh.positions.front(), high = low;
    for (const glm::vec3& p : mesh.positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const size_t vertexBytes = mesh.positions.size() * sizeof(glm::vec3);
    std::vector<uint8_t> bin;
    bin.reserve(2 * vertexBytes + mesh.indices.size() * sizeof(uint32_t));
    append(bin, mesh.positions);
    append(bin, mesh.normals);
    append(bin, mesh.indices);

    Json bufferJson{{"byteLength", bin.size()}};
    const fs::path binPath = fs::path(path).replace_extension(".bin");
    if (!glb && buffer == GltfBuffer::Embedded) {
        bufferJson["uri"] = "data:application/octet-stream;base64," + base64(bin);
    } else if (!glb) {
        bufferJson["uri"] = uriOfFileName(binPath.filename().string());
    }
    const Json accessors = Json::array(
        {{{"bufferView", 0}, {"componentType", kFloat}, {"count", mesh.positions.size()}, {"type", "VEC3"},
          {"min", vec3Json(low)}, {"max", vec3Json(high)}},
         {{"bufferView", 1}, {"componentType", kFloat}, {"count", mesh.normals.size()}, {"type", "VEC3"}},
         {{"bufferView", 2}, {"componentType", kUnsignedInt}, {"count", mesh.indices.size()}, {"type", "SCALAR"}}});
    const Json bufferViews = Json::array(
        {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", vertexBytes}, {"target", kArrayBuffer}},
         {{"buffer", 0}, {"byteOffset", vertexBytes}, {"byteLength", vertexBytes}, {"target", kArrayBuffer}},
         {{"buffer", 0}, {"byteOffset", 2 * vertexBytes}, {"byteLength", bin.size() - 2 * vertexBytes},
          {"target", kElementArrayBuffer}}});
    const Json primitive{
        {"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}, {"material", 0}, {"mode", 4}};
    Json document = Json::object();
    document["asset"] = {{"version", "2.0"}, {"generator", "Patina"}};
    document["extensionsUsed"] = Json::array({gltf::kMaterialExtensions[0], gltf::kMaterialExtensions[1]});
    document["scene"] = 0;
    document["scenes"] = Json::array({Json{{"nodes", Json::array({0})}}});
    document["nodes"] = Json::array({Json{{"mesh", 0}}});
    document["meshes"] = Json::array({Json{{"primitives", Json::array({primitive})}}});
    document["materials"] = Json::array({gltf::materialToGltf(material)});
    document["accessors"] = accessors;
    document["bufferViews"] = bufferViews;
    document["buffers"] = Json::array({bufferJson});

    const std::string json = document.dump();
    if (glb) {
        return {{path, gltf::joinGlb(json, bin.data(), bin.size())}};
    }
    std::vector<OutputFile> files;
    if (buffer == GltfBuffer::BinFile) {
        files.push_back({binPath, std::move(bin)});
    }
    files.push_back({path, std::vector<uint8_t>(json.begin(), json.end())});
    return files;
}

void exportGltf(const fs::path& path, const Mesh& mesh, const Material& material, GltfBuffer buffer) {
    writeOutputFiles(encodeGltf(path, mesh, material, buffer));
}

}  // namespace patina
