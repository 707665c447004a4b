// The environment-image readers (engine/environment/environment_files.h): Radiance .hdr through
// stb_image and OpenEXR through OpenEXR 3.1. Files are made here (RGBE by hand, EXR with OpenEXR's
// writers), read back and compared; damaged and hostile ones must end in an InputError that names
// the file, never a hang (CVE-2021-42715), a crash or a huge allocation.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfPartType.h>
#include <ImfRgbaFile.h>
#include <ImfTiledOutputFile.h>
#include <half.h>

#include "scratch_test.h"

#include "environment/environment_files.h"
#include "files/file_bytes.h"
#include "files/input_error.h"

namespace patina {
namespace {

using Bytes = std::vector<uint8_t>;

// A test image: every pixel and channel different, row 0 (the top) the brightest.
std::vector<float> testPixels(int width, int height, float scale = 1.0f) {
    std::vector<float> rgb(size_t(width) * size_t(height) * 3);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const float value = float(height - y) + 0.25f * float(x) + 0.125f * float(c);
                rgb[(size_t(y) * width + x) * 3 + c] = scale * value;
            }
        }
    }
    return rgb;
}

// The InputError's message, or "" when `decode` returned. Run on a thread of its own, waited for
// 10 s: a reader that loops forever fails the test instead of hanging the suite (the thread is
// left to spin until the process exits).
std::string errorOf(std::function<void()> decode) {
    auto done = std::make_shared<std::promise<std::string>>();
    std::future<std::string> result = done->get_future();
    std::thread([decode = std::move(decode), done] {
        try {
            decode();
            done->set_value("");
        } catch (const InputError& error) {
            done->set_value(error.what());
        } catch (const std::exception& error) {
            done->set_value(std::string("not an InputError: ") + error.what());
        }
    }).detach();
    if (result.wait_for(std::chrono::seconds(10)) != std::future_status::ready) {
        ADD_FAILURE() << "the reader did not return within 10 s";
        return "timed out";
    }
    return result.get();
}

std::string environmentError(const Bytes& bytes, const std::string& name) {
    return errorOf([bytes, name] { decodeEnvironmentImage(bytes, name); });
}

#define EXPECT_REFUSED(bytes, name, part)                                          \
    do {                                                                           \
        const std::string message = environmentError(bytes, name);                 \
        EXPECT_TRUE(message.starts_with(std::string(name))) << message;           \
        EXPECT_NE(message.find(part), std::string::npos) << message;              \
    } while (false)

// --- Radiance RGBE ---------------------------------------------------------------------------

// Ward's encoding: the largest channel's exponent shared, mantissas truncated to 8 bits.
std::array<uint8_t, 4> rgbe(const float* rgb) {
    const float largest = std::max({rgb[0], rgb[1], rgb[2]});
    if (largest < 1e-32f) {
        return {0, 0, 0, 0};
    }
    int exponent = 0;
    std::frexp(largest, &exponent);
    const float scale = std::ldexp(1.0f, 8 - exponent);   // the largest channel's mantissa in [128, 256)
    return {uint8_t(rgb[0] * scale), uint8_t(rgb[1] * scale), uint8_t(rgb[2] * scale), uint8_t(exponent + 128)};
}

std::string hdrHeader(const std::string& resolution, const std::string& format = "FORMAT=32-bit_rle_rgbe\n") {
    return "#?RADIANCE\n# written by test_environment_files\n" + format + "EXPOSURE=1.0\n\n" + resolution + "\n";
}

std::string resolution(int width, int height) {
    return "-Y " + std::to_string(height) + " +X " + std::to_string(width);
}

Bytes toBytes(const std::string& text) {
    return {text.begin(), text.end()};
}

Bytes flatHdr(int width, int height, const std::vector<float>& rgb) {
    Bytes bytes = toBytes(hdrHeader(resolution(width, height)));
    for (size_t i = 0; i < rgb.size(); i += 3) {
        const auto pixel = rgbe(&rgb[i]);
        bytes.insert(bytes.end(), pixel.begin(), pixel.end());
    }
    return bytes;
}

// One channel of a scanline as runs (3 or more equal bytes) and dumps.
void encodeChannel(const std::vector<uint8_t>& values, Bytes& out) {
    size_t x = 0;
    while (x < values.size()) {
        size_t run = 1;
        while (x + run < values.size() && run < 127 && values[x + run] == values[x]) {
            ++run;
        }
        if (run >= 3) {
            out.push_back(uint8_t(128 + run));
            out.push_back(values[x]);
            x += run;
            continue;
        }
        size_t dump = 1;
        while (x + dump < values.size() && dump < 128 &&
               !(x + dump + 2 < values.size() && values[x + dump] == values[x + dump + 1] &&
                 values[x + dump] == values[x + dump + 2])) {
            ++dump;
        }
        out.push_back(uint8_t(dump));
        out.insert(out.end(), values.begin() + long(x), values.begin() + long(x + dump));
        x += dump;
    }
}

Bytes rleScanline(int width, const float* rgb) {
    Bytes out = {2, 2, uint8_t(width >> 8), uint8_t(width & 0xff)};
    for (int channel = 0; channel < 4; ++channel) {
        std::vector<uint8_t> values(static_cast<size_t>(width));
        for (int x = 0; x < width; ++x) {
            values[size_t(x)] = rgbe(rgb + 3 * x)[size_t(channel)];
        }
        encodeChannel(values, out);
    }
    return out;
}

Bytes rleHdr(int width, int height, const std::vector<float>& rgb) {
    Bytes bytes = toBytes(hdrHeader(resolution(width, height)));
    for (int y = 0; y < height; ++y) {
        const Bytes row = rleScanline(width, &rgb[size_t(y) * width * 3]);
        bytes.insert(bytes.end(), row.begin(), row.end());
    }
    return bytes;
}

// RGBE keeps 8 bits of the largest channel: each channel within largest / 128.
void expectRgbeClose(const HdrImage& image, int width, int height, const std::vector<float>& rgb) {
    ASSERT_EQ(image.width, width);
    ASSERT_EQ(image.height, height);
    ASSERT_EQ(image.rgb.size(), rgb.size());
    for (size_t i = 0; i < rgb.size(); i += 3) {
        const float largest = std::max({rgb[i], rgb[i + 1], rgb[i + 2]});
        for (size_t c = 0; c < 3; ++c) {
            ASSERT_NEAR(image.rgb[i + c], rgb[i + c], largest / 128.0f) << "pixel " << i / 3 << " channel " << c;
        }
    }
}

TEST(EnvironmentFiles, RunLengthHdrRoundTripsTopRowFirst) {
    const int width = 40, height = 5;
    std::vector<float> rgb = testPixels(width, height);
    for (int x = 10; x < 30; ++x) {   // long runs of one colour in row 2
        float* pixel = &rgb[size_t(2 * width + x) * 3];
        pixel[0] = 7.0f, pixel[1] = 3.0f, pixel[2] = 0.5f;
    }
    const HdrImage image = decodeRadianceHdr(rleHdr(width, height, rgb), "sky.hdr");
    expectRgbeClose(image, width, height, rgb);
    EXPECT_GT(image.rgb[0], image.rgb[size_t(width) * (height - 1) * 3]);   // row 0 is the top
}

TEST(EnvironmentFiles, FlatHdrRoundTrips) {
    const std::vector<float> rgb = testPixels(5, 3, 100.0f);   // narrower than 8: always flat
    expectRgbeClose(decodeRadianceHdr(flatHdr(5, 3, rgb), "flat.hdr"), 5, 3, rgb);
    // A wide image may be flat too, when its first scanline does not start 2, 2.
    const std::vector<float> wide = testPixels(12, 4, 1000.0f);
    expectRgbeClose(decodeEnvironmentImage(flatHdr(12, 4, wide), "wide.hdr"), 12, 4, wide);
}

TEST(EnvironmentFiles, WrittenHdrReadsBack) {
    std::vector<float> rgb = testPixels(9, 4, 300.0f);
    rgb[3] = -1.0f, rgb[4] = NAN, rgb[5] = INFINITY;   // written as 0
    const HdrImage image = decodeRadianceHdr(encodeRadianceHdr({9, 4, rgb}), "written.hdr");
    rgb[3] = rgb[4] = rgb[5] = 0.0f;
    expectRgbeClose(image, 9, 4, rgb);
    EXPECT_EQ(image.rgb[4], 0.0f);
}

TEST(EnvironmentFiles, HdrKeepsBrightAndBlackPixels) {
    std::vector<float> rgb = testPixels(8, 2);
    rgb[0] = 1e6f, rgb[1] = 2e5f, rgb[2] = 5e4f;   // a sun
    rgb[3] = rgb[4] = rgb[5] = 0.0f;
    const HdrImage image = decodeRadianceHdr(rleHdr(8, 2, rgb), "sun.hdr");
    expectRgbeClose(image, 8, 2, rgb);
    EXPECT_EQ(image.rgb[3], 0.0f);
}

TEST(EnvironmentFiles, RgbeSignatureMayBeShort) {
    const std::vector<float> rgb = testPixels(3, 2);
    Bytes bytes = flatHdr(3, 2, rgb);
    const std::string rgbeSignature = "#?RGBE";
    bytes.erase(bytes.begin(), bytes.begin() + 10);
    bytes.insert(bytes.begin(), rgbeSignature.begin(), rgbeSignature.end());
    expectRgbeClose(decodeEnvironmentImage(bytes, "short.hdr"), 3, 2, rgb);
}

// CVE-2021-42715: stb_image 2.27 reads a count of 0 forever past the end of a run-length
// scanline. Every truncation of a run-length file must be refused, and return.
TEST(EnvironmentFiles, EveryTruncatedRunLengthHdrIsRefused) {
    const int width = 16, height = 3;
    const Bytes whole = rleHdr(width, height, testPixels(width, height));
    const size_t pixelsAt = hdrHeader(resolution(width, height)).size();
    for (size_t size = 0; size < whole.size(); ++size) {
        const Bytes cut(whole.begin(), whole.begin() + long(size));
        const std::string message = environmentError(cut, "cut.hdr");
        ASSERT_TRUE(message.starts_with("cut.hdr")) << size << ": " << message;
        if (size > pixelsAt) {
            ASSERT_NE(message.find("truncated: the file ends at row"), std::string::npos) << size << ": " << message;
        }
    }
    // The case the CVE describes: the file ends right after a scanline header.
    Bytes cut(whole.begin(), whole.begin() + long(pixelsAt) + 4);
    EXPECT_REFUSED(cut, "cve.hdr", "truncated: the file ends at row 0 of 3");
}

TEST(EnvironmentFiles, ZeroLengthRunIsRefused) {
    const int width = 8, height = 2;
    const std::vector<float> rgb = testPixels(width, height);
    Bytes bytes = toBytes(hdrHeader(resolution(width, height)));
    const Bytes row0 = rleScanline(width, rgb.data());
    bytes.insert(bytes.end(), row0.begin(), row0.end());
    Bytes row1 = rleScanline(width, &rgb[size_t(width) * 3]);
    row1.insert(row1.begin() + 4, 0);   // a count of 0 before the first channel's data
    bytes.insert(bytes.end(), row1.begin(), row1.end());
    EXPECT_REFUSED(bytes, "zero.hdr", "a run of length 0 at row 1");
}

TEST(EnvironmentFiles, OverflowingRunIsRefused) {
    Bytes bytes = toBytes(hdrHeader(resolution(8, 1)));
    const Bytes row = {2, 2, 0, 8, 128 + 9, 1};   // a run of 9 in a scanline of 8
    bytes.insert(bytes.end(), row.begin(), row.end());
    EXPECT_REFUSED(bytes, "run.hdr", "a run of 9 pixels overflows the scanline at row 0");
    Bytes dump = toBytes(hdrHeader(resolution(8, 1)));
    const Bytes dumpRow = {2, 2, 0, 8, 7, 1, 2, 3, 4, 5, 6, 7, 2, 9, 9};   // 7, then a dump of 2 past 8
    dump.insert(dump.end(), dumpRow.begin(), dumpRow.end());
    EXPECT_REFUSED(dump, "dump.hdr", "a run of 2 pixels overflows the scanline at row 0");
}

TEST(EnvironmentFiles, ScanlineOfAnotherWidthIsRefused) {
    Bytes bytes = toBytes(hdrHeader(resolution(8, 1)));
    const Bytes row = {2, 2, 0, 9, 128 + 8, 1, 128 + 8, 1, 128 + 8, 1, 128 + 8, 1};
    bytes.insert(bytes.end(), row.begin(), row.end());
    EXPECT_REFUSED(bytes, "width.hdr", "gives a width of 9, not 8");
}

TEST(EnvironmentFiles, FlatRowAfterRunLengthRowsIsRefused) {
    const int width = 8, height = 3;
    const std::vector<float> rgb = testPixels(width, height);
    Bytes bytes = toBytes(hdrHeader(resolution(width, height)));
    const Bytes row0 = rleScanline(width, rgb.data());
    bytes.insert(bytes.end(), row0.begin(), row0.end());
    bytes.insert(bytes.end(), size_t(width) * 4 * 2, 0x80);   // rows 1 and 2 flat
    EXPECT_REFUSED(bytes, "mixed.hdr", "row 1 is flat after run-length encoded rows");
}

TEST(EnvironmentFiles, ShortFlatHdrIsRefused) {
    Bytes bytes = flatHdr(4, 3, testPixels(4, 3));
    bytes.resize(bytes.size() - 1);
    EXPECT_REFUSED(bytes, "short.hdr", "truncated: the pixel data ends at row 2 of 3");
    const Bytes wide = flatHdr(10, 2, testPixels(10, 2, 500.0f));   // flat, wider than 8
    EXPECT_REFUSED(Bytes(wide.begin(), wide.end() - 4), "wide.hdr", "truncated: the pixel data ends at row 1 of 2");
}

TEST(EnvironmentFiles, UnsupportedHdrHeadersAreRefused) {
    const Bytes pixels(4 * 4 * 4, 0x40);
    const auto with = [&](const std::string& header) {
        Bytes bytes = toBytes(header);
        bytes.insert(bytes.end(), pixels.begin(), pixels.end());
        return bytes;
    };
    EXPECT_REFUSED(with(hdrHeader("-Y 4 +X 4", "")), "a.hdr", "no FORMAT=32-bit_rle_rgbe line");
    EXPECT_REFUSED(with(hdrHeader("-Y 4 +X 4", "FORMAT=32-bit_rle_xyze\n")), "b.hdr",
                   "\"32-bit_rle_xyze\" is not supported");
    EXPECT_REFUSED(with(hdrHeader("+Y 4 +X 4")), "c.hdr", "the resolution line \"+Y 4 +X 4\" is not supported");
    EXPECT_REFUSED(with(hdrHeader("-Y 4 -X 4")), "d.hdr", "\"-Y 4 -X 4\" is not supported");
    EXPECT_REFUSED(with(hdrHeader("+X 4 -Y 4")), "e.hdr", "is not supported");
    EXPECT_REFUSED(with(hdrHeader("-Y 4 +X 4x")), "f.hdr", "is not supported");
    EXPECT_REFUSED(with(hdrHeader("-Y +X 4")), "g.hdr", "is not supported");
    EXPECT_REFUSED(toBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4"), "h.hdr", "truncated: the header ends");
    EXPECT_REFUSED(toBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n"), "i.hdr", "truncated: the header ends");
    EXPECT_REFUSED(toBytes("#?RADIANCE"), "j.hdr", "its first line is not");
    EXPECT_REFUSED(toBytes("#?RADIANCEX\n"), "k.hdr", "its first line is not");
    EXPECT_REFUSED(with(hdrHeader("-Y 0 +X 4")), "l.hdr", "l.hdr has no pixels");
}

TEST(EnvironmentFiles, OversizedHdrIsRefusedFromItsHeader) {
    // No pixel data at all: the size is refused before anything is walked or allocated.
    EXPECT_REFUSED(toBytes(hdrHeader("-Y 20000 +X 20000")), "huge.hdr",
                   "huge.hdr is larger than 16384 pixels a side (20000 x 20000)");
    EXPECT_REFUSED(toBytes(hdrHeader("-Y 16000 +X 16000")), "big.hdr", "big.hdr would take more than 256 MiB decoded");
    EXPECT_REFUSED(toBytes(hdrHeader("-Y 99999999999999999999 +X 1")), "digits.hdr", "is larger than 16384 pixels");
}

TEST(EnvironmentFiles, GarbageAndEmptyFilesAreRefused) {
    EXPECT_REFUSED(Bytes{}, "empty.exr", "empty.exr: the file is empty; environment images are read from Radiance HDR");
    EXPECT_REFUSED(toBytes("GIF89a garbage"), "garbage.hdr", "not a Radiance HDR or OpenEXR image");
    EXPECT_REFUSED(toBytes("GIF89a garbage"), "garbage.hdr", "(.hdr) and OpenEXR (.exr)");
    Bytes noise(4096);
    for (size_t i = 0; i < noise.size(); ++i) {
        noise[i] = uint8_t(i * 2654435761u >> 13);
    }
    EXPECT_REFUSED(noise, "noise.bin", "noise.bin: not a Radiance HDR or OpenEXR image");
    // Garbage after each signature.
    Bytes afterHdr = toBytes("#?RADIANCE\n");
    afterHdr.insert(afterHdr.end(), noise.begin(), noise.end());
    EXPECT_REFUSED(afterHdr, "noise.hdr", "noise.hdr: ");
    Bytes afterExr = {0x76, 0x2f, 0x31, 0x01};
    afterExr.insert(afterExr.end(), noise.begin(), noise.end());
    EXPECT_REFUSED(afterExr, "noise.exr", "noise.exr: ");
}

// --- OpenEXR -----------------------------------------------------------------------------------

class MemoryOStream final : public Imf::OStream {
public:
    MemoryOStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        if (at_ + size_t(n) > bytes.size()) {
            bytes.resize(at_ + size_t(n));
        }
        std::memcpy(bytes.data() + at_, c, size_t(n));
        at_ += size_t(n);
    }
    uint64_t tellp() override { return at_; }
    void seekp(uint64_t position) override { at_ = position; }

    Bytes bytes;

private:
    uint64_t at_ = 0;
};

struct ExrSpec {
    int width = 6;
    int height = 4;
    Imath::V2i origin{0, 0};
    Imf::PixelType type = Imf::FLOAT;
    std::string channels = "RGB";   // one letter a channel: R, G, B, A or Y
    Imf::Compression compression = Imf::ZIP_COMPRESSION;
    int tileSize = 0;               // 0: scanlines
    Imf::LevelMode levels = Imf::ONE_LEVEL;
};

Imath::Box2i dataWindowOf(const ExrSpec& spec) {
    return {spec.origin, spec.origin + Imath::V2i(spec.width - 1, spec.height - 1)};
}

// One channel's values, as the file stores them: OpenEXR's writers do not convert.
struct Plane {
    std::vector<float> floats;
    std::vector<half> halves;
};

// One plane a channel, from `rgb` (Y from red, A 0.5).
std::vector<Plane> planes(const ExrSpec& spec, const std::vector<float>& rgb) {
    std::vector<Plane> out;
    for (const char channel : spec.channels) {
        Plane plane;
        plane.floats.assign(size_t(spec.width) * size_t(spec.height), 0.5f);
        const size_t c = channel == 'G' ? 1 : channel == 'B' ? 2 : 0;
        for (size_t i = 0; channel != 'A' && i < plane.floats.size(); ++i) {
            plane.floats[i] = rgb[3 * i + c];
        }
        plane.halves.assign(plane.floats.begin(), plane.floats.end());
        out.push_back(std::move(plane));
    }
    return out;
}

Imf::FrameBuffer frameBuffer(const ExrSpec& spec, const Imath::Box2i& window, std::vector<Plane>& data) {
    const size_t width = size_t(window.max.x - window.min.x + 1);
    Imf::FrameBuffer frame;
    for (size_t i = 0; i < spec.channels.size(); ++i) {
        const std::string name(1, spec.channels[i]);
        if (spec.type == Imf::HALF) {
            frame.insert(name, Imf::Slice::Make(Imf::HALF, data[i].halves.data(), window, sizeof(half),
                                                sizeof(half) * width));
        } else {
            frame.insert(name, Imf::Slice::Make(Imf::FLOAT, data[i].floats.data(), window, sizeof(float),
                                                sizeof(float) * width));
        }
    }
    return frame;
}

void writeTiledLevel(const ExrSpec& spec, const std::vector<float>& rgb, Imf::TiledOutputFile& file, int lx, int ly) {
    // Smaller levels hold the top-left corner of the image: any values will do.
    const Imath::Box2i window = file.dataWindowForLevel(lx, ly);
    const int w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
    std::vector<float> levelRgb(size_t(w) * size_t(h) * 3);
    for (int y = 0; y < h; ++y) {
        std::copy_n(&rgb[size_t(y) * spec.width * 3], size_t(w) * 3, &levelRgb[size_t(y) * w * 3]);
    }
    ExrSpec levelSpec = spec;
    levelSpec.width = w, levelSpec.height = h;
    auto data = planes(levelSpec, levelRgb);
    file.setFrameBuffer(frameBuffer(levelSpec, window, data));
    file.writeTiles(0, file.numXTiles(lx) - 1, 0, file.numYTiles(ly) - 1, lx, ly);
}

void writeTiled(const ExrSpec& spec, const Imf::Header& header, const std::vector<float>& rgb, MemoryOStream& stream) {
    Imf::TiledOutputFile file(stream, header);
    for (int lx = 0; lx < file.numXLevels(); ++lx) {
        for (int ly = 0; ly < file.numYLevels(); ++ly) {
            if (spec.levels == Imf::RIPMAP_LEVELS || lx == ly) {
                writeTiledLevel(spec, rgb, file, lx, ly);
            }
        }
    }
}

Bytes writeExr(const ExrSpec& spec, const std::vector<float>& rgb) {
    const Imath::Box2i window = dataWindowOf(spec);
    Imf::Header header(window, window, 1.0f, Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y, spec.compression);
    for (const char channel : spec.channels) {
        header.channels().insert(std::string(1, channel), Imf::Channel(spec.type));
    }
    MemoryOStream stream;
    if (spec.tileSize > 0) {
        header.setTileDescription(Imf::TileDescription(spec.tileSize, spec.tileSize, spec.levels));
        writeTiled(spec, header, rgb, stream);
    } else {
        Imf::OutputFile file(stream, header);
        auto data = planes(spec, rgb);
        file.setFrameBuffer(frameBuffer(spec, window, data));
        file.writePixels(spec.height);
    }
    return stream.bytes;
}

void expectPixels(const HdrImage& image, const ExrSpec& spec, const std::vector<float>& rgb, float relative) {
    ASSERT_EQ(image.width, spec.width);
    ASSERT_EQ(image.height, spec.height);
    ASSERT_EQ(image.rgb.size(), rgb.size());
    for (size_t i = 0; i < rgb.size(); ++i) {
        if (relative == 0.0f) {
            ASSERT_EQ(image.rgb[i], rgb[i]) << "value " << i;
        } else {
            ASSERT_NEAR(image.rgb[i], rgb[i], std::abs(rgb[i]) * relative) << "value " << i;
        }
    }
}

constexpr float kHalfPrecision = 1.0f / 1024.0f;   // 11 significant bits, rounded

TEST(EnvironmentFiles, FloatExrIsExact) {
    for (const std::string channels : {"RGB", "RGBA", "BGRA"}) {
        ExrSpec spec;
        spec.channels = channels;
        const std::vector<float> rgb = testPixels(spec.width, spec.height, 1.2345f);
        expectPixels(decodeOpenExr(writeExr(spec, rgb), "float.exr"), spec, rgb, 0.0f);
    }
}

TEST(EnvironmentFiles, HalfExrIsWithinHalfPrecision) {
    for (const std::string channels : {"RGB", "RGBA"}) {
        ExrSpec spec;
        spec.type = Imf::HALF;
        spec.channels = channels;
        const std::vector<float> rgb = testPixels(spec.width, spec.height, 3.3f);
        expectPixels(decodeEnvironmentImage(writeExr(spec, rgb), "half.exr"), spec, rgb, kHalfPrecision);
    }
}

TEST(EnvironmentFiles, FloatExrKeepsASunBrighterThanHalf) {
    ExrSpec spec;
    std::vector<float> rgb = testPixels(spec.width, spec.height);
    rgb[3] = 1e6f, rgb[4] = 3e5f, rgb[5] = 7e4f;
    const HdrImage image = decodeOpenExr(writeExr(spec, rgb), "sun.exr");
    EXPECT_EQ(image.rgb[3], 1e6f);   // half would clamp it to 65504
    expectPixels(image, spec, rgb, 0.0f);
}

TEST(EnvironmentFiles, ExrRowsComeTopFirstFromAnyDataWindow) {
    ExrSpec spec;
    spec.origin = {-3, 7};
    const std::vector<float> rgb = testPixels(spec.width, spec.height);
    const HdrImage image = decodeOpenExr(writeExr(spec, rgb), "origin.exr");
    expectPixels(image, spec, rgb, 0.0f);
    EXPECT_GT(image.rgb[0], image.rgb[size_t(spec.width) * (spec.height - 1) * 3]);
}

TEST(EnvironmentFiles, TiledExrIsRead) {
    for (const Imf::LevelMode levels : {Imf::ONE_LEVEL, Imf::MIPMAP_LEVELS, Imf::RIPMAP_LEVELS}) {
        for (const Imf::PixelType type : {Imf::FLOAT, Imf::HALF}) {
            ExrSpec spec;
            spec.width = 37, spec.height = 19, spec.origin = {5, -2};
            spec.tileSize = 8, spec.levels = levels, spec.type = type, spec.channels = "RGBA";
            const std::vector<float> rgb = testPixels(spec.width, spec.height, 0.7f);
            expectPixels(decodeOpenExr(writeExr(spec, rgb), "tiled.exr"), spec, rgb,
                         type == Imf::HALF ? kHalfPrecision : 0.0f);
        }
    }
}

TEST(EnvironmentFiles, LosslessCompressionsAreExact) {
    for (const Imf::Compression compression : {Imf::NO_COMPRESSION, Imf::RLE_COMPRESSION, Imf::ZIPS_COMPRESSION,
                                               Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION}) {
        ExrSpec spec;
        spec.width = 33, spec.height = 40, spec.compression = compression;
        const std::vector<float> rgb = testPixels(spec.width, spec.height, 0.01f);
        expectPixels(decodeOpenExr(writeExr(spec, rgb), "compressed.exr"), spec, rgb, 0.0f);
    }
}

TEST(EnvironmentFiles, LuminanceExrIsGrey) {
    ExrSpec spec;
    spec.channels = "Y";
    const std::vector<float> rgb = testPixels(spec.width, spec.height);
    const HdrImage image = decodeOpenExr(writeExr(spec, rgb), "grey.exr");
    ASSERT_EQ(image.rgb.size(), rgb.size());
    for (size_t i = 0; i < rgb.size(); i += 3) {
        EXPECT_EQ(image.rgb[i], rgb[i]);
        EXPECT_EQ(image.rgb[i + 1], rgb[i]);
        EXPECT_EQ(image.rgb[i + 2], rgb[i]);
    }
}

TEST(EnvironmentFiles, LuminanceChromaExrIsColour) {
    const int width = 8, height = 6;
    std::vector<Imf::Rgba> pixels(size_t(width) * height, Imf::Rgba(0.8f, 0.4f, 0.2f, 1.0f));
    const Imath::Box2i window({0, 0}, {width - 1, height - 1});
    MemoryOStream stream;
    {
        Imf::RgbaOutputFile file(stream, Imf::Header(window, window), Imf::WRITE_YC);
        file.setFrameBuffer(pixels.data(), 1, width);
        file.writePixels(height);
    }
    const HdrImage image = decodeOpenExr(stream.bytes, "yc.exr");
    ASSERT_EQ(image.width, width);
    ASSERT_EQ(image.height, height);
    // Luminance-chroma is lossy: the colour, not the values, comes back.
    EXPECT_NEAR(image.rgb[0], 0.8f, 0.05f);
    EXPECT_NEAR(image.rgb[1], 0.4f, 0.05f);
    EXPECT_NEAR(image.rgb[2], 0.2f, 0.05f);
}

TEST(EnvironmentFiles, ExrWithoutColourChannelsIsRefused) {
    ExrSpec spec;
    spec.channels = "RGA";
    EXPECT_REFUSED(writeExr(spec, testPixels(spec.width, spec.height)), "nocolour.exr",
                   "nocolour.exr: has no R, G and B channels, nor a Y channel: its channels are A, G, R");
}

TEST(EnvironmentFiles, TruncatedExrIsRefused) {
    ExrSpec spec;
    spec.width = 20, spec.height = 20;
    const Bytes whole = writeExr(spec, testPixels(spec.width, spec.height));
    for (size_t size = 0; size < whole.size(); size += size < 400 ? 1 : 7) {
        const std::string message = environmentError(Bytes(whole.begin(), whole.begin() + long(size)), "cut.exr");
        ASSERT_TRUE(message.starts_with("cut.exr")) << size << ": " << message;
    }
    spec.tileSize = 8;
    const Bytes tiled = writeExr(spec, testPixels(spec.width, spec.height));
    EXPECT_REFUSED(Bytes(tiled.begin(), tiled.end() - 10), "cut.exr", "cut.exr: cannot be decoded");
}

TEST(EnvironmentFiles, MultiPartExrIsRefused) {
    const Imath::Box2i window({0, 0}, {3, 3});
    Imf::Header headers[2] = {Imf::Header(window, window), Imf::Header(window, window)};
    for (int i = 0; i < 2; ++i) {
        headers[i].setName("part" + std::to_string(i));
        headers[i].setType(Imf::SCANLINEIMAGE);
        headers[i].channels().insert("R", Imf::Channel(Imf::HALF));
    }
    MemoryOStream stream;
    { Imf::MultiPartOutputFile file(stream, headers, 2); }
    EXPECT_REFUSED(stream.bytes, "parts.exr", "a multi-part OpenEXR file is not supported");
}

// --- Hostile EXR headers, written by hand ("The OpenEXR File Layout") ------------------------

std::string le32(int32_t value) {
    return {char(value), char(value >> 8), char(value >> 16), char(value >> 24)};
}

std::string attribute(const std::string& name, const std::string& type, const std::string& value) {
    return name + '\0' + type + '\0' + le32(int32_t(value.size())) + value;
}

std::string box(int32_t minX, int32_t minY, int32_t maxX, int32_t maxY) {
    return le32(minX) + le32(minY) + le32(maxX) + le32(maxY);
}

std::string channelList(const std::string& letters, int32_t type = 2) {
    std::string list;
    for (const char letter : letters) {
        list += std::string(1, letter) + '\0' + le32(type) + std::string(4, '\0') + le32(1) + le32(1);
    }
    return list + '\0';
}

Bytes craftedExr(const std::string& attributes, int32_t flags = 0) {
    const std::string bytes = "\x76\x2f\x31\x01" + le32(2 | flags) + attributes + '\0' + std::string(64, '\0');
    return toBytes(bytes);
}

std::string standardAttributes(const std::string& dataWindow, const std::string& channels = channelList("BGR")) {
    return attribute("channels", "chlist", channels) + attribute("compression", "compression", std::string(1, '\0')) +
           attribute("dataWindow", "box2i", dataWindow) + attribute("displayWindow", "box2i", dataWindow) +
           attribute("lineOrder", "lineOrder", std::string(1, '\0')) +
           attribute("pixelAspectRatio", "float", le32(0x3f800000)) +
           attribute("screenWindowCenter", "v2f", std::string(8, '\0')) +
           attribute("screenWindowWidth", "float", le32(0x3f800000));
}

TEST(EnvironmentFiles, OversizedExrIsRefusedFromItsHeader) {
    EXPECT_REFUSED(craftedExr(standardAttributes(box(0, 0, 19999, 19999))), "huge.exr",
                   "huge.exr is larger than 16384 pixels a side (20000 x 20000)");
    EXPECT_REFUSED(craftedExr(standardAttributes(box(INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX))), "wide.exr",
                   "wide.exr is larger than 16384 pixels a side (4294967296 x 4294967296)");
    EXPECT_REFUSED(craftedExr(standardAttributes(box(0, 0, 15999, 15999))), "big.exr",
                   "big.exr would take more than 256 MiB decoded");
    EXPECT_REFUSED(craftedExr(standardAttributes(box(5, 0, 4, 9))), "none.exr", "none.exr has no pixels");
}

TEST(EnvironmentFiles, ExrWhoseBuffersWouldBeHugeIsRefused) {
    std::string manyChannels;
    for (int i = 0; i < 40; ++i) {
        manyChannels += "extra" + std::to_string(i) + '\0' + le32(2) + std::string(4, '\0') + le32(1) + le32(1);
    }
    manyChannels = channelList("BGR").substr(0, channelList("BGR").size() - 1) + manyChannels + '\0';
    EXPECT_REFUSED(craftedExr(standardAttributes(box(0, 0, 16383, 1), manyChannels)), "channels.exr",
                   "its 43 channels are too many to read at 16384 pixels wide");
    const auto tiled = [](uint32_t x, uint32_t y, uint8_t mode, int32_t maxX, int32_t maxY) {
        const std::string tiles = le32(int32_t(x)) + le32(int32_t(y)) + std::string(1, char(mode));
        return craftedExr(standardAttributes(box(0, 0, maxX, maxY)) + attribute("tiles", "tiledesc", tiles), 0x200);
    };
    EXPECT_REFUSED(tiled(1, 1, 0, 4095, 2047), "tiny.exr", "its tiles of 1 x 1 pixels are too many to read (8388608)");
    EXPECT_REFUSED(tiled(2, 2, 2, 4095, 2047), "rip.exr", "its tiles of 2 x 2 pixels are too many to read");
    EXPECT_REFUSED(tiled(1, 100000, 0, 999, 9), "tall.exr", "its tiles of 1 x 100000 pixels are too large to read");
    EXPECT_REFUSED(tiled(0, 16, 0, 99, 9), "zero.exr", "its tile size 0 x 16 is not valid");
}

TEST(EnvironmentFiles, MalformedExrHeadersAreRefused) {
    const std::string window = box(0, 0, 3, 3);
    EXPECT_REFUSED(craftedExr(attribute("dataWindow", "box2i", window)), "a.exr",
                   "a.exr: the header has no channel list");
    EXPECT_REFUSED(craftedExr(attribute("channels", "chlist", channelList("RGB"))), "b.exr", "has no data window");
    // A box2i of 0 bytes: OpenEXR would read 16 anyway, and the walk would lose its place.
    EXPECT_REFUSED(craftedExr(attribute("dataWindow", "box2i", "") + standardAttributes(window)), "c.exr",
                   "attribute \"dataWindow\" of type box2i takes 0 bytes");
    EXPECT_REFUSED(craftedExr(standardAttributes(window) + attribute("dataWindow", "box2i", window)), "d.exr",
                   "attribute \"dataWindow\" appears twice");
    EXPECT_REFUSED(craftedExr(attribute("dataWindow", "v2i", std::string(8, '\0'))), "e.exr",
                   "attribute \"dataWindow\" has type \"v2i\", not box2i");
    std::string longSize = standardAttributes(window) + attribute("comment", "string", "hello");
    longSize.replace(longSize.size() - 9, 4, le32(1000000));
    EXPECT_REFUSED(craftedExr(longSize), "f.exr", "truncated: attribute \"comment\" says it takes 1000000 bytes");
    EXPECT_REFUSED(craftedExr(standardAttributes(window), 0x800), "g.exr", "deep OpenEXR data is not supported");
    EXPECT_REFUSED(craftedExr(standardAttributes(window), 0x4000), "h.exr", "flags this reader does not know");
    Bytes version = craftedExr(standardAttributes(window));
    version[4] = 3;
    EXPECT_REFUSED(version, "i.exr", "OpenEXR file version 3 is not supported");
    EXPECT_REFUSED(craftedExr(std::string(300, 'n')), "j.exr", "an attribute name is longer than 255 characters");
    EXPECT_REFUSED(toBytes("\x76\x2f\x31\x01\x02"), "k.exr", "truncated: the file ends in the version field");
    // The header is sound but there are no pixels behind it: OpenEXR's own error, as an InputError.
    EXPECT_REFUSED(craftedExr(standardAttributes(window)), "l.exr", "l.exr: cannot be decoded");
}

// --- Files on disk -----------------------------------------------------------------------------

class EnvironmentFilesOnDisk : public test::ScratchTest {};

TEST_F(EnvironmentFilesOnDisk, ReadsBothFormatsByContentNotByName) {
    const std::vector<float> rgb = testPixels(9, 3);
    writeFileAtomic(path("really_an_exr.hdr"), writeExr(ExrSpec{.width = 9, .height = 3}, rgb));
    writeFileAtomic(path("really_an_hdr.exr"), rleHdr(9, 3, rgb));
    expectPixels(readEnvironmentImage(path("really_an_exr.hdr")), ExrSpec{.width = 9, .height = 3}, rgb, 0.0f);
    expectRgbeClose(readEnvironmentImage(path("really_an_hdr.exr")), 9, 3, rgb);
}

TEST_F(EnvironmentFilesOnDisk, ErrorsNameThePath) {
    const auto errorReading = [](const std::filesystem::path& file) {
        return errorOf([file] { readEnvironmentImage(file); });
    };
    EXPECT_TRUE(errorReading(dir_).starts_with(dir_.string() + ": a folder, not a file")) << errorReading(dir_);
    EXPECT_TRUE(errorReading(path("missing.exr")).starts_with(path("missing.exr").string() + ": cannot open"));
    write("text.hdr", "hello\n");
    EXPECT_TRUE(errorReading(path("text.hdr")).starts_with(path("text.hdr").string() + ": not a Radiance HDR"));
}

// Blender's studio lights (Debian's blender-data, CC0 HDRIs by Greg Zaal): a real file from a
// real writer.
TEST(EnvironmentFiles, ReadsBlendersStudioHdri) {
    const std::filesystem::path file = "/usr/share/blender/datafiles/studiolights/world/studio.exr";
    if (!std::filesystem::exists(file)) {
        GTEST_SKIP() << file << " is not installed (blender-data)";
    }
    const HdrImage image = readEnvironmentImage(file);
    EXPECT_GE(image.height, 64);
    EXPECT_EQ(image.width, 2 * image.height);
    ASSERT_EQ(image.rgb.size(), size_t(image.width) * size_t(image.height) * 3);
    size_t bright = 0;
    for (const float value : image.rgb) {
        ASSERT_TRUE(std::isfinite(value));
        bright += value > 1.0f;
    }
    EXPECT_GT(bright, 0u);
}

}  // namespace
}  // namespace patina
