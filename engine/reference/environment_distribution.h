#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "common/hdr_image.h"

namespace patina {

// Importance sampling of an equirect image: a piecewise-constant 2D distribution over its
// pixels weighted by luminance * sin(theta) (pbrt-v4's ImageInfiniteLight), so directions come
// where the light is. Directions are in the image's own frame.
class EnvironmentDistribution {
public:
    explicit EnvironmentDistribution(const HdrImage& image);
    struct Sample {
        glm::vec3 direction;
        float pdf;   // per unit solid angle
    };
    Sample sample(float u1, float u2) const;
    // pdf_omega = pdf_uv / (2 pi^2 sin theta).
    float pdf(glm::vec3 direction) const;

private:
    int width_ = 0, height_ = 0;
    std::vector<float> rowCdf_;      // height + 1
    std::vector<float> columnCdf_;   // height * (width + 1)
    std::vector<float> pixelPdf_;    // per unit uv area
};

}  // namespace patina
