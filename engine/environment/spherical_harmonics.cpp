#include "environment/spherical_harmonics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shading/shading.h"

namespace patina {

namespace {
// The real basis Y_lm for l <= 2 (Ramamoorthi and Hanrahan 2001, eq. 3) and the cosine lobe's
// factors A_l: A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4 (eqs. 7-8).
double shBasis(int index, glm::dvec3 n) {
    switch (index) {
    case 0: return 0.282095;
    case 1: return 0.488603 * n.y;
    case 2: return 0.488603 * n.z;
    case 3: return 0.488603 * n.x;
    case 4: return 1.092548 * n.x * n.y;
    case 5: return 1.092548 * n.y * n.z;
    case 6: return 0.315392 * (3.0 * n.z * n.z - 1.0);
    case 7: return 1.092548 * n.x * n.z;
    default: return 0.546274 * (n.x * n.x - n.y * n.y);
    }
}

double shBandFactor(int index) {
    const double pi = std::numbers::pi;
    return index == 0 ? pi : index < 4 ? 2.0 * pi / 3.0 : pi / 4.0;
}
}  // namespace

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
                sum[size_t(i)] += radiance * (shBasis(i, glm::dvec3(d)) * solidAngle);
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
    glm::dvec3 sum(0.0);
    for (int i = 0; i < 9; ++i) {
        sum += glm::dvec3(coefficients[size_t(i)]) * (shBandFactor(i) * shBasis(i, glm::dvec3(n)));
    }
    return glm::vec3(sum);
}

}  // namespace patina
