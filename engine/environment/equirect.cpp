#include "environment/equirect.h"

#include <algorithm>
#include <cmath>

#include "shading/shading.h"

namespace patina {

namespace {
glm::vec3 pixel(const HdrImage& image, int x, int y) {
    const float* p = &image.rgb[(size_t(y) * size_t(image.width) + size_t(x)) * 3];
    return {p[0], p[1], p[2]};
}
}  // namespace

glm::vec3 sampleEquirect(const HdrImage& image, glm::vec3 direction) {
    const glm::vec2 uv = shader::directionToEquirect(direction);
    const float x = uv.x * float(image.width) - 0.5f, y = uv.y * float(image.height) - 0.5f;
    const float x0f = std::floor(x), y0f = std::floor(y);
    const float fx = x - x0f, fy = y - y0f;
    auto wrap = [&](int i) { return ((i % image.width) + image.width) % image.width; };
    auto row = [&](int j) { return std::clamp(j, 0, image.height - 1); };
    const int x0 = wrap(int(x0f)), x1 = wrap(int(x0f) + 1), y0 = row(int(y0f)), y1 = row(int(y0f) + 1);
    return (pixel(image, x0, y0) * (1.0f - fx) + pixel(image, x1, y0) * fx) * (1.0f - fy) +
           (pixel(image, x0, y1) * (1.0f - fx) + pixel(image, x1, y1) * fx) * fy;
}

CubeLevel equirectToCube(const HdrImage& image, int faceSize) {
    CubeLevel level(faceSize);
    for (int face = 0; face < 6; ++face) {
        for (int t = 0; t < faceSize; ++t) {
            for (int s = 0; s < faceSize; ++s) {
                glm::vec3 sum(0.0f);
                for (int j = 0; j < 2; ++j) {
                    for (int i = 0; i < 2; ++i) {
                        const float sc = (float(s) + 0.25f + 0.5f * float(i)) / float(faceSize) * 2.0f - 1.0f;
                        const float tc = (float(t) + 0.25f + 0.5f * float(j)) / float(faceSize) * 2.0f - 1.0f;
                        sum += sampleEquirect(image, glm::normalize(cubeFaceDirection(face, sc, tc)));
                    }
                }
                level.setTexel(face, s, t, sum * 0.25f);
            }
        }
    }
    return level;
}

int cubeFaceSizeFor(int width) {
    int size = 16;
    while (size < 512 && size * 4 < width) {
        size *= 2;
    }
    return size;
}

size_t replaceInvalidPixels(HdrImage& image) {
    size_t replaced = 0;
    for (size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
        bool bad = false;
        for (size_t c = 0; c < 3; ++c) {
            float& v = image.rgb[i + c];
            if (!std::isfinite(v) || v < 0.0f) {
                v = 0.0f;
                bad = true;
            }
        }
        replaced += bad ? 1 : 0;
    }
    return replaced;
}

const char* environmentSizeProblem(long long width, long long height) {
    if (width < 1 || height < 1) {
        return "has no pixels";
    }
    if (width > kMaxEnvironmentSide || height > kMaxEnvironmentSide) {
        return "is larger than 16384 pixels a side";
    }
    if (double(width) * double(height) * 12.0 > double(kMaxEnvironmentBytes)) {
        return "would take more than 256 MiB decoded";
    }
    return "";
}

}  // namespace patina
