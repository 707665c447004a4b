#pragma once
// The shared GLSL compiled a third time, with `real` a binary16 emulated on the CPU
// (engine/shading/half.h): the fp16 row of the precision comparisons. Literal constants are rounded to
// half where they are used, as a half-precision shader would hold them. PATINA_HALF_PRECISION
// selects the fp16 guards of shaders/shared/brdf.glsl (roughness floor 0.089, D capped at 65504).
#include "shading/half.h"

namespace patina::shader_f16 {
using vec3 = HalfVec3;
using namespace half_glsl;
using real = Half;   // the shared code's scalar (shaders/shared/brdf.glsl)
#define PATINA_INLINE inline
#define PATINA_HALF_PRECISION
#include "brdf.glsl"
#include "lights.glsl"
#undef PATINA_HALF_PRECISION
#undef PATINA_INLINE
}  // namespace patina::shader_f16
