#pragma once
// The per-type light functions with their compile-time switches, which the model dispatch of
// shading/brdf_models.h does not expose: the default model's permutation compiled for the
// tests as well, as shader::model_Epic (tests/shading/test_lights.cpp, test_area_lights.cpp).
#include "shading/energy_table.h"
#include "shading/shading.h"

namespace patina::shader {
#define PATINA_INLINE inline
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define PATINA_INSTANCE Epic
#include "shading/brdf_model_instance.h"
#pragma GCC diagnostic pop
#undef PATINA_INLINE
}  // namespace patina::shader
