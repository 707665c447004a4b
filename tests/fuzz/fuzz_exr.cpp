// OpenEXR bytes through decodeOpenExr: the header walk, then OpenEXR 3.1 (not instrumented: the
// fuzzer sees only the walk's coverage, but a crash, a leak, a hang or a huge allocation inside
// the library still ends the run). Refusals are InputErrors; anything else is a bug. What decodes
// must be the size its header said, within the environment limits.
#include <cstdint>
#include <cstdlib>

#include "environment/equirect.h"
#include "environment/environment_files.h"
#include "files/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace patina;
    HdrImage image;
    try {
        image = decodeOpenExr(std::vector<uint8_t>(data, data + size), "fuzz.exr");
    } catch (const InputError&) {
        return 0;
    }
    if (*environmentSizeProblem(image.width, image.height) ||
        image.rgb.size() != size_t(image.width) * size_t(image.height) * 3) {
        std::abort();
    }
    return 0;
}
