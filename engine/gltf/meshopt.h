#pragma once
// EXT_meshopt_compression: buffer views whose bytes are a meshoptimizer stream in another
// buffer, decoded through Debian's libmeshoptimizer into the bytes the view would hold
// uncompressed. docs/FORMATS.md, "glTF", has what is checked.
#include <optional>
#include <string>

#include <tiny_gltf.h>

#include "io/json_reader.h"

namespace patina::gltf {

inline constexpr const char* kMeshopt = "EXT_meshopt_compression";

// Everything a model's compressed views may decode to, all together: a stream of a few bytes
// can declare gigabytes.
inline constexpr uint64_t kMaxMeshoptBytes = uint64_t(512) << 20;

// Gives each fallback buffer (one the extension marks `fallback`, which has no data: its views
// are only ever read compressed) a one-byte data: URI in `document`, so that tinygltf, which
// wants every buffer of a .gltf to have a uri and would fill a GLB's from the BIN chunk,
// leaves it empty. True when it changed anything.
bool standInForMeshoptFallbacks(Json& document);

// Decodes every buffer view that has the extension into a buffer of its own appended to
// `model` and points the view at it (offset 0, its length the decoded size), so that the
// accessors read it as they read any view. Throws InputError("SOURCE: /bufferViews/N/extensions/
// EXT_meshopt_compression...: ...") for a stream outside its buffer, a mode, stride, count or
// filter the extension does not allow, a stream that does not decode, or decoded bytes past
// kMaxMeshoptBytes.
void decodeMeshoptViews(tinygltf::Model& model, const std::string& source);

}  // namespace patina::gltf
