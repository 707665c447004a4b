#pragma once
// The PNG container (PNG spec, 2nd edition, 5.2-5.3): signature and length-type-data-CRC chunks,
// shared by the encoder (image.cpp) and the text chunk reader and writer (png_text.cpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace patina {

inline constexpr std::array<uint8_t, 8> kPngSignature{137, 80, 78, 71, 13, 10, 26, 10};

uint32_t readBigEndian32(const uint8_t* p);
void appendBigEndian32(std::vector<uint8_t>& out, uint32_t value);
// CRC-32 of Annex D (zlib's crc32) over a chunk's type and data.
uint32_t pngCrc(const uint8_t* data, size_t size);
// Appends length, `type` (four letters), `data` and the CRC.
void appendPngChunk(std::vector<uint8_t>& out, const char (&type)[5], const uint8_t* data, size_t size);

}  // namespace patina
