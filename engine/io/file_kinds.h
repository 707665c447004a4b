#pragma once
// What a path names, by its extension.
#include <filesystem>
#include <string>

namespace patina {

// The path's extension in lower case (".png" for "SHOT.PNG"), "" for none.
std::string lowerExtension(const std::filesystem::path& path);
// ".gltf" or ".glb" for a path ending so in any case, else "".
std::string gltfExtension(const std::filesystem::path& path);

}  // namespace patina
