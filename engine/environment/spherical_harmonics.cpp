#include "environment/spherical_harmonics.h"

#include <algorithm>
#include <cmath>

#include "shading/shading.h"

namespace patina {

ShCoefficients projectSH(const HdrImage& image) {
    std::array<glm::dvec3, 9> sum{};
    const double dPhi = 2.0 * double(shader::PATINA_PI) / double(image.width);
    for (int y = 0; y < image.height; ++y) {
        const double theta0 = double(y) / image.height * double(shader::PATINA_PI);
        const double theta1 = double(y + 1) / image.height * double(shader::PATINA_PI);
        const double solidAngle = dPhi * (std::cos(theta0) - std::cos(theta1));
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 d = shader::equirectToDirection(
                glm::vec2((float(x) + 0.5f) / float(image.width), (float(y) + 0.5f) / float(image.height)));
            const float* p = &image.rgb[(size_t(y) * size_t(image.width) + size_t(x)) * 3];
            const glm::dvec3 radiance(p[0], p[1], p[2]);
            for (int i = 0; i < 9; ++i) {
                sum[size_t(i)] += radiance * (double(shader::shBasis(i, d)) * solidAngle);
            }
        }
    }
    ShCoefficients coefficients;
    for (size_t i = 0; i < 9; ++i) {
        coefficients[i] = glm::vec3(sum[i]);
    }
    return coefficients;
}

ShCoefficients windowSH(const ShCoefficients& coefficients) {
    const double pi = double(shader::PATINA_PI);
    const float band1 = float(std::sin(pi / 3.0) / (pi / 3.0)), band2 = float(std::sin(2.0 * pi / 3.0) / (2.0 * pi / 3.0));
    ShCoefficients windowed = coefficients;
    for (size_t i = 1; i < 9; ++i) {
        windowed[i] *= i < 4 ? band1 : band2;
    }
    return windowed;
}

glm::vec3 irradianceUnclamped(const ShCoefficients& coefficients, glm::vec3 n) {
    glm::vec3 c[9];
    std::copy(coefficients.begin(), coefficients.end(), c);
    return shader::irradianceSHUnclamped(c, n);
}

}  // namespace patina
