#pragma once
// What a path names, by its extension.
#include <filesystem>
#include <string>

namespace patina {

// ".gltf" or ".glb" for a path ending so in any case, else "".
std::string gltfExtension(const std::filesystem::path& path);

}  // namespace patina
