#pragma once
// What an export writes: files as bytes, named as a .gltf names them, written all or none.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace patina {

struct OutputFile {
    std::filesystem::path path;
    std::vector<uint8_t> bytes;
};

// RFC 4648 base64, as a data: URI holds its bytes.
std::string base64(const std::vector<uint8_t>& bytes);

// A file name as a URI path: everything but RFC 3986's unreserved characters percent-encoded.
std::string uriOfFileName(const std::string& name);

// Writes each file atomically, in order; if one cannot be written, those written before it
// are removed again. Throws std::runtime_error naming the path.
void writeOutputFiles(const std::vector<OutputFile>& files);

}  // namespace patina
