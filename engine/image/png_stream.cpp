#include "image/png_stream.h"

#include <algorithm>
#include <chrono>
#include <future>
#include <stdexcept>
#include <string>
#include <thread>

#include <zlib.h>

#include "image/png_chunks.h"

namespace patina {

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
        // A full output buffer could leave a flush unfinished: deflateBound says it cannot be.
        if ((flush == Z_FINISH ? status != Z_STREAM_END : status != Z_OK) || zs.avail_in != 0 || zs.avail_out == 0) {
            throw std::runtime_error("zlib: compressing the PNG failed");
        }
    }
    band.deflated.resize(zs.total_out);
    return band;
}

// Rows [first, last) as bands of `rowsPerBand` rows, none ending the stream, one after another:
// what one thread deflates.
std::vector<Band> deflateBands(const LdrImage& image, int rowsPerBand, int first, int last) {
    std::vector<Band> bands;
    for (int row = first; row < last; row += rowsPerBand) {
        bands.push_back(deflateBand(image, row, std::min(last, row + rowsPerBand), false));
    }
    return bands;
}
}  // namespace

// PNG (spec 2nd ed.): 8-bit RGBA, every row with the Sub filter, one zlib stream at level 1.
// stb's writer tries five filters per row at level 8: on a 3072x2048 contact sheet it took
// 0.45 s for 2.2 MB where one stream like this took 0.10 s for 2.1 MB. The rows are deflated
// in bands, as pigz does: each band starts with an empty dictionary and ends on a byte
// boundary, so the bands joined are one deflate stream, and their Adler-32s combine (RFC
// 1950, 1951). It costs a few bytes per band. Bands are cut at fixed rows, so the file's
// bytes do not depend on the threads or on when rows were handed on.
struct PngStream::State {
    explicit State(const LdrImage& shown) : image(shown) {}

    const LdrImage& image;
    unsigned threads = 1;
    int rowsPerBand = 1;   // about 1 MiB raw: a thread's start is a small part of a band
    int handedOn = 0;
    std::vector<std::future<std::vector<Band>>> tasks;   // in row order
    bool finished = false;

    // Where the band with the last row starts: it waits for finish(), which ends the stream
    // with it.
    int lastBand() const { return (image.height - 1) / rowsPerBand * rowsPerBand; }

    // Bands of rows [handedOn, rows) on a thread, unless `threads` are still busy (the rows
    // then wait for a later call): never blocks the caller.
    void handOn(int rows) {
        rows = handedOn + (rows - handedOn) / rowsPerBand * rowsPerBand;
        const auto busy = std::count_if(tasks.begin(), tasks.end(), [](const auto& task) {
            return task.wait_for(std::chrono::seconds(0)) != std::future_status::ready;
        });
        if (rows <= handedOn || size_t(busy) >= threads) {
            return;
        }
        tasks.push_back(std::async(std::launch::async, deflateBands, std::cref(image), rowsPerBand, handedOn, rows));
        handedOn = rows;
    }
};

PngStream::PngStream(const LdrImage& image, unsigned threads) : state_(new State(image)) {
    const size_t stride = size_t(std::max(image.width, 0)) * 4;
    if (image.width <= 0 || image.height <= 0 || image.width > 0x7FFFFFFF / 4 ||
        image.rgba.size() != stride * size_t(image.height)) {
        throw std::runtime_error("cannot encode a " + std::to_string(image.width) + "x" +
                                 std::to_string(image.height) + " PNG");
    }
    state_->threads = threads == 0 ? std::clamp(std::thread::hardware_concurrency(), 1u, 8u) : threads;
    state_->rowsPerBand = int(std::max<size_t>(1, (size_t(1) << 20) / (stride + 1)));
}

PngStream::~PngStream() = default;   // std::async's futures wait in their destructors

void PngStream::rowsReady(int rows) {
    State& s = *state_;
    if (!s.finished) {
        s.handOn(std::min(rows, s.lastBand()));
    }
}

int PngStream::rowsHandedOn() const {
    return state_->handedOn;
}

std::vector<uint8_t> PngStream::finish() {
    State& s = *state_;
    if (s.finished) {
        throw std::logic_error("PngStream::finish called twice");
    }
    s.finished = true;
    // What is left, but the last band, over the threads; the last band on this one.
    int bandsLeft = (s.lastBand() - s.handedOn) / s.rowsPerBand;
    for (int workers = std::min<int>(bandsLeft, int(std::min(s.threads, 64u))); workers > 0; --workers) {
        const int take = (bandsLeft + workers - 1) / workers;
        const int end = s.handedOn + take * s.rowsPerBand;
        s.tasks.push_back(
            std::async(std::launch::async, deflateBands, std::cref(s.image), s.rowsPerBand, s.handedOn, end));
        s.handedOn = end;
        bandsLeft -= take;
    }
    const Band last = deflateBand(s.image, s.handedOn, s.image.height, true);

    std::vector<uint8_t> compressed = {0x78, 0x01};   // zlib: deflate, 32 KiB window, fastest
    uLong adler = adler32(0L, Z_NULL, 0);
    auto append = [&](const Band& band) {
        compressed.insert(compressed.end(), band.deflated.begin(), band.deflated.end());
        adler = adler32_combine(adler, band.adler, z_off_t(band.filteredBytes));
    };
    for (auto& task : s.tasks) {
        for (const Band& band : task.get()) {
            append(band);
        }
    }
    append(last);
    appendBigEndian32(compressed, uint32_t(adler));

    std::vector<uint8_t> png(kPngSignature.begin(), kPngSignature.end());
    std::vector<uint8_t> header;
    appendBigEndian32(header, uint32_t(s.image.width));
    appendBigEndian32(header, uint32_t(s.image.height));
    header.insert(header.end(), {8, 6, 0, 0, 0});   // 8 bits, RGBA, deflate, adaptive filters, no interlace
    appendPngChunk(png, "IHDR", header.data(), header.size());
    appendPngChunk(png, "IDAT", compressed.data(), compressed.size());
    appendPngChunk(png, "IEND", nullptr, 0);
    return png;
}

std::vector<uint8_t> encodePng(const LdrImage& image, unsigned threads) {
    return PngStream(image, threads).finish();
}

}  // namespace patina
