#include "image/image.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb_image.h>

#include "common/decoder_reason.h"

namespace patina {

LdrImage decodePng(const std::vector<uint8_t>& bytes) {
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height,
                                            &channels, 4);
    if (!pixels) {
        throw std::runtime_error(std::string("not a readable PNG: ") + decoderReason(stbi_failure_reason()));
    }
    LdrImage image{width, height, std::vector<uint8_t>(pixels, pixels + size_t(width) * height * 4)};
    stbi_image_free(pixels);
    return image;
}

std::vector<uint8_t> encodePfm(const HdrImage& image) {
    std::string header = "PF\n" + std::to_string(image.width) + " " +
                         std::to_string(image.height) + "\n-1.0\n";   // negative: little-endian
    std::vector<uint8_t> bytes(header.begin(), header.end());
    const size_t rowFloats = size_t(image.width) * 3;
    // PFM stores rows bottom to top.
    for (int row = image.height - 1; row >= 0; --row) {
        const auto* begin = reinterpret_cast<const uint8_t*>(image.rgb.data() + row * rowFloats);
        bytes.insert(bytes.end(), begin, begin + rowFloats * sizeof(float));
    }
    return bytes;
}

HdrImage decodePfm(const std::vector<uint8_t>& bytes) {
    std::istringstream stream(std::string(bytes.begin(), bytes.end()));
    std::string magic;
    HdrImage image;
    double scale = 0.0;
    stream >> magic >> image.width >> image.height >> scale;
    if (!stream || magic != "PF" || image.width <= 0 || image.height <= 0 || scale >= 0.0) {
        throw std::runtime_error("not a little-endian RGB PFM");
    }
    stream.get();   // the single whitespace byte after the scale
    const size_t rowFloats = size_t(image.width) * 3;
    const size_t offset = size_t(stream.tellg());
    if (bytes.size() - offset != rowFloats * image.height * sizeof(float)) {
        throw std::runtime_error("PFM pixel data has the wrong size");
    }
    image.rgb.resize(rowFloats * image.height);
    for (int row = 0; row < image.height; ++row) {
        std::memcpy(image.rgb.data() + (image.height - 1 - row) * rowFloats,
                    bytes.data() + offset + row * rowFloats * sizeof(float),
                    rowFloats * sizeof(float));
    }
    return image;
}

}  // namespace patina
