#include "picture/linear_difference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "picture/compositing.h"
#include "shading/shading.h"

namespace patina {

namespace {

std::string sizeText(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

void checkFactor(const HdrImage& image, int factor) {
    if (image.width < 1 || image.height < 1 || image.rgb.size() != size_t(image.width) * size_t(image.height) * 3) {
        throw std::invalid_argument("not a valid linear image");
    }
    if (factor < 1 || image.width % factor != 0 || image.height % factor != 0) {
        throw std::invalid_argument("a " + sizeText(image.width, image.height) + " image cannot be shrunk by " +
                                    std::to_string(factor) + ": each side must be a multiple of it");
    }
}

void checkComparable(const HdrImage& a, const HdrImage& b, const std::vector<uint8_t>& mask) {
    checkFactor(a, 1);
    checkFactor(b, 1);
    if (a.width != b.width || a.height != b.height) {
        throw std::invalid_argument("cannot compare a " + sizeText(a.width, a.height) + " image with a " +
                                    sizeText(b.width, b.height) + " one");
    }
    if (mask.size() != size_t(a.width) * size_t(a.height)) {
        throw std::invalid_argument("the mask has " + std::to_string(mask.size()) + " pixels, the images " +
                                    std::to_string(size_t(a.width) * size_t(a.height)));
    }
}

// The pixel as displayed, in sRGB levels 0-255 (unrounded).
glm::vec3 displayed(const HdrImage& image, size_t pixel, const DisplaySettings& display) {
    const float* rgb = &image.rgb[pixel * 3];
    const glm::vec3 shown = shader::displayTransform(glm::vec3(rgb[0], rgb[1], rgb[2]), display.exposure,
                                                     tonemapShaderIndex(display.tonemap));
    return glm::clamp(shown, glm::vec3(0.0f), glm::vec3(1.0f)) * 255.0f;
}

}  // namespace

HdrImage downsampleBox(const HdrImage& image, int factor) {
    checkFactor(image, factor);
    HdrImage small{image.width / factor, image.height / factor, {}};
    small.rgb.assign(size_t(small.width) * size_t(small.height) * 3, 0.0f);
    const double weight = 1.0 / double(factor * factor);
    for (int y = 0; y < small.height; ++y) {
        for (int x = 0; x < small.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                double sum = 0.0;
                for (int j = 0; j < factor; ++j) {
                    for (int i = 0; i < factor; ++i) {
                        sum += image.rgb[((size_t(y * factor + j) * size_t(image.width)) + size_t(x * factor + i)) * 3 +
                                         size_t(c)];
                    }
                }
                small.rgb[(size_t(y) * size_t(small.width) + size_t(x)) * 3 + size_t(c)] = float(sum * weight);
            }
        }
    }
    return small;
}

std::vector<uint8_t> coverageMask(const HdrImage& coverage, int factor, int erode) {
    checkFactor(coverage, factor);
    if (erode < 0) {
        throw std::invalid_argument("a mask cannot be eroded by " + std::to_string(erode) + " pixels");
    }
    const int width = coverage.width / factor, height = coverage.height / factor;
    std::vector<uint8_t> covered(size_t(width) * size_t(height), 1);
    for (int y = 0; y < coverage.height; ++y) {
        for (int x = 0; x < coverage.width; ++x) {
            const float* v = &coverage.rgb[(size_t(y) * size_t(coverage.width) + size_t(x)) * 3];
            if (v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f) {
                covered[size_t(y / factor) * size_t(width) + size_t(x / factor)] = 0;
            }
        }
    }
    std::vector<uint8_t> mask(covered.size(), 0);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            bool all = true;
            for (int j = y - erode; all && j <= y + erode; ++j) {
                for (int i = x - erode; all && i <= x + erode; ++i) {
                    // Beyond the image counts as uncovered: what the frame cuts is an edge too.
                    all = j >= 0 && j < height && i >= 0 && i < width && covered[size_t(j) * size_t(width) + size_t(i)];
                }
            }
            mask[size_t(y) * size_t(width) + size_t(x)] = all ? 1 : 0;
        }
    }
    return mask;
}

MaskedDifference maskedDifference(const HdrImage& a, const HdrImage& b, const std::vector<uint8_t>& mask,
                                  const DisplaySettings& display) {
    checkComparable(a, b, mask);
    double absolute = 0.0, signedSum = 0.0;
    MaskedDifference result;
    for (size_t pixel = 0; pixel < mask.size(); ++pixel) {
        if (!mask[pixel]) {
            continue;
        }
        const glm::vec3 difference = displayed(b, pixel, display) - displayed(a, pixel, display);
        for (int c = 0; c < 3; ++c) {
            absolute += std::abs(double(difference[c]));
            signedSum += double(difference[c]);
        }
        ++result.pixels;
    }
    if (result.pixels > 0) {
        result.meanAbsolute = absolute / (3.0 * double(result.pixels));
        result.meanSigned = signedSum / (3.0 * double(result.pixels));
    }
    return result;
}

LdrImage maskedHeatMap(const HdrImage& a, const HdrImage& b, const std::vector<uint8_t>& mask,
                       const DisplaySettings& display, float gain) {
    checkComparable(a, b, mask);
    LdrImage map{a.width, a.height, std::vector<uint8_t>(mask.size() * 4, 255)};
    for (size_t pixel = 0; pixel < mask.size(); ++pixel) {
        Rgb8 colour{96, 96, 96};
        if (mask[pixel]) {
            const glm::vec3 difference = glm::abs(displayed(b, pixel, display) - displayed(a, pixel, display));
            colour = heatColour(int(std::lround(gain * std::max({difference.x, difference.y, difference.z}))));
        }
        map.rgba[pixel * 4] = colour.r;
        map.rgba[pixel * 4 + 1] = colour.g;
        map.rgba[pixel * 4 + 2] = colour.b;
    }
    return map;
}

}  // namespace patina
