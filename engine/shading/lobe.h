#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "shading/material_parameters.h"

namespace patina {

// The lobes of one pair of directions above the surface (N = (0, 0, 1)), the light along L and
// the view along V: the BRDF from L towards V, no cosine, 1/sr. With a clear coat or a sheen
// (layered_brdf.h), the base's lobes are what gets through them and `layers` their own terms; 0
// without. With KHR_materials_transmission (docs/SHADING.md S7) the diffuse is what the
// transmission leaves of it, and `transmitted` the thin-walled BTDF through the wall towards V
// mirrored below the surface, (V.x, V.y, -V.z): f_t is reciprocal, so it is seen from L with the
// light below, and weighed by the layers above it as the renderer weighs it, seen from L
// (layeredTransmission: the sheen's albedo scaling, the coat's 1 - clearcoat fr_c). 0 without;
// not in total(), which is the light above.
struct LobeValue {
    glm::vec3 diffuse{0.0f};
    glm::vec3 specular{0.0f};
    glm::vec3 layers{0.0f};
    glm::vec3 transmitted{0.0f};
    glm::vec3 total() const { return diffuse + specular + layers; }
};
LobeValue lobeValue(const MaterialParameters& material, glm::vec3 L, glm::vec3 V);

// The lobe in the plane of incidence: L = (sin t_in, 0, cos t_in), V = (sin t_out, 0, cos t_out),
// t_out from -90 to 90 degrees; `transmitted` towards (sin t_out, 0, -cos t_out), the
// reflection's mirrored, peaking straight through at -L.
struct LobeSample : LobeValue {
    float thetaOutDegrees = 0.0f;
};

// `samples` >= 2 evenly spaced angles including both ends.
std::vector<LobeSample> evaluateLobe(const MaterialParameters& material, float thetaInDegrees, int samples);
// One row a sample; a lobe with layers has their columns too (layers_r, _g, _b, before total),
// a transmitting one the transmitted lobe's after total (transmitted_r, _g, _b).
std::string formatLobeCsv(const std::vector<LobeSample>& lobe);

}  // namespace patina
