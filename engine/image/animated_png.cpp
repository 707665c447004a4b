#include "image/animated_png.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "image/png_chunks.h"

namespace patina {

namespace {
// A PNG's header data (IHDR's 13 bytes) and its image data, IDAT by IDAT.
struct PngParts {
    std::vector<uint8_t> header;
    std::vector<std::vector<uint8_t>> imageData;
};

PngParts pngParts(const std::vector<uint8_t>& png, size_t frame) {
    const std::string which = "frame " + std::to_string(frame) + ": ";
    if (png.size() < kPngSignature.size() || !std::equal(kPngSignature.begin(), kPngSignature.end(), png.begin())) {
        throw std::invalid_argument(which + "not a PNG");
    }
    PngParts parts;
    size_t at = kPngSignature.size();
    while (at + 12 <= png.size()) {
        const uint32_t length = readBigEndian32(&png[at]);
        if (length > png.size() - at - 12) {
            throw std::invalid_argument(which + "a chunk runs past the end of the PNG");
        }
        const std::string type(png.begin() + std::ptrdiff_t(at + 4), png.begin() + std::ptrdiff_t(at + 8));
        const auto data = png.begin() + std::ptrdiff_t(at + 8);
        if (type == "IHDR") {
            parts.header.assign(data, data + length);
        } else if (type == "IDAT") {
            parts.imageData.emplace_back(data, data + length);
        } else if (type == "IEND") {
            break;
        }
        at += 12 + size_t(length);
    }
    if (parts.header.size() != 13 || parts.imageData.empty()) {
        throw std::invalid_argument(which + "a PNG without its header or image data");
    }
    return parts;
}

void appendBigEndian16(std::vector<uint8_t>& out, uint16_t value) {
    out.push_back(uint8_t(value >> 8));
    out.push_back(uint8_t(value));
}

// fcTL: the frame covers the whole image (width and height from IHDR's first 8 bytes, offset
// 0, 0), shown for `delay`, dispose_op 0 (none) and blend_op 0 (source).
void appendFrameControl(std::vector<uint8_t>& out, uint32_t sequence, const std::vector<uint8_t>& header,
                        FrameDelay delay) {
    std::vector<uint8_t> data;
    appendBigEndian32(data, sequence);
    data.insert(data.end(), header.begin(), header.begin() + 8);
    appendBigEndian32(data, 0);
    appendBigEndian32(data, 0);
    appendBigEndian16(data, delay.numerator);
    appendBigEndian16(data, delay.denominator);
    data.push_back(0);
    data.push_back(0);
    appendPngChunk(out, "fcTL", data.data(), data.size());
}
}  // namespace

std::vector<uint8_t> encodeAnimatedPng(const std::vector<std::vector<uint8_t>>& framePngs, FrameDelay delay) {
    if (framePngs.empty()) {
        throw std::invalid_argument("an animated PNG needs a frame at least");
    }
    const PngParts first = pngParts(framePngs[0], 0);
    std::vector<uint8_t> out(kPngSignature.begin(), kPngSignature.end());
    appendPngChunk(out, "IHDR", first.header.data(), first.header.size());
    std::vector<uint8_t> animation;
    appendBigEndian32(animation, uint32_t(framePngs.size()));   // num_frames
    appendBigEndian32(animation, 0);                            // num_plays: for ever
    appendPngChunk(out, "acTL", animation.data(), animation.size());
    uint32_t sequence = 0;   // fcTL and fdAT share one sequence from 0
    appendFrameControl(out, sequence++, first.header, delay);
    for (const std::vector<uint8_t>& data : first.imageData) {
        appendPngChunk(out, "IDAT", data.data(), data.size());
    }
    for (size_t frame = 1; frame < framePngs.size(); ++frame) {
        const PngParts parts = pngParts(framePngs[frame], frame);
        if (parts.header != first.header) {
            throw std::invalid_argument("frame " + std::to_string(frame) + ": its size or pixel format is not the "
                                        "first frame's");
        }
        appendFrameControl(out, sequence++, first.header, delay);
        for (const std::vector<uint8_t>& data : parts.imageData) {
            std::vector<uint8_t> chunk;
            appendBigEndian32(chunk, sequence++);
            chunk.insert(chunk.end(), data.begin(), data.end());
            appendPngChunk(out, "fdAT", chunk.data(), chunk.size());
        }
    }
    appendPngChunk(out, "IEND", nullptr, 0);
    return out;
}

}  // namespace patina
