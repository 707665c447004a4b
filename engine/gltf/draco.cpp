#include "gltf/draco.h"

#include <cstring>
#include <limits>
#include <memory>

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include "files/input_error.h"
#include "gltf/accessor.h"
#include "gltf/primitives.h"
#include "gltf/values.h"
#include "io/json_reader.h"

namespace patina::gltf {

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw InputError(source + ": " + what);
}

// Every point's value of `attribute` as `T`, `components` numbers each, in point order (the
// order the faces' corners index).
template <typename T>
bool convertPoints(const draco::Mesh& mesh, const draco::PointAttribute& attribute, int components,
                   std::vector<uint8_t>& out) {
    out.resize(size_t(mesh.num_points()) * size_t(components) * sizeof(T));
    T values[4] = {};
    for (draco::PointIndex point(0); point < mesh.num_points(); ++point) {
        const draco::AttributeValueIndex value = attribute.mapped_index(point);
        if (value.value() >= attribute.size() || !attribute.ConvertValue<T>(value, int8_t(components), values)) {
            return false;
        }
        std::memcpy(out.data() + size_t(point.value()) * size_t(components) * sizeof(T), values,
                    size_t(components) * sizeof(T));
    }
    return true;
}

bool convertAttribute(const draco::Mesh& mesh, const draco::PointAttribute& attribute, DracoAttributeForm form,
                      std::vector<uint8_t>& out) {
    switch (form.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return convertPoints<float>(mesh, attribute, form.components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return convertPoints<uint16_t>(mesh, attribute, form.components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return convertPoints<uint8_t>(mesh, attribute, form.components, out);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return convertPoints<int16_t>(mesh, attribute, form.components, out);
    case TINYGLTF_COMPONENT_TYPE_BYTE: return convertPoints<int8_t>(mesh, attribute, form.components, out);
    default: return false;   // planPrimitive allows no other form for what it reads
    }
}

}  // namespace

bool moveDracoIndicesIntoTheExtension(Json& document) {
    bool moved = false;
    if (!document.is_object() || !document.contains("meshes") || !document["meshes"].is_array()) {
        return false;
    }
    for (Json& mesh : document["meshes"]) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) {
            continue;
        }
        for (Json& primitive : mesh["primitives"]) {
            if (!primitive.is_object() || !primitive.contains("indices") || !primitive.contains("extensions") ||
                !primitive["extensions"].is_object() || !primitive["extensions"].contains(kDraco) ||
                !primitive["extensions"][kDraco].is_object()) {
                continue;
            }
            primitive["extensions"][kDraco]["indices"] = primitive["indices"];
            primitive.erase("indices");
            moved = true;
        }
    }
    return moved;
}

std::optional<DracoPrimitive> dracoPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                             const std::string& where, const std::string& source) {
    const auto found = primitive.extensions.find(kDraco);
    if (found == primitive.extensions.end()) {
        return std::nullopt;
    }
    const std::string at = where + "/extensions/" + kDraco;
    const tinygltf::Value& extension = found->second;
    // tinygltf's Get asserts an object: the JSON rules make the extension one, asked first anyway.
    const std::optional<int> view =
        extension.IsObject() ? wholeNumber<int>(extension.Get("bufferView")) : std::nullopt;
    if (!view) {
        fail(source, at + "/bufferView: the index of the buffer view holding the compressed mesh is missing");
    }
    DracoPrimitive draco;
    draco.stream.bytes = bufferViewBytes(model, *view, source + ": " + at, source);
    const tinygltf::Value& attributes = extension.Get("attributes");
    for (const std::string& name : attributes.IsObject() ? attributes.Keys() : std::vector<std::string>()) {
        const std::optional<uint32_t> id = wholeNumber<uint32_t>(attributes.Get(name));
        if (!id) {
            fail(source, at + "/attributes/" + name + ": not a Draco attribute id (a whole number of at least 0)");
        }
        if (!primitive.attributes.count(name)) {
            fail(source, at + "/attributes/" + name + ": the primitive has no attribute " + name +
                             " for the compressed one to fill");
        }
        draco.stream.attributes[name] = *id;
    }
    if (extension.Has("indices")) {   // moved here by moveDracoIndicesIntoTheExtension
        const std::optional<int> indices = wholeNumber<int>(extension.Get("indices"));
        if (!indices) {
            fail(source, where + "/indices: not the index of an accessor");
        }
        draco.indices = *indices;
    }
    return draco;
}

DecodedDraco decodeDraco(const DracoStream& stream, const std::map<std::string, DracoAttributeForm>& forms,
                         const std::string& where, const std::string& source) {
    const std::string at = where + "/extensions/" + kDraco;
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(stream.bytes.data()), stream.bytes.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok() || !decoded.value()) {
        fail(source, at + ": the compressed mesh does not decode (Draco: " +
                         (decoded.ok() ? std::string("not a triangle mesh") : decoded.status().error_msg_string()) + ")");
    }
    const draco::Mesh& mesh = *decoded.value();
    if (mesh.num_points() > kGltfMaxVertices || mesh.num_faces() > kGltfMaxTriangles) {
        fail(source, at + ": the compressed mesh has " + std::to_string(mesh.num_points()) + " points and " +
                         std::to_string(mesh.num_faces()) + " triangles, over the limits of " +
                         std::to_string(kGltfMaxVertices) + " and " + std::to_string(kGltfMaxTriangles));
    }
    DecodedDraco out;
    out.corners.reserve(size_t(mesh.num_faces()) * 3);
    for (draco::FaceIndex face(0); face < mesh.num_faces(); ++face) {
        for (const draco::PointIndex corner : mesh.face(face)) {
            out.corners.push_back(corner.value());
        }
    }
    for (const auto& [name, form] : forms) {
        const auto id = stream.attributes.find(name);
        if (id == stream.attributes.end()) {
            continue;   // not compressed: the accessor's own buffer view holds it
        }
        const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(id->second);
        if (!attribute || attribute->num_components() < form.components) {
            fail(source, at + "/attributes/" + name + ": the compressed mesh has no attribute " +
                             std::to_string(id->second) +
                             (attribute ? " of " + std::to_string(form.components) + " numbers an element" : ""));
        }
        DecodedAttribute& decodedAttribute = out.attributes[name];
        decodedAttribute.count = mesh.num_points();
        if (!convertAttribute(mesh, *attribute, form, decodedAttribute.bytes)) {
            fail(source, at + "/attributes/" + name + ": the compressed values do not convert to the accessor's");
        }
    }
    return out;
}

}  // namespace patina::gltf
