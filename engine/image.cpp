#include "image.h"

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

namespace patina {

namespace {
std::string systemError(const std::string& what, const std::filesystem::path& path) {
    return what + " '" + path.string() + "': " + std::strerror(errno);
}
}  // namespace

LdrImage decodePng(const std::vector<uint8_t>& bytes) {
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height,
                                            &channels, 4);
    if (!pixels) {
        throw std::runtime_error(std::string("not a readable PNG: ") + stbi_failure_reason());
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

std::vector<uint8_t> readFileBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw std::runtime_error(systemError("cannot open", path));
    }
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                               std::istreambuf_iterator<char>());
    if (file.bad()) {
        throw std::runtime_error(systemError("cannot read", path));
    }
    return bytes;
}

void writeFileAtomic(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
    const std::filesystem::path directory =
        path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::string pattern = (directory / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) {
        throw std::runtime_error(systemError("cannot create a temporary file beside", path));
    }
    size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            const std::string message = systemError("cannot write", path);
            ::close(fd);
            ::unlink(pattern.c_str());
            throw std::runtime_error(message);
        }
        written += size_t(n);
    }
    // mkstemp makes the file 0600; give it the usual permissions of a new file.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    const bool synced = ::fsync(fd) == 0;
    const bool closed = ::close(fd) == 0;
    if (!synced || !closed) {
        const std::string message = systemError("cannot flush", path);
        ::unlink(pattern.c_str());
        throw std::runtime_error(message);
    }
    if (std::rename(pattern.c_str(), path.c_str()) != 0) {
        const std::string message = systemError("cannot replace", path);
        ::unlink(pattern.c_str());
        throw std::runtime_error(message);
    }
    // The rename is durable once the folder is flushed too. Best effort: the new file is
    // complete and in place already, and some file systems refuse fsync on a folder.
    if (const int folder = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY); folder >= 0) {
        ::fsync(folder);
        ::close(folder);
    }
}

}  // namespace patina
