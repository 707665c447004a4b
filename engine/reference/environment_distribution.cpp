#include "reference/environment_distribution.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "common/luminance.h"
#include "shading/shading.h"

namespace patina {

namespace {

// The index i with cdf[i] <= u < cdf[i + 1] and how far into it u lies.
std::pair<int, float> invert(const float* cdf, int count, float u) {
    const float* at = std::upper_bound(cdf, cdf + count + 1, u);
    const int i = std::clamp(int(at - cdf) - 1, 0, count - 1);
    const float width = cdf[i + 1] - cdf[i];
    return {i, width > 0.0f ? std::clamp((u - cdf[i]) / width, 0.0f, 1.0f) : 0.5f};
}
}  // namespace

EnvironmentDistribution::EnvironmentDistribution(const HdrImage& image)
    : width_(image.width), height_(image.height), rowCdf_(size_t(height_) + 1, 0.0f),
      columnCdf_(size_t(height_) * size_t(width_ + 1), 0.0f), pixelPdf_(size_t(width_) * size_t(height_), 0.0f) {
    // The estimate reads the image bilinearly, so a pixel's radiance reaches half a pixel into
    // its neighbours: each pixel is weighted by the brightest of itself and the 8 around it, or a
    // dark pixel beside a sun would be drawn rarely and weigh hugely when it is (fireflies; a
    // 20000-sample estimate under a sun had a standard error of 25% with the pixel's own
    // luminance). A floor keeps every direction possible.
    double total = 0.0;
    std::vector<double> weights(pixelPdf_.size());
    for (int y = 0; y < height_; ++y) {
        const double sinTheta = std::sin((double(y) + 0.5) / height_ * double(std::numbers::pi_v<float>));
        for (int x = 0; x < width_; ++x) {
            float brightest = 0.0f;
            for (int dy = -1; dy <= 1; ++dy) {
                const int row = std::clamp(y + dy, 0, height_ - 1);
                for (int dx = -1; dx <= 1; ++dx) {
                    const int column = (x + dx + width_) % width_;   // wraps in longitude
                    brightest = std::max(brightest, luminance(&image.rgb[(size_t(row) * size_t(width_) + size_t(column)) * 3]));
                }
            }
            const size_t i = size_t(y) * size_t(width_) + size_t(x);
            weights[i] = (double(brightest) + 1e-4) * sinTheta;
            total += weights[i];
        }
    }
    double rowSum = 0.0;
    for (int y = 0; y < height_; ++y) {
        double columnSum = 0.0;
        float* columns = &columnCdf_[size_t(y) * size_t(width_ + 1)];
        for (int x = 0; x < width_; ++x) {
            columnSum += weights[size_t(y) * size_t(width_) + size_t(x)];
        }
        double running = 0.0;
        for (int x = 0; x < width_; ++x) {
            const double w = weights[size_t(y) * size_t(width_) + size_t(x)];
            running += w;
            columns[x + 1] = float(running / columnSum);
            // Pixels cover 1 / (width height) of the unit uv square each.
            pixelPdf_[size_t(y) * size_t(width_) + size_t(x)] = float(w / total * double(width_) * double(height_));
        }
        columns[width_] = 1.0f;
        rowSum += columnSum;
        rowCdf_[size_t(y) + 1] = float(rowSum / total);
    }
    rowCdf_[size_t(height_)] = 1.0f;
}

EnvironmentDistribution::Sample EnvironmentDistribution::sample(float u1, float u2) const {
    const auto [y, fy] = invert(rowCdf_.data(), height_, u1);
    const auto [x, fx] = invert(&columnCdf_[size_t(y) * size_t(width_ + 1)], width_, u2);
    const glm::vec2 uv((float(x) + fx) / float(width_), (float(y) + fy) / float(height_));
    const glm::vec3 direction = shader::equirectToDirection(uv);
    const float sinTheta = std::sin(uv.y * std::numbers::pi_v<float>);
    const float pdf = sinTheta > 0.0f ? pixelPdf_[size_t(y) * size_t(width_) + size_t(x)] /
                                            (2.0f * std::numbers::pi_v<float> * std::numbers::pi_v<float> * sinTheta)
                                      : 0.0f;
    return {direction, pdf};
}

float EnvironmentDistribution::pdf(glm::vec3 direction) const {
    const glm::vec2 uv = shader::directionToEquirect(direction);
    const int x = std::clamp(int(uv.x * float(width_)), 0, width_ - 1);
    const int y = std::clamp(int(uv.y * float(height_)), 0, height_ - 1);
    const float sinTheta = std::sin(uv.y * std::numbers::pi_v<float>);
    return sinTheta > 0.0f ? pixelPdf_[size_t(y) * size_t(width_) + size_t(x)] /
                                 (2.0f * std::numbers::pi_v<float> * std::numbers::pi_v<float> * sinTheta)
                           : 0.0f;
}

}  // namespace patina
