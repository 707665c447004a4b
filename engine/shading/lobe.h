#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "shading/material_parameters.h"

namespace patina {

// The BRDF in the plane of incidence: N = (0, 0, 1), L = (sin t_in, 0, cos t_in),
// V = (sin t_out, 0, cos t_out), t_out from -90 to 90 degrees. Values in 1/sr, no cosine.
struct LobeSample {
    float thetaOutDegrees;
    glm::vec3 diffuse;
    glm::vec3 specular;
    glm::vec3 total() const { return diffuse + specular; }
};

// `samples` >= 2 evenly spaced angles including both ends.
std::vector<LobeSample> evaluateLobe(const MaterialParameters& material, float thetaInDegrees, int samples);
std::string formatLobeCsv(const std::vector<LobeSample>& lobe);

}  // namespace patina
