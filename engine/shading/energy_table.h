#pragma once
#include <vector>

namespace patina {

enum class BrdfModelId;

// E(NoV, r): the directional albedo of a model's single-scattering specular lobe with F = 1,
// kEnergyTableSize^2 values, NoV and r at i / (size - 1), row-major by r. Integrated on first
// use (thread-safe) and kept for the process. shaders/shared/energy_table.glsl interpolates it.
constexpr int kEnergyTableSize = 32;
const std::vector<float>& energyTable(BrdfModelId id);

// The table interpolated as the shaders do it (shaders/shared/energy_table.glsl).
float tabulatedAlbedo(BrdfModelId id, float NoV, float roughness);

// E(NoV, r) integrated directly: GGX importance sampling of the half vector (Walter et al.
// 2007, eqs. 35-36) over a Hammersley set of `samples` points, in double.
double directionalAlbedo(BrdfModelId id, double NoV, double roughness, int samples = 4096);

}  // namespace patina
