#pragma once
#include <vector>

namespace patina {

// E(N.V, r): the directional albedo of KHR_materials_sheen's lobe, the Charlie distribution
// with Neubelt & Pettineo's visibility and sheenColor 1 (shaders/shared/sheen.glsl),
// kSheenTableSize^2 values, N.V and r at i / (size - 1), row-major by r. Integrated on first use
// (thread-safe) and kept for the process; sheen.glsl interpolates it (sheenAlbedo).
constexpr int kSheenTableSize = 32;
const std::vector<float>& sheenAlbedoTable();

// E(N.V, r) integrated directly, in double, with the floors the shading applies: importance
// sampling of the Charlie distribution's half vectors over a Hammersley set of `samples`
// points (D cos(theta_h) is normalised, so sin(theta_h) = u^(alpha / (2 alpha + 1)) draws it),
// each weighed by f N.L / pdf = V N.L 4 V.H / N.H (pdf(L) = D N.H / (4 V.H), Walter et al.
// 2007 eq. 14).
double sheenDirectionalAlbedo(double NoV, double roughness, int samples = 2048);

}  // namespace patina
