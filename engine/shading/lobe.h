#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "shading/material_parameters.h"

namespace patina {

// The BRDF in the plane of incidence: N = (0, 0, 1), L = (sin t_in, 0, cos t_in),
// V = (sin t_out, 0, cos t_out), t_out from -90 to 90 degrees. Values in 1/sr, no cosine.
// With a clear coat or a sheen (layered_brdf.h), the base's lobes are what gets through them
// and `layers` their own terms; 0 without. With KHR_materials_transmission (docs/SHADING.md S7)
// the diffuse is what the transmission leaves of it, and `transmitted` is the thin-walled BTDF
// below the surface, towards (sin t_out, 0, -cos t_out): the lobe through the wall, the
// reflection's mirrored, peaking straight through at -L (0 without; not in total(), which is
// the light above).
struct LobeSample {
    float thetaOutDegrees;
    glm::vec3 diffuse;
    glm::vec3 specular;
    glm::vec3 layers{0.0f};
    glm::vec3 transmitted{0.0f};
    glm::vec3 total() const { return diffuse + specular + layers; }
};

// `samples` >= 2 evenly spaced angles including both ends.
std::vector<LobeSample> evaluateLobe(const MaterialParameters& material, float thetaInDegrees, int samples);
// One row a sample; a lobe with layers has their columns too (layers_r, _g, _b, before total),
// a transmitting one the transmitted lobe's after total (transmitted_r, _g, _b).
std::string formatLobeCsv(const std::vector<LobeSample>& lobe);

}  // namespace patina
