#include "image/display_image.h"

#include <algorithm>
#include <cmath>

#include "shading/shading.h"

namespace patina {

LdrImage displayImage(const HdrImage& linear, const DisplaySettings& display) {
    LdrImage image{linear.width, linear.height, std::vector<uint8_t>(size_t(linear.width) * size_t(linear.height) * 4, 255)};
    const int tonemap = tonemapShaderIndex(display.tonemap);
    for (size_t pixel = 0; pixel * 3 < linear.rgb.size(); ++pixel) {
        const float* rgb = &linear.rgb[pixel * 3];
        const glm::vec3 shown = shader::displayTransform(glm::vec3(rgb[0], rgb[1], rgb[2]), display.exposure, tonemap);
        for (int c = 0; c < 3; ++c) {
            image.rgba[pixel * 4 + size_t(c)] = uint8_t(std::lround(std::clamp(shown[c], 0.0f, 1.0f) * 255.0f));
        }
    }
    return image;
}

}  // namespace patina
