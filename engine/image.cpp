#include "image.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <future>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb_image.h>
#include <zlib.h>

#include "png_chunks.h"

namespace patina {

namespace {
std::string systemError(const std::string& what, const std::filesystem::path& path) {
    return what + " '" + path.string() + "': " + std::strerror(errno);
}
}  // namespace

namespace {
// Rows [first, last) of a PNG's image data, each with the Sub filter (each byte minus the one
// 4 to its left), as raw deflate at level 1 that ends on a byte boundary (Z_SYNC_FLUSH), or
// with the stream's final block for the last band; and the Adler-32 of those filtered bytes.
struct Band {
    std::vector<uint8_t> deflated;
    uLong adler = 0;
    size_t filteredBytes = 0;
};

Band deflateBand(const LdrImage& image, int first, int last, bool final) {
    const size_t stride = size_t(image.width) * 4;
    // Ends the stream however this function leaves (an allocation below can throw).
    struct Deflate {
        z_stream zs{};
        Deflate() {
            if (deflateInit2(&zs, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
                throw std::runtime_error("zlib: cannot start compressing");
            }
        }
        ~Deflate() { deflateEnd(&zs); }
    } stream;
    z_stream& zs = stream.zs;
    Band band;
    band.filteredBytes = (stride + 1) * size_t(last - first);
    band.adler = adler32(0L, Z_NULL, 0);
    // deflateBound is what the whole band can take (plus a sync flush's 5 bytes), so one
    // output buffer holds it (a 16384 x 16384 image is 1 GiB raw: inside zlib's 32-bit counts).
    band.deflated.resize(deflateBound(&zs, uLong(band.filteredBytes)) + 16);
    zs.next_out = band.deflated.data();
    zs.avail_out = uInt(band.deflated.size());
    std::vector<uint8_t> row(stride + 1);
    row[0] = 1;   // Sub
    for (int y = first; y < last; ++y) {
        const uint8_t* pixels = &image.rgba[size_t(y) * stride];
        std::copy_n(pixels, std::min<size_t>(4, stride), &row[1]);
        for (size_t i = 4; i < stride; ++i) {
            row[1 + i] = uint8_t(pixels[i] - pixels[i - 4]);
        }
        band.adler = adler32(band.adler, row.data(), uInt(row.size()));
        zs.next_in = row.data();
        zs.avail_in = uInt(row.size());
        const int flush = y + 1 < last ? Z_NO_FLUSH : final ? Z_FINISH : Z_SYNC_FLUSH;
        const int status = deflate(&zs, flush);
        if ((flush == Z_FINISH ? status != Z_STREAM_END : status != Z_OK) || zs.avail_in != 0) {
            throw std::runtime_error("zlib: compressing the PNG failed");
        }
    }
    band.deflated.resize(zs.total_out);
    return band;
}
}  // namespace

// PNG (spec 2nd ed.): 8-bit RGBA, every row with the Sub filter, one zlib stream at level 1.
// stb's writer tries five filters per row at level 8: on a 3072x2048 contact sheet it took
// 0.45 s for 2.2 MB where one stream like this took 0.10 s for 2.1 MB. Bands of rows are
// deflated on a thread each, as pigz does: each band starts with an empty dictionary and
// ends on a byte boundary, so the bands joined are one deflate stream, and their Adler-32s
// combine (RFC 1950, 1951). It costs a few bytes per band.
std::vector<uint8_t> encodePng(const LdrImage& image, unsigned threads) {
    const size_t stride = size_t(std::max(image.width, 0)) * 4;
    if (image.width <= 0 || image.height <= 0 || image.width > 0x7FFFFFFF / 4 ||
        image.rgba.size() != stride * size_t(image.height)) {
        throw std::runtime_error("cannot encode a " + std::to_string(image.width) + "x" +
                                 std::to_string(image.height) + " PNG");
    }
    // A band of at least 256 KiB raw, so a thread's start is a small part of it.
    const size_t rowsPerBand = std::max<size_t>(1, (size_t(256) << 10) / (stride + 1));
    if (threads == 0) {
        threads = std::min(std::thread::hardware_concurrency(), 8u);
    }
    const size_t bands = std::clamp<size_t>(threads, 1, (size_t(image.height) + rowsPerBand - 1) / rowsPerBand);
    auto bandRows = [&](size_t band) { return int(size_t(image.height) * band / bands); };
    std::vector<std::future<Band>> others;
    for (size_t band = 1; band < bands; ++band) {
        others.push_back(std::async(std::launch::async, deflateBand, std::cref(image), bandRows(band),
                                    bandRows(band + 1), band + 1 == bands));
    }
    std::vector<Band> deflated;
    deflated.push_back(deflateBand(image, 0, bandRows(1), bands == 1));
    for (std::future<Band>& band : others) {
        deflated.push_back(band.get());
    }

    std::vector<uint8_t> compressed = {0x78, 0x01};   // zlib: deflate, 32 KiB window, fastest
    uLong adler = deflated.front().adler;
    for (size_t band = 0; band < deflated.size(); ++band) {
        compressed.insert(compressed.end(), deflated[band].deflated.begin(), deflated[band].deflated.end());
        if (band > 0) {
            adler = adler32_combine(adler, deflated[band].adler, z_off_t(deflated[band].filteredBytes));
        }
    }
    appendBigEndian32(compressed, uint32_t(adler));

    std::vector<uint8_t> png(kPngSignature.begin(), kPngSignature.end());
    std::vector<uint8_t> header;
    appendBigEndian32(header, uint32_t(image.width));
    appendBigEndian32(header, uint32_t(image.height));
    header.insert(header.end(), {8, 6, 0, 0, 0});   // 8 bits, RGBA, deflate, adaptive filters, no interlace
    appendPngChunk(png, "IHDR", header.data(), header.size());
    appendPngChunk(png, "IDAT", compressed.data(), compressed.size());
    appendPngChunk(png, "IEND", nullptr, 0);
    return png;
}

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
