#include "gltf/accessor.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>

#include "files/input_error.h"

namespace patina::gltf {

namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

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

std::string formName(const AccessorForm& form) {
    return (form.normalized ? "normalized " : "") + componentTypeName(form.componentType);
}

std::string describe(int type, const std::vector<AccessorForm>& forms) {
    std::string text = typeName(type) + " of ";
    for (size_t f = 0; f < forms.size(); ++f) {
        text += (f == 0 ? "" : f + 1 == forms.size() ? " or " : ", ") + formName(forms[f]);
    }
    return text;
}

size_t componentSize(int componentType) {
    return size_t(tinygltf::GetComponentSizeInBytes(uint32_t(componentType)));
}

// A buffer view's bytes, checked against its buffer (section 3.6.1). `owner` starts the message
// when the view does not exist.
struct ViewBytes {
    int index;
    const uint8_t* data;
    size_t length, byteStride;
};

ViewBytes viewBytes(const tinygltf::Model& model, int index, const std::string& owner, const std::string& source) {
    if (index < 0 || size_t(index) >= model.bufferViews.size()) {
        throw InputError(owner + ": buffer view " + std::to_string(index) + " does not exist");
    }
    const tinygltf::BufferView& view = model.bufferViews[size_t(index)];
    const std::string at = source + ": /bufferViews/" + std::to_string(index);
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) {
        throw InputError(at + ": buffer " + std::to_string(view.buffer) + " does not exist");
    }
    const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
        throw InputError(at + ": bytes " + std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
                         " run past the end of buffer " + std::to_string(view.buffer) + " (" +
                         std::to_string(buffer.size()) + " bytes)");
    }
    return {index, buffer.data() + view.byteOffset, view.byteLength, view.byteStride};
}

// `count` elements of `size` bytes, `stride` apart, from byte `offset` of the view: all inside it.
AccessorView elements(const ViewBytes& view, size_t offset, size_t count, size_t size, size_t stride,
                      const std::string& owner) {
    // Without overflow: the last element starts (count - 1) * stride bytes after the first.
    const size_t available = view.length - std::min(offset, view.length);
    if (offset > view.length || (count > 0 && (available < size || count - 1 > (available - size) / stride))) {
        throw InputError(owner + ": " + std::to_string(count) + " elements of " + std::to_string(size) +
                         " bytes, " + std::to_string(stride) + " apart, from byte " + std::to_string(offset) +
                         " run past the end of buffer view " + std::to_string(view.index) + " (" +
                         std::to_string(view.length) + " bytes)");
    }
    return {view.data + offset, count, stride};
}

// Section 3.6.2.3: `count` indices and as many values, tightly packed in views of their own.
// Each index is checked against the accessor's count as it is read; their order is not needed.
void checkSparse(const tinygltf::Model& model, const tinygltf::Accessor& accessor, size_t elementSize,
                 const std::string& at, const std::string& what, const std::string& source,
                 CheckedAccessor& checked) {
    const auto& sparse = accessor.sparse;
    if (sparse.count < 1 || size_t(sparse.count) > accessor.count) {
        throw InputError(at + "/sparse/count: " + std::to_string(sparse.count) + " must be from 1 to the accessor's " +
                         std::to_string(accessor.count) + " elements");
    }
    const int indexType = sparse.indices.componentType;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        throw InputError(at + "/sparse/indices/componentType: must be UNSIGNED_BYTE, UNSIGNED_SHORT or "
                              "UNSIGNED_INT, not " + componentTypeName(indexType));
    }
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) {
        throw InputError(at + "/sparse: a byteOffset is negative");
    }
    const std::string indicesAt = at + "/sparse/indices (" + what + ")";
    const std::string valuesAt = at + "/sparse/values (" + what + ")";
    const size_t count = size_t(sparse.count), indexSize = componentSize(indexType);
    checked.sparseIndices = elements(viewBytes(model, sparse.indices.bufferView, indicesAt, source),
                                     size_t(sparse.indices.byteOffset), count, indexSize, indexSize, indicesAt);
    checked.sparseValues = elements(viewBytes(model, sparse.values.bufferView, valuesAt, source),
                                    size_t(sparse.values.byteOffset), count, elementSize, elementSize, valuesAt);
    checked.sparseIndexType = indexType;
}

}  // namespace

std::span<const uint8_t> bufferViewBytes(const tinygltf::Model& model, int index, const std::string& owner,
                                         const std::string& source) {
    const ViewBytes view = viewBytes(model, index, owner, source);
    return {view.data, view.length};
}

CheckedAccessor checkAccessor(const tinygltf::Model& model, int index, int type,
                              const std::vector<AccessorForm>& forms, const std::string& what,
                              const std::string& source, bool compressed) {
    if (index < 0 || size_t(index) >= model.accessors.size()) {
        throw InputError(source + ": " + what + ": accessor " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Accessor& accessor = model.accessors[size_t(index)];
    const std::string path = source + ": /accessors/" + std::to_string(index);
    const std::string at = path + " (" + what + ")";
    const bool known = std::any_of(forms.begin(), forms.end(), [&](const AccessorForm& form) {
        return form.componentType == accessor.componentType && form.normalized == accessor.normalized;
    });
    if (accessor.type != type || !known) {
        throw InputError(at + ": must be " + describe(type, forms) + ", not " + (accessor.normalized ? "normalized " : "") +
                         typeName(accessor.type) + " of " + componentTypeName(accessor.componentType));
    }
    CheckedAccessor checked;
    checked.count = accessor.count;
    checked.components = tinygltf::GetNumComponentsInType(uint32_t(type));
    checked.componentType = accessor.componentType;
    checked.normalized = accessor.normalized;
    checked.where = at;
    if (compressed) {
        return checked;
    }
    const size_t elementSize = componentSize(accessor.componentType) * size_t(checked.components);
    if (accessor.sparse.isSparse) {
        checkSparse(model, accessor, elementSize, path, what, source, checked);
    }
    // Without a view the elements are zeros (3.6.2.3): only a sparse accessor makes that useful.
    if (accessor.bufferView == -1 && accessor.sparse.isSparse) {
        return checked;
    }
    const ViewBytes view = viewBytes(model, accessor.bufferView, at, source);
    const size_t stride = view.byteStride == 0 ? elementSize : view.byteStride;
    if (stride < elementSize) {
        throw InputError(source + ": /bufferViews/" + std::to_string(view.index) + ": byteStride " +
                         std::to_string(stride) + " is less than the " + std::to_string(elementSize) +
                         " bytes of an element of accessor " + std::to_string(index));
    }
    checked.dense = elements(view, accessor.byteOffset, accessor.count, elementSize, stride, at);
    return checked;
}

namespace {

// One component as a float: section 3.11's mapping for a normalized integer.
template <typename T, bool normalized>
float decodeFloat(const uint8_t* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    if constexpr (normalized) {
        constexpr float largest = float(std::numeric_limits<T>::max());
        return std::max(float(value) / largest, -1.0f);
    } else {
        return float(value);
    }
}

template <typename T>
uint32_t decodeInteger(const uint8_t* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return uint32_t(value);
}

using FloatDecoder = float (*)(const uint8_t*);
using IntegerDecoder = uint32_t (*)(const uint8_t*);

FloatDecoder floatDecoder(int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return normalized ? decodeFloat<int8_t, true> : decodeFloat<int8_t, false>;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? decodeFloat<uint8_t, true> : decodeFloat<uint8_t, false>;
    case TINYGLTF_COMPONENT_TYPE_SHORT: return normalized ? decodeFloat<int16_t, true> : decodeFloat<int16_t, false>;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return normalized ? decodeFloat<uint16_t, true> : decodeFloat<uint16_t, false>;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return decodeFloat<uint32_t, false>;
    }
    return decodeFloat<float, false>;
}

// Unsigned integer types only: checkAccessor let no other through for an integer use.
IntegerDecoder integerDecoder(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return decodeInteger<uint8_t>;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return decodeInteger<uint16_t>;
    }
    return decodeInteger<uint32_t>;
}

// The dense elements (or zeros), then each sparse value over the element its index names.
template <typename Number>
std::vector<Number> readAll(const CheckedAccessor& accessor, Number (*decode)(const uint8_t*)) {
    const size_t components = size_t(accessor.components), size = componentSize(accessor.componentType);
    std::vector<Number> numbers(accessor.count * components, Number(0));
    auto copy = [&](const AccessorView& from, size_t element, size_t to) {
        const uint8_t* bytes = from.data + element * from.stride;
        for (size_t c = 0; c < components; ++c) {
            numbers[to * components + c] = decode(bytes + c * size);
        }
    };
    if (accessor.dense.data) {
        for (size_t i = 0; i < accessor.count; ++i) {
            copy(accessor.dense, i, i);
        }
    }
    const IntegerDecoder decodeIndex = integerDecoder(accessor.sparseIndexType);
    for (size_t j = 0; j < accessor.sparseIndices.count; ++j) {
        const uint32_t target = decodeIndex(accessor.sparseIndices.data + j * accessor.sparseIndices.stride);
        if (target >= accessor.count) {
            throw InputError(accessor.where + ": sparse index " + std::to_string(j) + " is " + std::to_string(target) +
                             " but the accessor has " + std::to_string(accessor.count) + " elements");
        }
        copy(accessor.sparseValues, j, target);
    }
    return numbers;
}

}  // namespace

std::vector<float> readFloats(const CheckedAccessor& accessor) {
    return readAll(accessor, floatDecoder(accessor.componentType, accessor.normalized));
}

std::vector<uint32_t> readIntegers(const CheckedAccessor& accessor) {
    return readAll(accessor, integerDecoder(accessor.componentType));
}

}  // namespace patina::gltf
