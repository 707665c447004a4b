#pragma once
#include <vector>

#include "scene/scene.h"
#include "shading/shading.h"

namespace patina {

// The enabled lights of a scene in the layout shaders/shared/lights.glsl reads (std140-compatible:
// seven vec4s per light): points, then directionals, hemispheres, spheres and tubes, each in
// scene order.
// Grouped so the single pass loops over each type with no type branch per light (a branch
// that software rasterisers pay for in every lane), and every path sums in this one order.
std::vector<shader::PackedLight> packEnabledLights(const std::vector<Light>& lights);
// Which of `lights` packEnabledLights packs, in its order: the packed list's i-th light is
// lights[order[i]].
std::vector<size_t> enabledLightOrder(const std::vector<Light>& lights);
// uLightCount of shade.frag: (all, points, directionals, hemispheres) of a packed list.
glm::ivec4 packedLightCounts(const std::vector<shader::PackedLight>& packed);
// uAreaLightCount of shade.frag: (spheres, tubes, 0, 0).
glm::ivec4 packedAreaLightCounts(const std::vector<shader::PackedLight>& packed);

shader::PackedLight packLight(const Light& light);
// A packed point, sphere or tube light whose coefficients are exactly KARIS_ATTENUATION.
bool hasKarisAttenuation(const shader::PackedLight& light);

}  // namespace patina
