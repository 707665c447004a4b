#include "image/png_chunks.h"

#include <zlib.h>

namespace patina {

uint32_t readBigEndian32(const uint8_t* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

void appendBigEndian32(std::vector<uint8_t>& out, uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) {
        out.push_back(uint8_t(value >> shift));
    }
}

uint32_t pngCrc(const uint8_t* data, size_t size) {
    uLong crc = crc32(0L, Z_NULL, 0);
    // zlib takes uInt lengths: feed a 4 GiB chunk (never written, but readable) in pieces.
    while (size > 0) {
        const uInt piece = uInt(std::min<size_t>(size, 1u << 30));
        crc = crc32(crc, data, piece);
        data += piece;
        size -= piece;
    }
    return uint32_t(crc);
}

void appendPngChunk(std::vector<uint8_t>& out, const char (&type)[5], const uint8_t* data, size_t size) {
    appendBigEndian32(out, uint32_t(size));
    const size_t typeAt = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data, data + size);
    appendBigEndian32(out, pngCrc(out.data() + typeAt, size + 4));
}

}  // namespace patina
