#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "material.h"
#include "scene.h"

namespace patina {

// One shading query: world position, normal, unit vector towards the camera.
struct ProbeSample {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 toViewer;
};

// Reads `px,py,pz,nx,ny,nz,vx,vy,vz` CSV; throws InputError naming file and line.
std::vector<ProbeSample> parseProbeCsv(const std::string& text, const std::string& source);
// `r,g,b` with 9 significant digits, one row per value.
std::string formatRadianceCsv(const std::vector<glm::vec3>& radiance);

// Linear radiance summed over the enabled lights, by the shared shading code compiled as C++.
std::vector<glm::vec3> probeOnCpu(const Material& material, const std::vector<Light>& lights,
                                  const std::vector<ProbeSample>& samples);

}  // namespace patina
