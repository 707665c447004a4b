#pragma once
// The probe command's files (README, "The command line").
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "reference/probe_reference.h"
#include "scene/probe.h"

namespace patina {

// Reads `px,py,pz,nx,ny,nz,vx,vy,vz` CSV; throws InputError naming file and line.
std::vector<ProbeSample> parseProbeCsv(const std::string& text, const std::string& source);
// `r,g,b` with 9 significant digits, one row per value.
std::string formatRadianceCsv(const std::vector<glm::vec3>& radiance);

// `r,g,b,se_r,se_g,se_b`: the reference backend's value and standard error per row.
std::string formatReferenceCsv(const std::vector<ReferenceRow>& rows);

}  // namespace patina
