#include "picture/display_image.h"

#include <algorithm>
#include <cmath>

#include "environment/equirect.h"
#include "shading/shading.h"

namespace patina {

LdrImage displayImage(const HdrImage& linear, const DisplaySettings& display, std::span<const uint8_t> backdrop) {
    LdrImage image{linear.width, linear.height, std::vector<uint8_t>(size_t(linear.width) * size_t(linear.height) * 4, 255)};
    const int tonemap = tonemapShaderIndex(display.tonemap);
    for (size_t pixel = 0; pixel * 3 < linear.rgb.size(); ++pixel) {
        const float* rgb = &linear.rgb[pixel * 3];
        const glm::vec3 value(rgb[0], rgb[1], rgb[2]);
        const glm::vec3 shown = pixel < backdrop.size() && backdrop[pixel]
                                    ? shader::srgbColor(value)
                                    : shader::displayTransform(value, display.exposure, tonemap);
        for (int c = 0; c < 3; ++c) {
            image.rgba[pixel * 4 + size_t(c)] = uint8_t(std::lround(std::clamp(shown[c], 0.0f, 1.0f) * 255.0f));
        }
    }
    return image;
}

LdrImage channelDisplayImage(const HdrImage& channel, int channelId, bool srgb) {
    LdrImage image{channel.width, channel.height,
                   std::vector<uint8_t>(size_t(channel.width) * size_t(channel.height) * 4, 255)};
    for (size_t pixel = 0; pixel * 3 < channel.rgb.size(); ++pixel) {
        const float* rgb = &channel.rgb[pixel * 3];
        const glm::vec3 shown = shader::shownChannel(channelId, glm::vec3(rgb[0], rgb[1], rgb[2]), srgb);
        for (int c = 0; c < 3; ++c) {
            image.rgba[pixel * 4 + size_t(c)] = uint8_t(std::lround(shown[c] * 255.0f));
        }
    }
    return image;
}

LdrImage equirectPreview(const HdrImage& equirect, int width, int height) {
    HdrImage small{width, height, std::vector<float>(size_t(width) * size_t(height) * 3, 0.0f)};
    constexpr int kReads = 3;   // per side of a pixel
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            glm::vec3 sum(0.0f);
            for (int j = 0; j < kReads; ++j) {
                for (int i = 0; i < kReads; ++i) {
                    const glm::vec2 uv((float(x) + (float(i) + 0.5f) / kReads) / float(width),
                                       (float(y) + (float(j) + 0.5f) / kReads) / float(height));
                    sum += sampleEquirect(equirect, shader::equirectToDirection(uv));
                }
            }
            const glm::vec3 mean = sum / float(kReads * kReads);
            std::copy(&mean.x, &mean.x + 3, &small.rgb[(size_t(y) * size_t(width) + size_t(x)) * 3]);
        }
    }
    DisplaySettings display;
    display.tonemap = Tonemap::PbrNeutral;
    return displayImage(small, display);
}

}  // namespace patina
