#include "gltf/values.h"

#include <charconv>

#include "files/input_error.h"

namespace patina::gltf {

double numberOf(const tinygltf::Value& value, const std::string& what, const std::string& source) {
    if (!value.IsNumber()) {
        throw InputError(source + ": " + what + ": must be a number");
    }
    return value.GetNumberAsDouble();
}

std::string numberText(double value) {
    char text[32];
    const std::to_chars_result written = std::to_chars(text, text + sizeof text, value);
    return std::string(text, written.ptr);
}

const tinygltf::Value* extensionOf(const tinygltf::ExtensionMap& extensions, const char* name) {
    const auto found = extensions.find(name);
    return found == extensions.end() ? nullptr : &found->second;
}

double numberField(const tinygltf::Value* object, const char* key, double fallback, const std::string& what,
                   const std::string& source) {
    return object && object->Has(key) ? numberOf(object->Get(key), what + "/" + key, source) : fallback;
}

std::vector<double> numbersField(const tinygltf::Value* object, const char* key, size_t size,
                                 const std::string& what, const std::string& source) {
    if (!object || !object->Has(key)) {
        return {};
    }
    const tinygltf::Value& array = object->Get(key);
    const std::string at = what + "/" + key;
    if (!array.IsArray() || array.ArrayLen() != size) {
        throw InputError(source + ": " + at + ": must be an array of " + std::to_string(size) + " numbers");
    }
    std::vector<double> numbers(size);
    for (size_t i = 0; i < size; ++i) {
        numbers[i] = numberOf(array.Get(int(i)), at + "/" + std::to_string(i), source);
    }
    return numbers;
}

}  // namespace patina::gltf
