#pragma once
// PNG encoding (encodePng in image.h is this at once), for an image still being drawn.
#include <memory>
#include <vector>

#include "image/image.h"

namespace patina {

// A PNG of an image whose rows become final from the top down: rowsReady(n) says rows
// [0, n) will not change and deflates those not handed on yet on a thread of their own,
// while the caller draws the rest; finish() deflates what is left over up to `threads`
// threads (0: one per core, at most 8) and returns the file. `image` must outlive the stream.
class PngStream {
public:
    // Throws std::runtime_error for an image that cannot be a PNG (no pixels, sizes that
    // disagree, rows too wide).
    explicit PngStream(const LdrImage& image, unsigned threads = 0);
    ~PngStream();   // waits for the bands in flight
    PngStream(const PngStream&) = delete;
    PngStream& operator=(const PngStream&) = delete;

    void rowsReady(int rows);
    // Rows [0, rowsHandedOn()) are deflated or being deflated.
    int rowsHandedOn() const;
    // Once; throws std::runtime_error if zlib fails.
    std::vector<uint8_t> finish();

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace patina
