#pragma once
#include <cstdint>
#include <vector>

namespace patina {

// Display-referred sRGB bytes, RGBA, rows top to bottom (HdrImage's counterpart; its files are
// image/image.h's).
struct LdrImage {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;   // width * height * 4
};

}  // namespace patina
