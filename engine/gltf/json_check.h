#pragma once
// A pass over the glTF JSON before tinygltf parses it, for what would otherwise cost a crash
// or unbounded memory inside the parser: syntax, nesting depth, the number of values (each
// becomes an object of up to 2 KiB in tinygltf's model), in a GLB that only buffers[0] takes
// the BIN chunk (tinygltf copies the chunk for every buffer without a uri), and the JSON type
// of every property Patina reads (json_rules.h: tinygltf drops one of the wrong type quietly).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace patina::gltf {

constexpr size_t kMaxJsonDepth = 64;
constexpr size_t kMaxJsonValues = size_t(4) << 20;
constexpr size_t kMaxJsonObjects = size_t(256) << 10;

// Throws InputError("SOURCE: ...") for the first rule broken. Returns the file's
// extensionsRequired, so that a file Patina cannot draw is refused by name before tinygltf
// trips on what the extension changed (a Draco mesh's accessors have no bufferView).
std::vector<std::string> checkGltfJson(std::string_view json, bool glb, const std::string& source);

}  // namespace patina::gltf
