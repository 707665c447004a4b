// The animated PNG writer (image/animated_png.h): the chunk sequence of the APNG specification
// (PNG 3rd edition: acTL before the image data, fcTL and fdAT numbered from 0 in one sequence),
// every CRC right, the default image the first frame, and each frame's image data the frame's own.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/animated_png.h"
#include "image/image.h"
#include "image/png_chunks.h"
#include "png_crc.h"

namespace patina {
namespace {

struct Chunk {
    std::string type;
    std::vector<uint8_t> data;
};

// The chunks after the signature, each CRC checked with the tests' own CRC-32.
std::vector<Chunk> chunksOf(const std::vector<uint8_t>& png) {
    std::vector<Chunk> chunks;
    EXPECT_TRUE(png.size() > 8 && std::equal(kPngSignature.begin(), kPngSignature.end(), png.begin()));
    size_t at = 8;
    while (at + 12 <= png.size()) {
        const uint32_t length = readBigEndian32(&png[at]);
        Chunk chunk{std::string(png.begin() + std::ptrdiff_t(at + 4), png.begin() + std::ptrdiff_t(at + 8)),
                    std::vector<uint8_t>(png.begin() + std::ptrdiff_t(at + 8),
                                         png.begin() + std::ptrdiff_t(at + 8 + length))};
        EXPECT_EQ(readBigEndian32(&png[at + 8 + length]), test::pngCrc(&png[at + 4], length + 4)) << chunk.type;
        chunks.push_back(std::move(chunk));
        at += 12 + length;
    }
    EXPECT_EQ(at, png.size());
    return chunks;
}

LdrImage stripes(int width, int height, uint8_t shade) {
    LdrImage image{width, height, std::vector<uint8_t>(size_t(width * height * 4), 255)};
    for (int i = 0; i < width * height; ++i) {
        image.rgba[size_t(i) * 4] = uint8_t(shade + i % 7 * 20);
        image.rgba[size_t(i) * 4 + 1] = shade;
    }
    return image;
}

uint32_t number(const std::vector<uint8_t>& data, size_t at) {
    return readBigEndian32(&data[at]);
}

TEST(AnimatedPng, HasTheApngChunksInOrderAndEachFrameIsItsImage) {
    const std::vector<LdrImage> frames{stripes(9, 5, 10), stripes(9, 5, 90), stripes(9, 5, 170)};
    std::vector<std::vector<uint8_t>> pngs;
    for (const LdrImage& frame : frames) {
        pngs.push_back(encodePng(frame));
    }
    const std::vector<uint8_t> apng = encodeAnimatedPng(pngs, {1, 24});
    const std::vector<Chunk> chunks = chunksOf(apng);
    std::string sequence;
    for (const Chunk& chunk : chunks) {
        sequence += chunk.type + " ";
    }
    EXPECT_EQ(sequence, "IHDR acTL fcTL IDAT fcTL fdAT fcTL fdAT IEND ");
    ASSERT_EQ(chunks.size(), 9u);
    EXPECT_EQ(number(chunks[1].data, 0), 3u);   // num_frames
    EXPECT_EQ(number(chunks[1].data, 4), 0u);   // num_plays: for ever
    // fcTL: sequence, the whole image at 0, 0, 1/24 s, dispose none, blend source.
    uint32_t expected = 0;
    for (const size_t at : {2u, 4u, 6u}) {
        const std::vector<uint8_t>& control = chunks[at].data;
        ASSERT_EQ(control.size(), 26u);
        EXPECT_EQ(number(control, 0), expected++);
        EXPECT_EQ(number(control, 4), 9u);
        EXPECT_EQ(number(control, 8), 5u);
        EXPECT_EQ(number(control, 12), 0u);
        EXPECT_EQ(number(control, 16), 0u);
        EXPECT_EQ(control[20] << 8 | control[21], 1);
        EXPECT_EQ(control[22] << 8 | control[23], 24);
        EXPECT_EQ(control[24], 0);
        EXPECT_EQ(control[25], 0);
        if (at > 2) {
            EXPECT_EQ(number(chunks[at + 1].data, 0), expected++);   // fdAT's
        }
    }
    // A reader without APNG shows the first frame; each fdAT without its number, as a PNG's
    // IDAT, is its frame.
    EXPECT_EQ(decodePng(apng).rgba, frames[0].rgba);
    for (const size_t at : {5u, 7u}) {
        std::vector<uint8_t> alone(kPngSignature.begin(), kPngSignature.end());
        appendPngChunk(alone, "IHDR", chunks[0].data.data(), chunks[0].data.size());
        appendPngChunk(alone, "IDAT", chunks[at].data.data() + 4, chunks[at].data.size() - 4);
        appendPngChunk(alone, "IEND", nullptr, 0);
        EXPECT_EQ(decodePng(alone).rgba, frames[at / 2 - 1].rgba) << "frame " << at / 2 - 1;
    }
}

TEST(AnimatedPng, OneFrameIsAStillAnimation) {
    const std::vector<uint8_t> apng = encodeAnimatedPng({encodePng(stripes(4, 4, 50))});
    std::string sequence;
    for (const Chunk& chunk : chunksOf(apng)) {
        sequence += chunk.type + " ";
    }
    EXPECT_EQ(sequence, "IHDR acTL fcTL IDAT IEND ");
}

TEST(AnimatedPng, RefusesNoFramesFramesOfAnotherSizeAndWhatIsNoPng) {
    EXPECT_THROW(encodeAnimatedPng({}), std::invalid_argument);
    EXPECT_THROW(encodeAnimatedPng({encodePng(stripes(4, 4, 0)), encodePng(stripes(5, 4, 0))}), std::invalid_argument);
    EXPECT_THROW(encodeAnimatedPng({encodePng(stripes(4, 4, 0)), std::vector<uint8_t>{1, 2, 3}}),
                 std::invalid_argument);
}

}  // namespace
}  // namespace patina
