// PNG bytes through the reader of a screenshot's scene (readPngText, then the scene JSON).
// Refusals are InputErrors; anything else is a bug. A scene read must be written back (as the
// editor's screenshot does) and read the same.
//
// The input's chunk CRCs are made right first: a mutation would almost never keep them right,
// and the fuzzer would stop at the CRC check. (The unit tests cover wrong CRCs.)
#include <cstdint>
#include <cstdlib>

#include "png_crc.h"
#include "picture/png_text.h"
#include "io/scene_file.h"

namespace {
// Every chunk that fits: length, type, data, CRC, big-endian, after the 8-byte signature.
void fixCrcs(std::vector<uint8_t>& png) {
    for (size_t at = 8; png.size() - at >= 12;) {
        const size_t length = size_t(png[at]) << 24 | size_t(png[at + 1]) << 16 | size_t(png[at + 2]) << 8 | png[at + 3];
        if (length > png.size() - at - 12) {
            return;
        }
        const uint32_t crc = patina::test::pngCrc(&png[at + 4], length + 4);
        for (int i = 0; i < 4; ++i) {
            png[at + 8 + length + size_t(i)] = uint8_t(crc >> (24 - 8 * i));
        }
        at += 12 + length;
    }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace patina;
    std::vector<uint8_t> bytes(data, data + size);
    if (size >= 8) {
        fixCrcs(bytes);
    }
    std::vector<std::string> warnings;
    std::optional<Scene> scene;
    try {
        scene = sceneFromPngBytes(bytes, "fuzz.png", warnings);
    } catch (const InputError&) {
        return 0;
    }
    if (scene) {
        const LdrImage pixel{1, 1, {0, 0, 0, 255}};
        const auto png = encodePngWithText(pixel, {{kSceneTextKeyword, sceneToJson(*scene).dump()}});
        if (sceneFromPngBytes(png, "again.png", warnings) != scene) {
            std::abort();
        }
    }
    return 0;
}
