#pragma once
// The shared GLSL (shaders/shared/brdf.glsl, lights.glsl) compiled a second time with `real` a
// double: the guarded code itself in double precision. It tells fp32 rounding apart from what
// the guards do, and is the fp64 row of the precision comparisons.
// Literal constants keep their float rounding (5.55473f and PATINA_PI differ from the decimal
// values by about 3e-8 relative); everything computed from them is double.
#include <cmath>

#include <glm/glm.hpp>

namespace patina::shader_f64 {
using namespace glm;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using std::sqrt;
// The float literals make mixed (double, float) calls, which glm's one-type templates refuse.
using glm::clamp;
using glm::max;
using glm::min;
inline double max(double a, double b) { return a > b ? a : b; }
inline double min(double a, double b) { return a < b ? a : b; }
inline double clamp(double x, double lo, double hi) { return min(max(x, lo), hi); }
using real = double;   // the shared code's scalar (shaders/shared/brdf.glsl)
#define PATINA_INLINE inline
#include "brdf.glsl"
#include "iridescence.glsl"
#include "lights.glsl"
#include "clearcoat.glsl"
// sheen.glsl's table (engine/shading/sheen_table.cpp): E at N.V = x / 31, r = y / 31.
real sheenTexel(int x, int y);
#include "sheen.glsl"
#undef PATINA_INLINE
}  // namespace patina::shader_f64
