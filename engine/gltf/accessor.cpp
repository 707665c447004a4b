#include "gltf/accessor.h"

#include <algorithm>

#include "io/input_error.h"

namespace patina::gltf {

namespace {

std::string componentTypeName(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    }
    return "component type " + std::to_string(componentType);
}

std::string typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    }
    return "type " + std::to_string(type);
}

std::string describe(int type, std::initializer_list<int> componentTypes) {
    std::string text = typeName(type) + " of ";
    for (const int* c = componentTypes.begin(); c != componentTypes.end(); ++c) {
        text += (c == componentTypes.begin() ? "" : std::next(c) == componentTypes.end() ? " or " : ", ") +
                componentTypeName(*c);
    }
    return text;
}

}  // namespace

AccessorView viewAccessor(const tinygltf::Model& model, int index, int type,
                          std::initializer_list<int> componentTypes, const std::string& what,
                          const std::string& source) {
    const std::string where = source + ": " + what;
    if (index < 0 || size_t(index) >= model.accessors.size()) {
        throw InputError(where + ": accessor " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Accessor& accessor = model.accessors[size_t(index)];
    const std::string at = source + ": /accessors/" + std::to_string(index) + " (" + what + ")";
    const bool knownComponent =
        std::find(componentTypes.begin(), componentTypes.end(), accessor.componentType) != componentTypes.end();
    if (accessor.type != type || !knownComponent || accessor.normalized) {
        throw InputError(at + ": must be " + describe(type, componentTypes) + ", not " +
                         (accessor.normalized ? "normalized " : "") + typeName(accessor.type) + " of " +
                         componentTypeName(accessor.componentType));
    }
    if (accessor.sparse.isSparse) {
        throw InputError(at + ": sparse accessors are not supported");
    }
    if (accessor.bufferView < 0 || size_t(accessor.bufferView) >= model.bufferViews.size()) {
        throw InputError(at + ": buffer view " + std::to_string(accessor.bufferView) + " does not exist");
    }
    const tinygltf::BufferView& view = model.bufferViews[size_t(accessor.bufferView)];
    const std::string viewAt = source + ": /bufferViews/" + std::to_string(accessor.bufferView);
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) {
        throw InputError(viewAt + ": buffer " + std::to_string(view.buffer) + " does not exist");
    }
    const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
        throw InputError(viewAt + ": bytes " + std::to_string(view.byteOffset) + " + " +
                         std::to_string(view.byteLength) + " run past the end of buffer " +
                         std::to_string(view.buffer) + " (" + std::to_string(buffer.size()) + " bytes)");
    }
    const size_t elementSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType))) *
                               size_t(tinygltf::GetNumComponentsInType(uint32_t(accessor.type)));
    const size_t stride = view.byteStride == 0 ? elementSize : view.byteStride;
    if (stride < elementSize) {
        throw InputError(viewAt + ": byteStride " + std::to_string(stride) + " is less than the " +
                         std::to_string(elementSize) + " bytes of an element of accessor " +
                         std::to_string(index));
    }
    // Without overflow: the last element starts (count - 1) * stride bytes after the first.
    const size_t available = view.byteLength - std::min(accessor.byteOffset, view.byteLength);
    if (accessor.byteOffset > view.byteLength ||
        (accessor.count > 0 &&
         (available < elementSize || accessor.count - 1 > (available - elementSize) / stride))) {
        throw InputError(at + ": " + std::to_string(accessor.count) + " elements of " +
                         std::to_string(elementSize) + " bytes, " + std::to_string(stride) +
                         " apart, from byte " + std::to_string(accessor.byteOffset) +
                         " run past the end of buffer view " + std::to_string(accessor.bufferView) +
                         " (" + std::to_string(view.byteLength) + " bytes)");
    }
    return {buffer.data() + view.byteOffset + accessor.byteOffset, accessor.count, stride,
            accessor.componentType};
}

}  // namespace patina::gltf
