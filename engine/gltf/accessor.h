#pragma once
// glTF accessors (glTF 2.0 section 3.6.2) checked against their buffer views and buffers before
// any element is read, then read as floats or as indices: normalized integers and sparse
// substitution included.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace patina::gltf {

// Elements `stride` bytes apart from `data`; every byte of all `count` elements is inside the
// buffer. Read them with memcpy: glTF does not promise alignment for every component type.
struct AccessorView {
    const uint8_t* data = nullptr;
    size_t count = 0;
    size_t stride = 0;
};

// A form an accessor may take for one use: a component type (TINYGLTF_COMPONENT_TYPE_*), and
// whether its integers are normalized (section 3.11).
struct AccessorForm {
    int componentType;
    bool normalized = false;
};

// An accessor checked for one use. Without a buffer view its elements start as zeros (3.6.2.3).
struct CheckedAccessor {
    size_t count = 0;
    int components = 0;        // numbers an element
    int componentType = 0;
    bool normalized = false;
    AccessorView dense;        // data null: zeros
    AccessorView sparseIndices, sparseValues;   // count 0 when not sparse
    int sparseIndexType = 0;
    std::string where;         // "SOURCE: /accessors/N (WHAT)", to start messages about elements
};

// The accessor `index` for the use `what` ("/meshes/0/primitives/1/attributes/POSITION"): of
// `type` (TINYGLTF_TYPE_*) in one of `forms`, with a buffer view unless it is sparse, every
// view in its buffer. A `compressed` one (KHR_draco_mesh_compression: a stream holds its
// elements) is checked for its type and form only; its view, if it has one, is the file's
// uncompressed fallback and is not read. Throws InputError("SOURCE: WHERE: ...") naming what is
// wrong.
CheckedAccessor checkAccessor(const tinygltf::Model& model, int index, int type,
                              const std::vector<AccessorForm>& forms, const std::string& what,
                              const std::string& source, bool compressed = false);

// Every number of every element (count * components), normalized integers mapped to [0, 1] or
// [-1, 1] as section 3.11 says, sparse values substituted. Throws InputError for a sparse index
// outside the accessor.
std::vector<float> readFloats(const CheckedAccessor& accessor);

// The bytes of buffer view `index`, checked against its buffer; `owner` ("SOURCE: /images/2")
// starts the message when there is no such view.
std::span<const uint8_t> bufferViewBytes(const tinygltf::Model& model, int index, const std::string& owner,
                                         const std::string& source);

// The elements of a SCALAR accessor of unsigned integers, sparse values substituted.
std::vector<uint32_t> readIntegers(const CheckedAccessor& accessor);

}  // namespace patina::gltf
