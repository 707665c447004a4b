#pragma once
// The PNG CRC-32 (PNG spec Annex D), bit by bit, unlike the engine's table: an independent
// check for tests/test_png_text.cpp, and the fix-up tests/fuzz/fuzz_png.cpp applies.
#include <cstddef>
#include <cstdint>

namespace patina::test {

inline uint32_t pngCrc(const uint8_t* bytes, size_t size) {
    uint32_t crc = 0xFFFFFFFFu;
    for (size_t i = 0; i < size; ++i) {
        crc ^= bytes[i];
        for (int bit = 0; bit < 8; ++bit) {
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
        }
    }
    return ~crc;
}

}  // namespace patina::test
