#include "scene/probe.h"

#include "scene/light_packing.h"
#include "shading/cpu_shading.h"

namespace patina {

std::vector<glm::vec3> probeOnCpu(const Material& material, const std::vector<Light>& lights,
                                  const std::vector<ProbeSample>& samples) {
    const shader::SurfaceMaterial surface = surfaceMaterial(material);
    const std::vector<shader::PackedLight> packed = packEnabledLights(lights);
    std::vector<glm::vec3> radiance;
    radiance.reserve(samples.size());
    for (const ProbeSample& sample : samples) {
        radiance.push_back(shadePoint(material.model, surface, packed, sample.position, sample.normal, sample.toViewer));
    }
    return radiance;
}

}  // namespace patina
