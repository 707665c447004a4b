#include "reference/probe_reference.h"

#include <optional>

#include "common/parallel_for.h"
#include "reference/radiance.h"
#include "scene/light_packing.h"
#include "shading/cpu_shading.h"

namespace patina {

std::vector<ReferenceRow> probeReference(const MaterialParameters& material, const std::vector<Light>& lights,
                                         const std::vector<ProbeSample>& samples,
                                         const std::shared_ptr<const Environment>& environment, int samplesPerRow,
                                         uint64_t pass) {
    return probeReference({material}, std::vector<int32_t>(samples.size(), 0), lights, samples, environment,
                          samplesPerRow, pass);
}

std::vector<ReferenceRow> probeReference(const std::vector<MaterialParameters>& materials,
                                         const std::vector<int32_t>& materialOfSample,
                                         const std::vector<Light>& lights, const std::vector<ProbeSample>& samples,
                                         const std::shared_ptr<const Environment>& environment, int samplesPerRow,
                                         uint64_t pass, const std::vector<float>& occlusion,
                                         const RayCaster* occluders, const std::vector<glm::vec4>& tangents) {
    std::vector<shader::SurfaceMaterial> surfaces;
    for (const MaterialParameters& material : materials) {
        surfaces.push_back(surfaceMaterial(material));
    }
    const std::vector<shader::PackedLight> packed = packEnabledLights(lights);
    const Light* environmentLight = enabledEnvironment(lights);
    const std::shared_ptr<const Environment> shown =
        environmentLight ? environmentShown(environment, environmentLight->source) : nullptr;
    std::optional<EnvironmentDistribution> distribution;
    ReferenceEnvironment reference;
    if (environmentLight) {
        distribution.emplace(shown->image);
        reference = {shown.get(), &*distribution, environmentLight->intensity, environmentLight->rotationDegrees};
    }
    std::vector<ReferenceRow> rows(samples.size());
    parallelFor(samples.size(), [&](size_t i) {
        ReferenceOptions options;
        options.samples = samplesPerRow;
        options.seed = 0x9E3779B97F4A7C15ull * (i + 1) + 0xD1B54A32D192ED03ull * pass;
        options.indirectOcclusion = occlusion.empty() ? 1.0f : occlusion[i];
        options.occluders = occluders;
        const size_t m = size_t(materialOfSample[i]);
        // KHR_materials_anisotropy's lobe turns with the surface: derived at the sample, from its
        // tangent where the rows have them, else along the fallback (a probe's sample has none).
        const glm::vec4 tangent = tangents.empty() ? glm::vec4(0.0f) : tangents[i];
        const shader::SurfaceMaterial surface =
            materials[m].anisotropyStrength > 0.0f
                ? surfaceMaterialAt(materials[m], shader::safeNormalize(samples[i].normal), tangent)
                : surfaces[m];
        const ReferenceEstimate e = referenceRadiance(materials[m].model, surface, reference, packed,
                                                      samples[i].position, samples[i].normal, samples[i].toViewer,
                                                      withLayersOf(options, materials[m]));
        rows[i] = {e.value, e.standardError};
    });
    return rows;
}

}  // namespace patina
