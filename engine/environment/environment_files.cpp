#include "environment/environment_files.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <optional>
#include <set>
#include <string_view>

#include <IexBaseExc.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfRgbaFile.h>
#include <stb_image.h>

#include "common/one_line.h"
#include "environment/equirect.h"
#include "files/input_error.h"
#include "files/regular_file.h"

namespace patina {

namespace {

constexpr uint64_t kMaxEnvironmentFileBytes = uint64_t(512) << 20;
constexpr std::string_view kFormats = "environment images are read from Radiance HDR (.hdr) and OpenEXR (.exr) files";

// Up to 40 characters of a line or a name from the file, fit to quote in a message.
std::string shown(std::string_view text) {
    std::string out;
    for (const char c : text.substr(0, 40)) {
        out += c >= 0x20 && c < 0x7f ? c : '?';
    }
    return text.size() > 40 ? out + "..." : out;
}

void requireSize(long long width, long long height, const std::string& name) {
    if (const std::string problem = environmentSizeProblem(width, height); !problem.empty()) {
        throw InputError(name + " " + problem + " (" + std::to_string(width) + " x " + std::to_string(height) + ")");
    }
}

// ---------------------------------------------------------------------------------------------
// Radiance RGBE (Greg Ward, "Real Pixels", Graphics Gems II; the Radiance file format notes), as
// Debian's stb_image 2.27 reads it (stbi__hdr_load). stb trusts the file: a truncated run-length
// scanline makes it read a count of 0 forever (CVE-2021-42715), short flat data leaves pixels
// uninitialised, and a flat scanline after run-length ones restarts decoding at the top. So the
// whole structure is walked here first, and stb only sees files it decodes as this walk reads them.

struct RgbeLayout {
    int width = 0;
    int height = 0;
    size_t pixelsAt = 0;   // the first byte after the resolution line
};

class RgbeWalk {
public:
    RgbeWalk(const std::vector<uint8_t>& bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    RgbeLayout header();
    void pixels(const RgbeLayout& layout);

private:
    std::string_view line();
    void flat(const RgbeLayout& layout, size_t at) const;
    size_t scanline(const RgbeLayout& layout, size_t at, int row) const;
    [[noreturn]] void fail(const std::string& what) const { throw InputError(name_ + ": " + what); }

    const std::vector<uint8_t>& bytes_;
    const std::string& name_;
    size_t at_ = 0;
};

// The next header line, without its '\n', as stbi__hdr_gettoken sees it: cut at its first NUL
// and after 1023 characters.
std::string_view RgbeWalk::line() {
    const auto* start = bytes_.data() + at_;
    const auto* end = static_cast<const uint8_t*>(std::memchr(start, '\n', bytes_.size() - at_));
    if (!end) {
        fail("truncated: the header ends without a blank line and a resolution line");
    }
    at_ += size_t(end - start) + 1;
    std::string_view token(reinterpret_cast<const char*>(start), size_t(end - start));
    return token.substr(0, std::min({token.find('\0'), token.size(), size_t(1023)}));
}

// Decimal digits at `text`'s start, consumed; saturating, so that a huge count stays huge.
std::optional<long long> leadingNumber(std::string_view& text) {
    size_t digits = 0;
    long long value = 0;
    for (; digits < text.size() && text[digits] >= '0' && text[digits] <= '9'; ++digits) {
        value = std::min(value * 10 + (text[digits] - '0'), 1LL << 40);
    }
    text.remove_prefix(digits);
    return digits > 0 ? std::optional(value) : std::nullopt;
}

// "-Y H +X W" exactly: rows top to bottom, pixels left to right, the only orientation stb reads
// (it would read "+Y H +X W" upside down without a word).
std::optional<std::pair<long long, long long>> parseResolution(std::string_view text) {
    if (!text.starts_with("-Y ")) {
        return std::nullopt;
    }
    text.remove_prefix(3);
    const std::optional<long long> height = leadingNumber(text);
    const size_t spaces = text.find_first_not_of(' ');
    if (!height || spaces == 0 || spaces == std::string_view::npos) {
        return std::nullopt;
    }
    text.remove_prefix(spaces);
    if (!text.starts_with("+X ")) {
        return std::nullopt;
    }
    text.remove_prefix(3);
    const std::optional<long long> width = leadingNumber(text);
    if (!width || !text.empty()) {
        return std::nullopt;
    }
    return std::pair(*height, *width);
}

RgbeLayout RgbeWalk::header() {
    // stbi__hdr_test: the signature and its newline, or stb hands the bytes to its other loaders.
    const std::string_view start(reinterpret_cast<const char*>(bytes_.data()), std::min(bytes_.size(), size_t(16)));
    if (!start.starts_with("#?RADIANCE\n") && !start.starts_with("#?RGBE\n")) {
        fail("not a Radiance HDR file: its first line is not \"#?RADIANCE\" or \"#?RGBE\"");
    }
    line();
    bool rgbe = false;
    for (std::string_view token = line(); !token.empty(); token = line()) {
        if (token.starts_with("FORMAT=")) {
            if (token != "FORMAT=32-bit_rle_rgbe") {
                fail("the pixel format \"" + shown(token.substr(7)) +
                     "\" is not supported; only 32-bit_rle_rgbe is read");
            }
            rgbe = true;
        }
    }
    if (!rgbe) {
        fail("the header has no FORMAT=32-bit_rle_rgbe line");
    }
    const std::string_view resolution = line();
    const auto size = parseResolution(resolution);
    if (!size) {
        fail("the resolution line \"" + shown(resolution) +
             "\" is not supported; only \"-Y height +X width\" (rows from the top) is read");
    }
    requireSize(size->second, size->first, name_);
    return {int(size->second), int(size->first), at_};
}

// Four bytes (R, G, B, shared exponent) a pixel, row after row.
void RgbeWalk::flat(const RgbeLayout& layout, size_t at) const {
    const size_t rowBytes = size_t(layout.width) * 4;
    const size_t available = bytes_.size() - at;
    if (available / rowBytes < size_t(layout.height)) {
        fail("truncated: the pixel data ends at row " + std::to_string(available / rowBytes) + " of " +
             std::to_string(layout.height));
    }
}

// One run-length scanline from `at` (2, 2, width as 15 bits, then each channel's runs and dumps);
// where the next one starts.
size_t RgbeWalk::scanline(const RgbeLayout& layout, size_t at, int row) const {
    const std::string where = " at row " + std::to_string(row);
    const auto need = [&](size_t count) {
        if (bytes_.size() - at < count) {
            fail("truncated: the file ends" + where + " of " + std::to_string(layout.height));
        }
    };
    need(4);
    const int width = bytes_[at + 2] << 8 | bytes_[at + 3];
    if (width != layout.width) {
        fail("the scanline header" + where + " gives a width of " + std::to_string(width) + ", not " +
             std::to_string(layout.width));
    }
    at += 4;
    for (int channel = 0; channel < 4; ++channel) {
        for (int x = 0; x < layout.width;) {
            need(1);
            const int count = bytes_[at] > 128 ? bytes_[at] - 128 : bytes_[at];
            const bool run = bytes_[at] > 128;
            ++at;
            if (count == 0) {   // stb loops forever on it (CVE-2021-42715); no writer makes one
                fail("a run of length 0" + where);
            }
            if (count > layout.width - x) {
                fail("a run of " + std::to_string(count) + " pixels overflows the scanline" + where);
            }
            need(run ? 1 : size_t(count));
            at += run ? 1 : size_t(count);
            x += count;
        }
    }
    return at;
}

void RgbeWalk::pixels(const RgbeLayout& layout) {
    // Narrow and very wide images are always flat (stbi__hdr_load); others are run-length encoded
    // unless their first scanline does not start with a run-length header.
    if (layout.width < 8 || layout.width >= 32768) {
        return flat(layout, layout.pixelsAt);
    }
    size_t at = layout.pixelsAt;
    for (int row = 0; row < layout.height; ++row) {
        const bool runLength =
            bytes_.size() - at >= 3 && bytes_[at] == 2 && bytes_[at + 1] == 2 && !(bytes_[at + 2] & 0x80);
        if (!runLength && row == 0 && bytes_.size() - at >= 4) {
            return flat(layout, at);
        }
        if (!runLength && row > 0 && bytes_.size() - at >= 4) {
            fail("row " + std::to_string(row) + " is flat after run-length encoded rows; mixing them is not supported");
        }
        at = scanline(layout, at, row);
    }
}

// ---------------------------------------------------------------------------------------------
// OpenEXR ("The OpenEXR File Layout", openexr.com). OpenEXR 3.1 sizes its tables and buffers from
// the header before reading any pixel: line or tile offsets from the data window and tile size,
// line buffers from the channels. So the first header is walked here, as Header::readFrom reads
// it, and a file whose image, channels or tiles would take too much is refused before OpenEXR
// sees it.

constexpr uint32_t kExrTiled = 0x200, kExrLongNames = 0x400, kExrDeep = 0x800, kExrMultiPart = 0x1000;
// One scanline of every channel: 16 float channels 16384 pixels wide. OpenEXR reads up to 256 lines
// at once (DWAB).
constexpr uint64_t kMaxExrScanlineBytes = uint64_t(1) << 20;
constexpr uint64_t kMaxExrTileBytes = uint64_t(64) << 20;
// Of the cached row of tiles InputFile keeps: width x tile height pixels.
constexpr uint64_t kMaxExrTileRowPixels = uint64_t(1) << 24;
constexpr uint64_t kMaxExrTiles = uint64_t(1) << 22;

struct ExrChannel {
    std::string name;
    int32_t type = 0;   // 0 UINT, 1 HALF, 2 FLOAT
    int32_t xSampling = 1;
    int32_t ySampling = 1;
};

struct ExrTiles {
    uint32_t xSize = 0;
    uint32_t ySize = 0;
    uint8_t mode = 0;   // level mode in the low 4 bits
};

enum class ExrColour { Rgb, Luminance, LuminanceChroma };

struct ExrLayout {
    int32_t minX = 0, minY = 0, maxX = 0, maxY = 0;
    ExrColour colour = ExrColour::Rgb;
};

// The bytes of a value as the attribute's type reads them in OpenEXR 3.1, for the fixed-size types
// (their readValueFrom ignores the size field, so a wrong one would make the walk and OpenEXR part
// ways). -1: a type whose value is as long as its size says (string, preview, opaque types...).
int fixedValueSize(std::string_view type) {
    static constexpr std::pair<std::string_view, int> kSizes[] = {
        {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"deepImageState", 1},
        {"double", 8}, {"envmap", 1}, {"float", 4}, {"int", 4}, {"keycode", 28}, {"lineOrder", 1},
        {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"rational", 8}, {"tiledesc", 9},
        {"timecode", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12}, {"v3d", 24}};
    for (const auto& [name, size] : kSizes) {
        if (name == type) {
            return size;
        }
    }
    return -1;
}

class ExrWalk {
public:
    ExrWalk(const std::vector<uint8_t>& bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    ExrLayout check();

private:
    void version();
    void attributes();
    void attribute(const std::string& attributeName, std::string_view type, size_t size);
    void channelList(size_t size);
    std::string text(const char* what);
    int32_t int32At(size_t at) const;
    void require(size_t count, const std::string& what) const;
    ExrColour colour() const;
    void checkScanlines(long long width) const;
    void checkTiles(long long width, long long height) const;
    [[noreturn]] void fail(const std::string& what) const { throw InputError(name_ + ": " + what); }

    const std::vector<uint8_t>& bytes_;
    const std::string& name_;
    size_t at_ = 0;
    std::optional<std::array<int32_t, 4>> dataWindow_;
    std::optional<std::vector<ExrChannel>> channels_;
    std::optional<ExrTiles> tiles_;
};

int32_t ExrWalk::int32At(size_t at) const {
    return int32_t(uint32_t(bytes_[at]) | uint32_t(bytes_[at + 1]) << 8 | uint32_t(bytes_[at + 2]) << 16 |
                   uint32_t(bytes_[at + 3]) << 24);
}

void ExrWalk::require(size_t count, const std::string& what) const {
    if (bytes_.size() - at_ < count) {
        fail("truncated: the file ends in " + what);
    }
}

void ExrWalk::version() {
    require(8, "the version field");
    const uint32_t field = uint32_t(int32At(4));
    if ((field & 0xff) != 2) {
        fail("OpenEXR file version " + std::to_string(field & 0xff) + " is not supported (only 2)");
    }
    if (field & kExrMultiPart) {
        fail("a multi-part OpenEXR file is not supported; save the environment as a single-part image");
    }
    if (field & kExrDeep) {
        fail("deep OpenEXR data is not supported; save the environment as a flat image");
    }
    if (field & ~(0xffu | kExrTiled | kExrLongNames)) {
        fail("the version field has flags this reader does not know");
    }
    at_ = 8;
}

// A NUL-terminated name of at most 255 characters (Name::MAX_LENGTH, which 3.1 allows whatever the
// long-names flag says).
std::string ExrWalk::text(const char* what) {
    const size_t limit = std::min(bytes_.size() - at_, size_t(256));
    const auto* start = bytes_.data() + at_;
    const void* end = std::memchr(start, '\0', limit);
    if (!end) {
        fail(limit < 256 ? std::string("truncated: the file ends in ") + what
                         : std::string(what) + " is longer than 255 characters");
    }
    const size_t length = size_t(static_cast<const uint8_t*>(end) - start);
    at_ += length + 1;
    return {reinterpret_cast<const char*>(start), length};
}

void ExrWalk::channelList(size_t size) {
    const size_t start = at_;
    std::vector<ExrChannel> channels;
    for (std::string channelName = text("the channel list"); !channelName.empty();
         channelName = text("the channel list")) {
        require(16, "channel " + shown(channelName));
        channels.push_back({channelName, int32At(at_), int32At(at_ + 8), int32At(at_ + 12)});
        at_ += 16;   // type, pLinear and 3 reserved bytes, x and y sampling
    }
    if (at_ - start != size) {
        fail("the channel list takes " + std::to_string(at_ - start) + " bytes, but its size says " +
             std::to_string(size));
    }
    channels_ = std::move(channels);
}

void ExrWalk::attribute(const std::string& attributeName, std::string_view type, size_t size) {
    const auto expect = [&](std::string_view wanted) {
        if (type != wanted) {
            fail("attribute \"" + attributeName + "\" has type \"" + shown(type) + "\", not " + std::string(wanted));
        }
    };
    if (attributeName == "channels") {
        expect("chlist");
        return channelList(size);
    }
    if (attributeName == "dataWindow") {
        expect("box2i");
        dataWindow_ = {int32At(at_), int32At(at_ + 4), int32At(at_ + 8), int32At(at_ + 12)};
    } else if (attributeName == "tiles") {
        expect("tiledesc");
        tiles_ = ExrTiles{uint32_t(int32At(at_)), uint32_t(int32At(at_ + 4)), bytes_[at_ + 8]};
    }
    at_ += size;
}

void ExrWalk::attributes() {
    std::set<std::string> seen;
    for (std::string attributeName = text("an attribute name"); !attributeName.empty();
         attributeName = text("an attribute name")) {
        const std::string where = "attribute \"" + shown(attributeName) + "\"";
        const std::string type = text(("the type of " + where).c_str());
        require(4, where);
        const int32_t size = int32At(at_);
        at_ += 4;
        if (size < 0 || size_t(size) > bytes_.size() - at_) {
            fail("truncated: " + where + " says it takes " + std::to_string(size) + " bytes, more than are left");
        }
        const int fixed = fixedValueSize(type);
        if ((fixed >= 0 && size != fixed) || (type == "floatvector" && size % 4 != 0)) {
            fail(where + " of type " + shown(type) + " takes " + std::to_string(size) +
                 " bytes, which is not its size");
        }
        if (type == "idmanifest") {   // 3.1 reads 4 bytes more than its size says (ImfIDManifestAttribute.cpp)
            fail(where + " is an ID manifest, which is not supported in an environment image");
        }
        if (!seen.insert(attributeName).second) {
            fail(where + " appears twice");
        }
        attribute(attributeName, type, size_t(size));
    }
}

ExrColour ExrWalk::colour() const {
    const auto find = [&](std::string_view wanted) -> const ExrChannel* {
        for (const ExrChannel& channel : *channels_) {
            if (channel.name == wanted) {
                return &channel;
            }
        }
        return nullptr;
    };
    const auto whole = [&](const ExrChannel* channel) {
        if (channel->xSampling != 1 || channel->ySampling != 1) {
            fail("channel " + channel->name + " is subsampled, which is not supported");
        }
    };
    if (find("R") && find("G") && find("B")) {
        for (const char* wanted : {"R", "G", "B"}) {
            whole(find(wanted));
        }
        return ExrColour::Rgb;
    }
    if (const ExrChannel* luminance = find("Y")) {
        whole(luminance);
        return find("RY") || find("BY") ? ExrColour::LuminanceChroma : ExrColour::Luminance;
    }
    std::string names;
    for (size_t i = 0; i < channels_->size() && i < 8; ++i) {
        names += (i ? ", " : "") + shown((*channels_)[i].name);
    }
    fail("has no R, G and B channels, nor a Y channel: its channels are " +
         (names.empty() ? std::string("none") : names + (channels_->size() > 8 ? ", ..." : "")));
}

uint64_t bytesPerPixel(const std::vector<ExrChannel>& channels) {
    uint64_t bytes = 0;
    for (const ExrChannel& channel : channels) {
        bytes += channel.type == 1 ? 2 : 4;   // counted whole: subsampling only makes lines shorter
    }
    return bytes;
}

void ExrWalk::checkScanlines(long long width) const {
    const uint64_t perPixel = bytesPerPixel(*channels_);
    if (perPixel * uint64_t(width) > kMaxExrScanlineBytes) {
        fail("its " + std::to_string(channels_->size()) + " channels are too many to read at " + std::to_string(width) +
             " pixels wide (at most 1 MiB a scanline)");
    }
}

// Every level's tiles, counted as OpenEXR's TileOffsets allocates them, rounding level sizes up
// (the larger count) whatever the file's rounding mode.
uint64_t tileCount(const ExrTiles& tiles, long long width, long long height) {
    const auto levels = [](long long size) {
        int count = 1;
        for (; size > 1; size = (size + 1) / 2) {
            ++count;
        }
        return count;
    };
    const auto tilesAcross = [](long long size, int level, uint32_t tile) {
        for (int i = 0; i < level; ++i) {
            size = (size + 1) / 2;
        }
        return (uint64_t(size) + tile - 1) / tile;
    };
    const int xLevels = levels(width), yLevels = levels(height);
    uint64_t count = 0;
    switch (tiles.mode & 0x0f) {
    case 0:   // ONE_LEVEL
        return tilesAcross(width, 0, tiles.xSize) * tilesAcross(height, 0, tiles.ySize);
    case 1:   // MIPMAP_LEVELS
        for (int level = 0; level < std::max(xLevels, yLevels); ++level) {
            count += tilesAcross(width, std::min(level, xLevels - 1), tiles.xSize) *
                     tilesAcross(height, std::min(level, yLevels - 1), tiles.ySize);
        }
        return count;
    default:   // RIPMAP_LEVELS, or a mode OpenEXR refuses: the most it could be
        for (int x = 0; x < xLevels; ++x) {
            for (int y = 0; y < yLevels; ++y) {
                count += tilesAcross(width, x, tiles.xSize) * tilesAcross(height, y, tiles.ySize);
            }
        }
        return count;
    }
}

void ExrWalk::checkTiles(long long width, long long height) const {
    const ExrTiles& tiles = *tiles_;
    const std::string size = std::to_string(tiles.xSize) + " x " + std::to_string(tiles.ySize);
    if (tiles.xSize == 0 || tiles.ySize == 0 || tiles.xSize > INT_MAX || tiles.ySize > INT_MAX) {
        fail("its tile size " + size + " is not valid");
    }
    if (uint64_t(tiles.xSize) * tiles.ySize * bytesPerPixel(*channels_) > kMaxExrTileBytes ||
        uint64_t(width) * tiles.ySize > kMaxExrTileRowPixels) {
        fail("its tiles of " + size + " pixels are too large to read");
    }
    if (const uint64_t count = tileCount(tiles, width, height); count > kMaxExrTiles) {
        fail("its tiles of " + size + " pixels are too many to read (" + std::to_string(count) + ")");
    }
}

ExrLayout ExrWalk::check() {
    version();
    attributes();
    if (!channels_) {
        fail("the header has no channel list");
    }
    if (!dataWindow_) {
        fail("the header has no data window");
    }
    const auto [minX, minY, maxX, maxY] = *dataWindow_;
    const long long width = (long long)maxX - minX + 1, height = (long long)maxY - minY + 1;
    requireSize(width, height, name_);
    const ExrColour kind = colour();
    checkScanlines(width);
    if (tiles_) {
        checkTiles(width, height);
    }
    return {minX, minY, maxX, maxY, kind};
}

// The file's bytes as OpenEXR's input stream; reading past the end throws, as a file would.
class ByteStream final : public Imf::IStream {
public:
    // OpenEXR quotes the name in its messages.
    ByteStream(const std::vector<uint8_t>& bytes, const std::string& name)
        : Imf::IStream(name.c_str()), bytes_(bytes) {}

    bool read(char c[], int n) override {
        if (n < 0 || at_ > bytes_.size() || size_t(n) > bytes_.size() - at_) {
            throw Iex::InputExc("unexpected end of file");
        }
        std::memcpy(c, bytes_.data() + at_, size_t(n));
        at_ += size_t(n);
        return at_ < bytes_.size();
    }
    uint64_t tellg() override { return at_; }
    void seekg(uint64_t position) override { at_ = position; }

private:
    const std::vector<uint8_t>& bytes_;
    uint64_t at_ = 0;
};

// Decoded on the calling thread. OpenEXR's global pool starts with none (IlmThreadPool.cpp), and
// resizing it would change it for every other user of the library in the process.
constexpr int kExrThreads = 0;

HdrImage emptyImage(const ExrLayout& layout) {
    HdrImage image;
    image.width = layout.maxX - layout.minX + 1;
    image.height = layout.maxY - layout.minY + 1;
    image.rgb.assign(size_t(image.width) * size_t(image.height) * 3, 0.0f);
    return image;
}

// R, G, B (or Y) as FLOAT slices, whatever the file stores: RgbaInputFile would convert to half
// and clamp a sun above 65504.
HdrImage readChannels(Imf::IStream& stream, const ExrLayout& layout, const std::string& name) {
    Imf::InputFile file(stream, kExrThreads);
    const Imath::Box2i window = file.header().dataWindow();
    if (window.min.x != layout.minX || window.min.y != layout.minY || window.max.x != layout.maxX ||
        window.max.y != layout.maxY) {
        throw InputError(name + ": OpenEXR read a different data window from the header");
    }
    HdrImage image = emptyImage(layout);
    const size_t xStride = 3 * sizeof(float), yStride = xStride * size_t(image.width);
    Imf::FrameBuffer frame;
    if (layout.colour == ExrColour::Rgb) {
        for (int c = 0; c < 3; ++c) {
            frame.insert(std::string(1, "RGB"[c]),
                         Imf::Slice::Make(Imf::FLOAT, image.rgb.data() + c, window, xStride, yStride));
        }
    } else {
        frame.insert("Y", Imf::Slice::Make(Imf::FLOAT, image.rgb.data(), window, xStride, yStride));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    if (layout.colour == ExrColour::Luminance) {
        for (size_t i = 0; i < image.rgb.size(); i += 3) {
            image.rgb[i + 1] = image.rgb[i + 2] = image.rgb[i];
        }
    }
    return image;
}

// Y with RY and BY (RgbaOutputFile's WRITE_YC): only RgbaInputFile turns them back into RGB.
// Its half values lose nothing: luminance-chroma files are written in half.
HdrImage readLuminanceChroma(Imf::IStream& stream, const ExrLayout& layout) {
    Imf::RgbaInputFile file(stream, kExrThreads);
    HdrImage image = emptyImage(layout);
    std::vector<Imf::Rgba> pixels(size_t(image.width) * size_t(image.height));
    // Where pixel (0, 0) would be: integer arithmetic, as Slice::Make does, since the data window's
    // origin may lie anywhere.
    const uintptr_t first =
        uintptr_t(intptr_t(layout.minX)) + uintptr_t(intptr_t(layout.minY)) * uintptr_t(image.width);
    const uintptr_t origin = reinterpret_cast<uintptr_t>(pixels.data()) - first * sizeof(Imf::Rgba);
    file.setFrameBuffer(reinterpret_cast<Imf::Rgba*>(origin), 1, size_t(image.width));
    file.readPixels(layout.minY, layout.maxY);
    for (size_t i = 0; i < pixels.size(); ++i) {
        image.rgb[3 * i] = pixels[i].r;
        image.rgb[3 * i + 1] = pixels[i].g;
        image.rgb[3 * i + 2] = pixels[i].b;
    }
    return image;
}

}  // namespace

HdrImage decodeRadianceHdr(const std::vector<uint8_t>& bytes, const std::string& name) {
    if (bytes.size() > size_t(INT_MAX)) {   // stbi_loadf_from_memory takes an int
        throw InputError(name + ": a Radiance HDR file is limited to 2 GiB");
    }
    RgbeWalk walk(bytes, name);
    const RgbeLayout layout = walk.header();
    walk.pixels(layout);
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<float, void (*)(void*)> pixels(
        stbi_loadf_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 3), stbi_image_free);
    if (!pixels) {
        throw InputError(name + ": cannot be decoded: " + decoderReason(stbi_failure_reason()));
    }
    if (width != layout.width || height != layout.height) {
        throw InputError(name + ": stb_image read a different size from the header");
    }
    HdrImage image;
    image.width = width;
    image.height = height;
    image.rgb.assign(pixels.get(), pixels.get() + size_t(width) * size_t(height) * 3);
    return image;
}

HdrImage decodeOpenExr(const std::vector<uint8_t>& bytes, const std::string& name) {
    const ExrLayout layout = ExrWalk(bytes, name).check();
    try {
        ByteStream stream(bytes, name);
        return layout.colour == ExrColour::LuminanceChroma ? readLuminanceChroma(stream, layout)
                                                           : readChannels(stream, layout, name);
    } catch (const InputError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw InputError(name + ": out of memory while decoding");
    } catch (const std::exception& error) {   // Iex::BaseExc and the standard library's
        throw InputError(name + ": cannot be decoded: " + oneLine(error.what(), ' '));
    }
}

HdrImage decodeEnvironmentImage(const std::vector<uint8_t>& bytes, const std::string& name) {
    const std::string_view start(reinterpret_cast<const char*>(bytes.data()), std::min(bytes.size(), size_t(16)));
    if (start.starts_with("#?RADIANCE") || start.starts_with("#?RGBE")) {
        return decodeRadianceHdr(bytes, name);
    }
    if (start.starts_with("\x76\x2f\x31\x01")) {
        return decodeOpenExr(bytes, name);
    }
    throw InputError(name + (bytes.empty() ? ": the file is empty; " : ": not a Radiance HDR or OpenEXR image; ") +
                     std::string(kFormats));
}

HdrImage readEnvironmentImage(const std::filesystem::path& path) {
    const RegularFile file(path, 0, path.string());
    file.requireAtMost(kMaxEnvironmentFileBytes, "environment images");
    return decodeEnvironmentImage(file.readAll(), path.string());
}

std::vector<uint8_t> encodeRadianceHdr(const HdrImage& image) {
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(image.height) + " +X " +
                               std::to_string(image.width) + "\n";
    std::vector<uint8_t> bytes(header.begin(), header.end());
    bytes.reserve(bytes.size() + size_t(image.width) * size_t(image.height) * 4);
    for (size_t pixel = 0; pixel * 3 < image.rgb.size(); ++pixel) {
        float rgb[3];
        for (int c = 0; c < 3; ++c) {
            const float v = image.rgb[pixel * 3 + size_t(c)];
            rgb[c] = std::isfinite(v) && v > 0.0f ? v : 0.0f;
        }
        const float largest = std::max({rgb[0], rgb[1], rgb[2]});
        if (largest < 1e-32f) {
            bytes.insert(bytes.end(), {0, 0, 0, 0});
            continue;
        }
        // largest = m 2^e with m in [0.5, 1): each channel as a fraction of 2^e in 256ths.
        int exponent = 0;
        const float mantissa = std::frexp(largest, &exponent);
        const float scale = mantissa * 256.0f / largest;
        for (float v : rgb) {
            bytes.push_back(uint8_t(std::min(v * scale, 255.0f)));
        }
        bytes.push_back(uint8_t(std::clamp(exponent + 128, 0, 255)));
    }
    return bytes;
}

}  // namespace patina
