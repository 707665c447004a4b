#pragma once
#include <vector>

#include "scene.h"
#include "shading.h"

namespace patina {

// The enabled lights of a scene in the layout shaders/lights.glsl reads (std140-compatible:
// six vec4s per light), in scene order.
std::vector<shader::PackedLight> packEnabledLights(const std::vector<Light>& lights);

shader::PackedLight packLight(const Light& light);

}  // namespace patina
