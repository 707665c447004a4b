#pragma once
// KHR_draco_mesh_compression: a primitive whose attributes and indices are one Draco stream in
// a buffer view, decoded through Debian's libdraco into the accessors the primitive names.
// docs/FORMATS.md, "glTF", has what is checked.
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <tiny_gltf.h>

#include "io/json_reader.h"

namespace patina::gltf {

inline constexpr const char* kDraco = "KHR_draco_mesh_compression";

// A primitive's Draco stream: its bytes (checked inside their buffer) and the Draco attribute id
// of each glTF attribute it holds ("POSITION" -> 0).
struct DracoStream {
    std::span<const uint8_t> bytes;
    std::map<std::string, uint32_t> attributes;
};

// Moves each Draco primitive's `indices` into its extension object (as "indices") in
// `document`; true when it moved any. A compressed primitive's index accessor has no buffer view
// of its own, which tinygltf refuses ("accessor[N] invalid bufferView") before Patina could
// decode it; moved, tinygltf keeps it in the extension's value and dracoPrimitive reads it back.
bool moveDracoIndicesIntoTheExtension(Json& document);

// The primitive's Draco stream and its index accessor (-1: none), when it has the extension.
// Throws InputError("SOURCE: WHERE/extensions/KHR_draco_mesh_compression...") for a buffer view
// outside its buffer or an attribute the primitive does not name.
struct DracoPrimitive {
    DracoStream stream;
    int indices = -1;
};
std::optional<DracoPrimitive> dracoPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                             const std::string& where, const std::string& source);

// The decoded stream: the corners of its triangles, and each attribute's elements as `count`
// elements of `components` numbers of `componentType` (a TINYGLTF_COMPONENT_TYPE_*), laid out as
// an accessor's buffer view would hold them.
struct DecodedAttribute {
    std::vector<uint8_t> bytes;
    size_t count = 0;
};
struct DecodedDraco {
    std::vector<uint32_t> corners;
    std::map<std::string, DecodedAttribute> attributes;
};

// What an attribute's accessor asks of the stream: its component type and numbers an element.
struct DracoAttributeForm {
    int componentType;
    int components;
};

// Decodes the stream and converts each attribute in `forms` to its accessor's form. Throws
// InputError("SOURCE: WHERE: ...") when the stream does not decode, is not a triangle mesh, or
// lacks an attribute, or an attribute does not convert.
DecodedDraco decodeDraco(const DracoStream& stream, const std::map<std::string, DracoAttributeForm>& forms,
                         const std::string& where, const std::string& source);

}  // namespace patina::gltf
