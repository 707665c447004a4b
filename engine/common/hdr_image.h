#pragma once
#include <vector>

namespace patina {

// Linear RGB, float per channel, rows top to bottom.
struct HdrImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;   // width * height * 3

    bool operator==(const HdrImage&) const = default;
};

}  // namespace patina
