#pragma once
// The GLB container (glTF 2.0 binary): a 12-byte header, a JSON chunk, an optional BIN chunk.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace patina::gltf {

bool looksLikeGlb(const std::vector<uint8_t>& bytes);   // starts with the magic "glTF"

struct GlbChunks {
    std::string_view json;
    const uint8_t* bin = nullptr;   // null without a BIN chunk
    size_t binSize = 0;
    bool onlyJsonAndBin = true;     // no chunks of other types after them
};

// Checks the whole layout before anything reads a chunk: version 2, a length equal to the
// file's, chunks that fit and are 4-byte aligned, JSON first, at most one BIN and only second.
// Throws InputError("SOURCE: ...") otherwise. The views point into `bytes`.
GlbChunks splitGlb(const std::vector<uint8_t>& bytes, const std::string& source);

// A GLB of the JSON (padded with spaces) and, when not empty, the BIN chunk (padded with zeros).
std::vector<uint8_t> joinGlb(std::string_view json, const uint8_t* bin, size_t binSize);

}  // namespace patina::gltf
