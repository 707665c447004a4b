#include "gltf/meshopt.h"

#include <cstring>

#include <meshoptimizer.h>

#include "files/input_error.h"
#include "gltf/values.h"

namespace patina::gltf {

namespace {

[[noreturn]] void fail(const std::string& at, const std::string& what) {
    throw InputError(at + ": " + what);
}

// The extension's fields (EXT_meshopt_compression, "Properties"), read and checked.
struct MeshoptView {
    size_t buffer = 0;
    size_t byteOffset = 0;
    size_t byteLength = 0;
    size_t byteStride = 0;
    size_t count = 0;
    std::string mode;
    std::string filter = "NONE";
};

size_t wholeField(const tinygltf::Value& extension, const char* key, std::optional<size_t> fallback,
                  const std::string& at) {
    if (!extension.Has(key)) {
        if (!fallback) {
            fail(at, std::string("has no ") + key);
        }
        return *fallback;
    }
    const std::optional<size_t> value = wholeNumber<size_t>(extension.Get(key));
    if (!value) {
        fail(at + "/" + key, "not a whole number of at least 0");
    }
    return *value;
}

std::string stringField(const tinygltf::Value& extension, const char* key, const char* fallback, const std::string& at) {
    if (!extension.Has(key)) {
        if (!fallback) {
            fail(at, std::string("has no ") + key);
        }
        return fallback;
    }
    if (!extension.Get(key).IsString()) {
        fail(at + "/" + key, "not a string");
    }
    return extension.Get(key).Get<std::string>();
}

// The extension's rules for each mode: ATTRIBUTES' stride a multiple of 4 up to 256, the
// filters' strides; TRIANGLES whole triangles; indices of 2 or 4 bytes.
void checkForm(const MeshoptView& view, const std::string& at) {
    if (view.mode == "ATTRIBUTES") {
        if (view.byteStride == 0 || view.byteStride % 4 != 0 || view.byteStride > 256) {
            fail(at + "/byteStride", std::to_string(view.byteStride) + ": ATTRIBUTES take a multiple of 4 up to 256");
        }
        const bool fits = view.filter == "NONE" || view.filter == "EXPONENTIAL" ||
                          (view.filter == "OCTAHEDRAL" && (view.byteStride == 4 || view.byteStride == 8)) ||
                          (view.filter == "QUATERNION" && view.byteStride == 8);
        if (!fits) {
            fail(at + "/filter", "'" + view.filter + "' with a stride of " + std::to_string(view.byteStride) +
                                     ": NONE, EXPONENTIAL, OCTAHEDRAL (stride 4 or 8) or QUATERNION (stride 8)");
        }
        return;
    }
    if (view.mode != "TRIANGLES" && view.mode != "INDICES") {
        fail(at + "/mode", "'" + view.mode + "': ATTRIBUTES, TRIANGLES or INDICES");
    }
    if (view.byteStride != 2 && view.byteStride != 4) {
        fail(at + "/byteStride", std::to_string(view.byteStride) + ": indices are 2 or 4 bytes");
    }
    if (view.filter != "NONE") {
        fail(at + "/filter", "'" + view.filter + "': " + view.mode + " take no filter");
    }
    if (view.mode == "TRIANGLES" && view.count % 3 != 0) {
        fail(at + "/count", std::to_string(view.count) + " is not a whole number of triangles");
    }
}

MeshoptView readView(const tinygltf::Model& model, const tinygltf::Value& extension, const std::string& at) {
    if (!extension.IsObject()) {
        fail(at, "not an object");
    }
    MeshoptView view;
    view.buffer = wholeField(extension, "buffer", std::nullopt, at);
    view.byteOffset = wholeField(extension, "byteOffset", 0, at);
    view.byteLength = wholeField(extension, "byteLength", std::nullopt, at);
    view.byteStride = wholeField(extension, "byteStride", std::nullopt, at);
    view.count = wholeField(extension, "count", std::nullopt, at);
    view.mode = stringField(extension, "mode", nullptr, at);
    view.filter = stringField(extension, "filter", "NONE", at);
    checkForm(view, at);
    if (view.buffer >= model.buffers.size()) {
        fail(at + "/buffer", "buffer " + std::to_string(view.buffer) + " does not exist");
    }
    const size_t size = model.buffers[view.buffer].data.size();
    if (view.byteOffset > size || view.byteLength > size - view.byteOffset) {
        fail(at, "its stream (" + std::to_string(view.byteLength) + " bytes at " + std::to_string(view.byteOffset) +
                     ") lies outside buffer " + std::to_string(view.buffer) + " (" + std::to_string(size) + " bytes)");
    }
    return view;
}

// meshoptimizer's decoders return 0, or a negative number for a stream that is not one.
std::vector<uint8_t> decode(const tinygltf::Model& model, const MeshoptView& view, const std::string& at) {
    std::vector<uint8_t> out(view.count * view.byteStride);
    const unsigned char* stream = model.buffers[view.buffer].data.data() + view.byteOffset;
    const int result =
        view.mode == "ATTRIBUTES"
            ? meshopt_decodeVertexBuffer(out.data(), view.count, view.byteStride, stream, view.byteLength)
        : view.mode == "TRIANGLES"
            ? meshopt_decodeIndexBuffer(out.data(), view.count, view.byteStride, stream, view.byteLength)
            : meshopt_decodeIndexSequence(out.data(), view.count, view.byteStride, stream, view.byteLength);
    if (result != 0) {
        fail(at, "the " + view.mode + " stream does not decode (meshoptimizer's error " + std::to_string(result) + ")");
    }
    if (view.filter == "OCTAHEDRAL") {
        meshopt_decodeFilterOct(out.data(), view.count, view.byteStride);
    } else if (view.filter == "QUATERNION") {
        meshopt_decodeFilterQuat(out.data(), view.count, view.byteStride);
    } else if (view.filter == "EXPONENTIAL") {
        meshopt_decodeFilterExp(out.data(), view.count, view.byteStride);
    }
    return out;
}

bool isFallback(const Json& buffer) {
    if (!buffer.is_object() || buffer.contains("uri") || !buffer.contains("extensions") ||
        !buffer["extensions"].is_object() || !buffer["extensions"].contains(kMeshopt)) {
        return false;
    }
    const Json& extension = buffer["extensions"][kMeshopt];
    return extension.is_object() && extension.value("fallback", false) == true;
}

}  // namespace

bool standInForMeshoptFallbacks(Json& document) {
    if (!document.is_object() || !document.contains("buffers") || !document["buffers"].is_array()) {
        return false;
    }
    bool changed = false;
    for (Json& buffer : document["buffers"]) {
        if (isFallback(buffer)) {
            buffer["uri"] = "data:application/octet-stream;base64,AA==";
            buffer["byteLength"] = 1;
            changed = true;
        }
    }
    return changed;
}

void decodeMeshoptViews(tinygltf::Model& model, const std::string& source) {
    uint64_t decoded = 0;
    for (size_t i = 0; i < model.bufferViews.size(); ++i) {
        tinygltf::BufferView& bufferView = model.bufferViews[i];
        const auto found = bufferView.extensions.find(kMeshopt);
        if (found == bufferView.extensions.end()) {
            continue;
        }
        const std::string at = source + ": /bufferViews/" + std::to_string(i) + "/extensions/" + kMeshopt;
        const MeshoptView view = readView(model, found->second, at);
        // count * byteStride without overflow: the stride is at most 256.
        if (view.count > (kMaxMeshoptBytes - decoded) / view.byteStride) {
            fail(at + "/count", std::to_string(view.count) + " elements of " + std::to_string(view.byteStride) +
                                    " bytes would take the model's decoded views past Patina's limit of " +
                                    std::to_string(kMaxMeshoptBytes >> 20) + " MiB");
        }
        decoded += view.count * view.byteStride;
        tinygltf::Buffer buffer;
        buffer.data = decode(model, view, at);
        bufferView.buffer = int(model.buffers.size());
        bufferView.byteOffset = 0;
        bufferView.byteLength = buffer.data.size();
        model.buffers.push_back(std::move(buffer));
    }
}

}  // namespace patina::gltf
