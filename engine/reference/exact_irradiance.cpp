#include "reference/exact_irradiance.h"

#include <glm/geometric.hpp>

#include "environment/irradiance.h"

namespace patina {

ExactIrradiance::ExactIrradiance(const HdrImage& image) {
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float* p = &image.rgb[(size_t(y) * size_t(image.width) + size_t(x)) * 3];
            if (p[0] > 0.0f || p[1] > 0.0f || p[2] > 0.0f) {
                const glm::vec3 moment(pixelMoment(image.width, image.height, x, y));
                pixels_.push_back({moment, glm::vec3(p[0], p[1], p[2])});
            }
        }
    }
}

glm::dvec3 ExactIrradiance::at(glm::vec3 n) const {
    glm::dvec3 sum(0.0);
    for (const Pixel& pixel : pixels_) {
        const float cosine = glm::dot(n, pixel.moment);
        if (cosine > 0.0f) {
            sum += glm::dvec3(pixel.radiance * cosine);
        }
    }
    return sum;
}

}  // namespace patina
