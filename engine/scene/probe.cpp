#include "scene/probe.h"

#include <algorithm>
#include <stdexcept>

#include "scene/light_packing.h"
#include "shading/cpu_shading.h"

namespace patina {

std::vector<glm::vec3> probeOnCpu(const Material& material, const std::vector<Light>& lights,
                                  const std::vector<ProbeSample>& samples,
                                  const std::shared_ptr<const Environment>& environment) {
    const shader::SurfaceMaterial plain = surfaceMaterial(material);
    const std::vector<shader::PackedLight> packed = packEnabledLights(lights);
    const Light* environmentLight = enabledEnvironment(lights);
    const std::shared_ptr<const Environment> shown =
        environmentLight ? environmentShown(environment, environmentLight->source) : nullptr;
    std::vector<glm::vec3> radiance;
    radiance.reserve(samples.size());
    for (const ProbeSample& sample : samples) {
        // An anisotropic lobe turns from the fallback direction there (a probe has no tangent).
        const shader::SurfaceMaterial surface =
            material.anisotropyStrength > 0.0f
                ? surfaceMaterialAt(material, shader::safeNormalize(sample.normal), glm::vec4(0.0f))
                : plain;
        glm::vec3 value = shadePoint(material.model, surface, packed, sample.position, sample.normal, sample.toViewer);
        if (environmentLight) {
            // As shade.frag: the unit (or zero) N and V of shadePoint.
            value += shadeEnvironmentOnCpu(material.model, surface, *shown, environmentLight->intensity,
                                           environmentLight->rotationDegrees, shader::safeNormalize(sample.normal),
                                           shader::safeNormalize(sample.toViewer));
        }
        radiance.push_back(value);
    }
    return radiance;
}

}  // namespace patina
