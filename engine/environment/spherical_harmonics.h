#pragma once
#include <array>

#include <glm/vec3.hpp>

#include "common/hdr_image.h"

namespace patina {

// The irradiance as the renderer had it until the irradiance map (irradiance.h) replaced it,
// kept as the measured alternative (docs/LIGHTING.md, "Diffuse"): the 9 coefficients L_lm
// (l <= 2) of an equirect image's radiance in the real basis (Ramamoorthi and Hanrahan 2001,
// eq. 3), each pixel weighted by its exact solid angle (eq. 10), and
// E(n) = sum over l <= 2 of A_l L_lm Y_lm(n) with A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4
// (eqs. 7-8). Nine terms ring around a small bright source and go negative on its far side.
using ShCoefficients = std::array<glm::vec3, 9>;
ShCoefficients projectSH(const HdrImage& equirect);

// The ringing guard beyond a clamp at 0: bands 1 and 2 scaled by Lanczos's sigma
// factors sinc(pi l / 3) (Sloan 2008, "Stupid Spherical Harmonics Tricks", section 7).
ShCoefficients windowSH(const ShCoefficients& coefficients);

// E(n) without the clamp (what the guard is measured against).
glm::vec3 irradianceUnclamped(const ShCoefficients& coefficients, glm::vec3 n);

}  // namespace patina
