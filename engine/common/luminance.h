#pragma once
// Luminance of linear RGB with the Rec. 709 primaries: Y = 0.2126 R + 0.7152 G + 0.0722 B
// (ITU-R BT.709-6, part 1, item 3.2; applied to linear values, as sRGB's IEC 61966-2-1 does).

namespace patina {

// `rgb`: anything indexed 0, 1, 2 as R, G, B: a glm::vec3, a float[3], a pointer to a pixel's
// three floats.
template <typename Rgb>
float luminance(const Rgb& rgb) {
    return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
}

}  // namespace patina
