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
    // With an enabled environment light among `lights`, `environment` is what it shows (an
    // std::invalid_argument when null).
    std::vector<glm::vec3> evaluate(const Material& material, const std::vector<Light>& lights,
                                    const std::vector<ProbeSample>& samples,
                                    const std::shared_ptr<const Environment>& environment = nullptr);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace patina
