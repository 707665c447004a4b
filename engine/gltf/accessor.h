#pragma once
// glTF accessors checked against their buffer view and buffer before any element is read.
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>

#include <tiny_gltf.h>

namespace patina::gltf {

// Elements `stride` bytes apart from `data`; every byte of all `count` elements is inside the
// buffer. Read them with memcpy: glTF does not promise alignment for every component type.
struct AccessorView {
    const uint8_t* data = nullptr;
    size_t count = 0;
    size_t stride = 0;
    int componentType = 0;   // TINYGLTF_COMPONENT_TYPE_*
};

// The accessor `index`, required to be of `type` (TINYGLTF_TYPE_*) with one of
// `componentTypes` and not normalized, to have a buffer view and not to be sparse. `what`
// names its use in messages ("/meshes/0/primitives/1/attributes/POSITION"); failures throw
// InputError("SOURCE: WHAT: ...").
AccessorView viewAccessor(const tinygltf::Model& model, int index, int type,
                          std::initializer_list<int> componentTypes, const std::string& what,
                          const std::string& source);

}  // namespace patina::gltf
