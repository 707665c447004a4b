// Radiance .hdr bytes through decodeRadianceHdr: the structure walk, then stb_image. Refusals are
// InputErrors; anything else, a crash or a hang (CVE-2021-42715 was one) is a bug. So is stb
// refusing a file the walk passed: the walk exists to hand stb only what it decodes as read.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "environment/equirect.h"
#include "environment/environment_files.h"
#include "files/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace patina;
    HdrImage image;
    try {
        image = decodeRadianceHdr(std::vector<uint8_t>(data, data + size), "fuzz.hdr");
    } catch (const InputError& error) {
        if (std::string_view(error.what()).starts_with("fuzz.hdr: cannot be decoded")) {
            std::abort();
        }
        return 0;
    }
    if (*environmentSizeProblem(image.width, image.height) ||
        image.rgb.size() != size_t(image.width) * size_t(image.height) * 3) {
        std::abort();
    }
    for (const float value : image.rgb) {   // 8-bit mantissas and an exponent: nothing else
        if (!std::isfinite(value) || value < 0.0f) {
            std::abort();
        }
    }
    return 0;
}
