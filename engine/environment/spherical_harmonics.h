#pragma once
#include <array>

#include <glm/vec3.hpp>

#include "common/hdr_image.h"

namespace patina {

// The 9 coefficients L_lm (l <= 2) of an equirect image's radiance, in the real basis of
// shaders/shared/ibl.glsl's shBasis, each pixel weighted by its exact solid angle
// (Ramamoorthi and Hanrahan 2001, eq. 10).
using ShCoefficients = std::array<glm::vec3, 9>;
ShCoefficients projectSH(const HdrImage& equirect);

// The ringing guard beyond the shader's clamp at 0: bands 1 and 2 scaled by Lanczos's sigma
// factors sinc(pi l / 3) (Sloan 2008, "Stupid Spherical Harmonics Tricks", section 7).
ShCoefficients windowSH(const ShCoefficients& coefficients);

// E(n) without the clamp (what the guard is measured against).
glm::vec3 irradianceUnclamped(const ShCoefficients& coefficients, glm::vec3 n);

}  // namespace patina
