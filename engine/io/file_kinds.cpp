#include "io/file_kinds.h"

#include <algorithm>
#include <cctype>

namespace patina {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

std::string gltfExtension(const std::filesystem::path& path) {
    const std::string extension = lowerExtension(path);
    return extension == ".gltf" || extension == ".glb" ? extension : std::string();
}

}  // namespace patina
