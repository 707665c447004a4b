#pragma once
// The GLSL in shaders/ compiled as C++: GLM supplies vec3, dot, mix, exp2, ... with GLSL's
// names and meaning, so these are the very functions the GPU runs.
#include <cmath>

#include <glm/glm.hpp>

namespace patina::shader {
using namespace glm;
using std::sqrt;
#define PATINA_INLINE inline
#include "brdf.glsl"
#include "lights.glsl"
#include "display.glsl"
#undef PATINA_INLINE
}  // namespace patina::shader

// The default model, "epic", as shader::evaluateBrdf and shader::shadeLight; every model is in
// engine/shading/brdf_models.h.
#include "shading/energy_table.h"
namespace patina::shader {
// In a namespace of its own so that argument-dependent lookup from the other models'
// namespaces (brdf_model_instance.h) never sees it; the using-directive serves shader::name.
namespace seed {
#define PATINA_INLINE inline
inline float energyTexel(int, int) {
    return 1.0f;   // epic has no energy compensation: never read
}
#include "energy_table.glsl"
// A permutation uses only some parameters of each dispatch function (Lambert ignores the angles).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "brdf_model.glsl"
#pragma GCC diagnostic pop
#undef PATINA_INLINE
}  // namespace seed
using namespace seed;
#undef PATINA_D
#undef PATINA_V
#undef PATINA_F
#undef PATINA_FD
#undef PATINA_MS
}  // namespace patina::shader
