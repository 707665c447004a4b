#pragma once
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "environment/environment.h"
#include "scene/material.h"
#include "scene/scene.h"

namespace patina {

// One shading query: world position, normal, unit vector towards the camera.
struct ProbeSample {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 toViewer;
};

// Linear radiance summed over the enabled lights, by the shared shading code compiled as C++:
// the lights, then an enabled environment light showing `environment` by the split sum
// (an std::invalid_argument when null).
std::vector<glm::vec3> probeOnCpu(const Material& material, const std::vector<Light>& lights,
                                  const std::vector<ProbeSample>& samples,
                                  const std::shared_ptr<const Environment>& environment = nullptr);

}  // namespace patina
