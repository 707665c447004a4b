#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "common/hdr_image.h"
#include "common/ldr_image.h"

namespace patina {

// PNG bytes of the image (opaque RGB), or an exception on failure. Compressed on up to
// `threads` threads (0: one per core, at most 8), each a band of rows (png_stream.h).
std::vector<uint8_t> encodePng(const LdrImage& image, unsigned threads = 0);
LdrImage decodePng(const std::vector<uint8_t>& bytes);   // throws std::runtime_error

// Portable float map (little-endian "PF"), the usual linear HDR interchange format.
std::vector<uint8_t> encodePfm(const HdrImage& image);
HdrImage decodePfm(const std::vector<uint8_t>& bytes);   // throws std::runtime_error

}  // namespace patina
