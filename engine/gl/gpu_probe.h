#pragma once
#include <memory>
#include <vector>

#include "scene/probe.h"

namespace patina {

// Evaluates shaders/stages/shade.frag itself, one probe per pixel of a float target, so the GPU's
// arithmetic can be checked against the CPU and the double reference. Needs a current context.
class GpuProbe {
public:
    GpuProbe();
    ~GpuProbe();
    std::vector<glm::vec3> evaluate(const Material& material, const std::vector<Light>& lights,
                                    const std::vector<ProbeSample>& samples);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace patina
