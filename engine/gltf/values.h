#pragma once
// Reading tinygltf's untyped values (extension objects) with an InputError naming the JSON
// pointer for a value of the wrong type. json_rules.h has checked the types of those Patina
// reads already; these check again, so that no caller depends on that.
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace patina::gltf {

// JSON numbers are finite: checkGltfJson refuses any that a double cannot hold.
double numberOf(const tinygltf::Value& value, const std::string& what, const std::string& source);

// The extension's object (tinygltf keeps only objects), or null when there is none.
const tinygltf::Value* extensionOf(const tinygltf::ExtensionMap& extensions, const char* name);

// object[key] as a number; `fallback` when there is no object or no such key.
double numberField(const tinygltf::Value* object, const char* key, double fallback, const std::string& what,
                   const std::string& source);

// object[key] as an array of `size` numbers; empty when there is no object or no such key.
std::vector<double> numbersField(const tinygltf::Value* object, const char* key, size_t size,
                                 const std::string& what, const std::string& source);

}  // namespace patina::gltf
