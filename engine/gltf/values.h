#pragma once
// Reading tinygltf's untyped values (extension objects) with an InputError naming the JSON
// pointer for a value of the wrong type. json_rules.h has checked the types of those Patina
// reads already; these check again, so that no caller depends on that.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace patina::gltf {

// JSON numbers are finite: checkGltfJson refuses any that a double cannot hold.
double numberOf(const tinygltf::Value& value, const std::string& what, const std::string& source);

// A number as a message quotes it: the shortest text that reads back as the same double
// ("0.5", "-2", "1e+300"), as the file most likely wrote it; not std::to_string's "0.500000".
std::string numberText(double value);

// The extension's object (tinygltf keeps only objects), or null when there is none.
const tinygltf::Value* extensionOf(const tinygltf::ExtensionMap& extensions, const char* name);

// object[key] as a number; `fallback` when there is no object or no such key.
double numberField(const tinygltf::Value* object, const char* key, double fallback, const std::string& what,
                   const std::string& source);

// object[key] as an array of `size` numbers; empty when there is no object or no such key.
std::vector<double> numbersField(const tinygltf::Value* object, const char* key, size_t size,
                                 const std::string& what, const std::string& source);

// A whole number of at least 0 that fits `Limit`, from tinygltf's value (an int, or a real
// where the JSON's number did not fit one); else nothing.
template <typename Limit>
std::optional<Limit> wholeNumber(const tinygltf::Value& value) {
    if (!value.IsNumber()) {
        return std::nullopt;
    }
    const double number = value.GetNumberAsDouble();
    if (!(number >= 0.0 && number <= double(std::numeric_limits<Limit>::max())) || number != double(Limit(number))) {
        return std::nullopt;
    }
    return Limit(number);
}

}  // namespace patina::gltf
