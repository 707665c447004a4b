#include "shading/energy_table.h"

#include <array>
#include <cmath>
#include <mutex>
#include <numbers>

#include "shading/brdf_models.h"

namespace patina {

namespace {

// Van der Corput radical inverse in base 2 (the second coordinate of the Hammersley set), in
// double: the shared bit reversal of ibl.glsl, divided without fp32's rounding.
double radicalInverse(unsigned bits) {
    return double(shader::reverseBits(bits)) * 2.3283064365386963e-10;
}

std::vector<float> integrateTable(BrdfModelId id) {
    std::vector<float> table(size_t(kEnergyTableSize) * kEnergyTableSize);
    for (int y = 0; y < kEnergyTableSize; ++y) {
        for (int x = 0; x < kEnergyTableSize; ++x) {
            const double NoV = double(x) / double(kEnergyTableSize - 1);
            const double r = double(y) / double(kEnergyTableSize - 1);
            table[size_t(y) * kEnergyTableSize + size_t(x)] = float(directionalAlbedo(id, NoV, r, 1024));
        }
    }
    return table;
}
}  // namespace

const std::vector<float>& energyTable(BrdfModelId id) {
    static std::array<std::once_flag, brdfModelCount()> once;
    static std::array<std::vector<float>, brdfModelCount()> tables;
    const size_t index = size_t(id);
    std::call_once(once[index], [&] { tables[index] = integrateTable(id); });
    return tables[index];
}

double directionalAlbedo(BrdfModelId id, double NoV, double roughness, int samples) {
    // The same floors the shading applies (shaders/shared/brdf.glsl).
    const double r = std::max(roughness, double(shader::MIN_PERCEPTUAL_ROUGHNESS));
    const double alpha = r * r, a2 = alpha * alpha;
    NoV = std::max(NoV, double(shader::MIN_N_DOT_V));
    const glm::dvec3 N(0.0, 0.0, 1.0), V(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        const double u1 = (double(i) + 0.5) / double(samples), u2 = radicalInverse(unsigned(i));
        // GGX distribution of H: cos^2 theta_h = (1 - u) / (1 + (a^2 - 1) u).
        const double cosH = std::sqrt((1.0 - u1) / (1.0 + (a2 - 1.0) * u1));
        const double sinH = std::sqrt(std::max(0.0, 1.0 - cosH * cosH));
        const double phi = 2.0 * std::numbers::pi * u2;
        const glm::dvec3 H(sinH * std::cos(phi), sinH * std::sin(phi), cosH);
        const double VoH = glm::dot(V, H);
        const glm::dvec3 L = 2.0 * VoH * H - V;
        const double NoL = L.z;
        if (NoL <= 0.0 || VoH <= 0.0) {
            continue;
        }
        // pdf(L) = D(H) NoH / (4 VoH).
        const double base = cosH * cosH * (a2 - 1.0) + 1.0;
        const double pdf = a2 / (std::numbers::pi * base * base) * cosH / (4.0 * VoH);
        sum += specularLobeF64(id, roughness, N, V, L) * NoL / pdf;
    }
    return sum / double(samples);
}

}  // namespace patina
