#pragma once
// The GLSL in shaders/ compiled as C++: GLM supplies vec3, dot, mix, exp2, ... with GLSL's
// names and meaning, so these are the very functions the GPU runs.
#include <cmath>
#include <functional>

#include <glm/glm.hpp>

namespace patina::shader {
using namespace glm;
using std::sqrt;
using real = float;   // the shared code's scalar (shaders/shared/brdf.glsl)
#define PATINA_INLINE inline
#include "brdf.glsl"
#include "iridescence.glsl"
#include "lights.glsl"
#include "clearcoat.glsl"
// sheen.glsl's table (engine/shading/sheen_table.cpp): E at N.V = x / 31, r = y / 31.
real sheenTexel(int x, int y);
#include "sheen.glsl"
#include "transmission.glsl"
#include "display.glsl"
#include "channels.glsl"
#include "texture.glsl"
// The prefilter's source on the CPU (ibl.glsl): any trilinear lookup of (direction, mip).
using EnvironmentSource = const std::function<vec3(vec3, real)>&;
inline vec3 sampleEnvironmentSource(EnvironmentSource source, vec3 direction, real lod) {
    return source(direction, lod);
}
#include "ibl.glsl"
#undef PATINA_INLINE
}  // namespace patina::shader

// The BRDF models built from these, the default "epic" among them, are compiled once each in
// shading/brdf_models.cpp and reached through shading/brdf_models.h.
