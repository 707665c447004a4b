#pragma once
// The inputs where the spec's formulas fail (../shared/spec/shading.md section 2), as probe
// rows and scenes, for the CPU and GPU edge sweeps.
#include <string>
#include <vector>

#include "scene/probe.h"
#include "scene/scene.h"

namespace patina {

struct EdgeCase {
    std::string name;
    Material material;
    std::vector<Light> lights;
    std::vector<ProbeSample> samples;
};

std::vector<EdgeCase> edgeCases();

}  // namespace patina
