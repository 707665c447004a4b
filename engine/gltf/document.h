#pragma once
// A glTF file loaded into tinygltf's model: bounded and confined (files.h, glb.h, json_check.h)
// before tinygltf sees it, and the required extensions checked (glTF 2.0 section 3.12).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace patina::gltf {

// The model at `path`, whose file holds `bytes` (read by the caller: readModelFile); `source`
// names it in messages; the files it names are read from its folder. Images are not decoded here: an image
// read from a file or a data: URI keeps its encoded bytes in `image` with `as_is` set (one in a
// buffer view keeps its view); one whose file is missing has neither. Throws InputError.
tinygltf::Model loadDocument(const std::filesystem::path& path, const std::vector<uint8_t>& bytes,
                             const std::string& source);

}  // namespace patina::gltf
