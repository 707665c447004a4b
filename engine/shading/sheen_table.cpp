#include "shading/sheen_table.h"

#include <cmath>
#include <mutex>
#include <numbers>

#include "shading/shading.h"
#include "shading/shading_f64.h"

namespace patina {

namespace {

// Van der Corput radical inverse in base 2, in double (as energy_table.cpp's).
double radicalInverse(unsigned bits) {
    return double(shader::reverseBits(bits)) * 2.3283064365386963e-10;
}

std::vector<float> integrateTable() {
    std::vector<float> table(size_t(kSheenTableSize) * kSheenTableSize);
    for (int y = 0; y < kSheenTableSize; ++y) {
        for (int x = 0; x < kSheenTableSize; ++x) {
            const double NoV = double(x) / double(kSheenTableSize - 1);
            const double r = double(y) / double(kSheenTableSize - 1);
            table[size_t(y) * kSheenTableSize + size_t(x)] = float(sheenDirectionalAlbedo(NoV, r));
        }
    }
    return table;
}

}  // namespace

const std::vector<float>& sheenAlbedoTable() {
    static std::once_flag once;
    static std::vector<float> table;
    std::call_once(once, [] { table = integrateTable(); });
    return table;
}

double sheenDirectionalAlbedo(double NoV, double roughness, int samples) {
    // The same floors the shading applies (sheen.glsl's deriveSheen).
    const double r = std::max(roughness, double(shader::MIN_PERCEPTUAL_ROUGHNESS));
    const double alpha = r * r;
    NoV = std::max(NoV, double(shader::MIN_N_DOT_V));
    const glm::dvec3 V(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        const double u1 = (double(i) + 0.5) / double(samples), u2 = radicalInverse(unsigned(i));
        const double sinH = std::pow(u1, alpha / (2.0 * alpha + 1.0));
        const double cosH = std::sqrt(std::max(0.0, 1.0 - sinH * sinH));
        const double phi = 2.0 * std::numbers::pi * u2;
        const glm::dvec3 H(sinH * std::cos(phi), sinH * std::sin(phi), cosH);
        const double VoH = glm::dot(V, H);
        const double NoL = 2.0 * VoH * cosH - NoV;
        if (NoL <= 0.0 || VoH <= 0.0 || cosH <= 0.0) {
            continue;
        }
        sum += shader_f64::sheenVisibility(NoV, std::min(NoL, 1.0)) * NoL * 4.0 * VoH / cosH;
    }
    return sum / double(samples);
}

namespace shader {
real sheenTexel(int x, int y) {
    return sheenAlbedoTable()[size_t(y) * size_t(kSheenTableSize) + size_t(x)];
}
}  // namespace shader

namespace shader_f64 {
real sheenTexel(int x, int y) {
    return double(sheenAlbedoTable()[size_t(y) * size_t(kSheenTableSize) + size_t(x)]);
}
}  // namespace shader_f64

}  // namespace patina
