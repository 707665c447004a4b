#pragma once
// The JSON types of the glTF properties Patina reads (glTF 2.0 section 5, the properties
// reference). tinygltf quietly drops a property of the wrong type (an extension that is not an
// object, an index of -1, a material's pbrMetallicRoughness that is an array); checkGltfJson
// refuses them instead, by these rules.
#include <string>

namespace patina::gltf {

enum class JsonKind { Object, Array, String, Number, Boolean, Integer, Unsigned, Index };

struct JsonRule {
    JsonKind kind;
    const char* noun = nullptr;   // Index: what it names ("accessor"), for "accessor -2 does not exist"
};

// The rule for the value at `pattern`: its JSON pointer with every array index written "*", and
// "{}" for a key of any name (attributes). Null when Patina has none for it.
const JsonRule* gltfJsonRule(const std::string& pattern);

}  // namespace patina::gltf
