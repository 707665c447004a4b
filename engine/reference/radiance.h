#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "environment/environment.h"
#include "reference/environment_distribution.h"
#include "reference/visibility.h"
#include "shading/brdf_model_id.h"
#include "shading/material_parameters.h"
#include "shading/shading.h"

namespace patina {

// The environment of a reference estimate: the source image at full resolution, never the
// prefiltered chain, turned and scaled as the light says.
struct ReferenceEnvironment {
    const Environment* environment = nullptr;   // null: no environment
    const EnvironmentDistribution* distribution = nullptr;
    float intensity = 1.0f;
    float rotationDegrees = 0.0f;
};

struct ReferenceOptions {
    int samples = 1024;    // iterations; each draws one direction from each strategy
    uint64_t seed = 1;
    bool diffuse = true;    // the lobes estimated (both: the full f)
    bool specular = true;
    // What reaches the point of the environment's and the hemisphere lights' light (an
    // occlusion map's factor, glTF 2.0 3.9.3; shade.frag's OCCLUDED).
    float indirectOcclusion = 1.0f;
    // KHR_materials_clearcoat over the material (docs/SHADING.md S5) on the sample's normal:
    // its factor (0: none, and the estimate draws the same random numbers as without) and its
    // perceptual roughness. Every estimate takes the coated BRDF sample by sample.
    float clearcoat = 0.0f;
    float clearcoatRoughness = 0.0f;
    // KHR_materials_sheen beneath the coat (docs/SHADING.md S6) on the sample's normal: its
    // colour (0: none, and every estimate is as without) and its perceptual roughness. Every
    // estimate takes the extension's sheened BRDF sample by sample, E at N.V and N.L.
    glm::vec3 sheenColor{0.0f};
    float sheenRoughness = 0.0f;
    // What blocks the light (the scene's triangles, ray_caster.h): each point and directional
    // light by one shadow ray, every sample of the environment and of sphere and tube lights by
    // its own; hemisphere lights, which have no direction, are not shadowed. Null: nothing
    // blocks anything, the estimate of a point alone in its lights.
    const RayCaster* occluders = nullptr;
    // KHR_materials_transmission's factor (0: none, and every estimate is as without) and
    // KHR_materials_volume's attenuation T (docs/SHADING.md S7), thin-walled: that fraction of the
    // diffuse gone, the environment's light through the wall estimated by sampling the mirrored
    // GGX lobe (transmission.glsl's f_t), the other lights' by transmission.glsl exactly as the
    // GPU (sphere and tube lights at their centres, a hemisphere light along -V).
    float transmission = 0.0f;
    glm::vec3 transmissionAttenuation{1.0f};
};

// T of KHR_materials_volume for `material` (its thickness already in world units).
glm::vec3 volumeAttenuationOf(const MaterialParameters& material);

// `options` with `material`'s layers: its clear coat, sheen, transmission and the volume's T.
ReferenceOptions withLayersOf(ReferenceOptions options, const MaterialParameters& material);

struct ReferenceEstimate {
    glm::vec3 value{0.0f};
    glm::vec3 standardError{0.0f};
    // The share of `value` through the wall (ReferenceOptions::transmission; 0 without), for the
    // views that show the transmitted albedo beside the reflected.
    glm::vec3 transmitted{0.0f};
};

// A Monte Carlo estimate's running sums: its mean, and the variance of that mean (the sample
// variance over n - 1, divided by n).
struct SampleMoments {
    glm::dvec3 sum{0.0}, sumSquares{0.0};
    void add(glm::dvec3 x) {
        sum += x;
        sumSquares += x * x;
    }
    glm::dvec3 mean(double n) const { return sum / n; }
    glm::dvec3 varianceOfMean(double n) const {
        const glm::dvec3 m = mean(n);
        return glm::max(sumSquares / n - m * m, glm::dvec3(0.0)) / std::max(n - 1.0, 1.0);
    }
};

// The pdf of direction L under GGX half-vector sampling (importanceSampleGGX, ibl.glsl):
// D(H) NoH / (4 VoH); 0 where VoH <= 0.
float ggxPdf(glm::vec3 N, glm::vec3 V, glm::vec3 L, float alpha);

// The coat of `options` at (N, V): factor 0 where there is none.
shader::Clearcoat referenceCoat(const ReferenceOptions& options, glm::vec3 N, glm::vec3 V);

// The sheen of `options` at (N, V): colour 0 where there is none.
shader::Sheen referenceSheen(const ReferenceOptions& options, glm::vec3 N, glm::vec3 V);

// The layers over the base at one shading point.
struct ReferenceLayers {
    shader::Clearcoat coat;
    shader::Sheen sheen;
};

// The BRDF every estimate integrates towards unit L (times N.L, the layers' normal being N): the
// lobes of `f` that `options` asks for; the sheen (if any) over them, f sheenAlbedoScaling(N.V,
// N.L) + f_sheen (sheen.glsl); the coat (if any) over that, (1 - clearcoat fr_c) + the coat's
// term (clearcoat.glsl). Without either, the lobes' sum as it always was.
glm::vec3 coatedBrdf(const shader::BrdfValue& f, const ReferenceLayers& layers, glm::vec3 N, glm::vec3 V,
                     glm::vec3 L, const ReferenceOptions& options);

// Lo(V) = integral over the hemisphere of Env(L) f(L, V) NoL dL (docs/LIGHTING.md L3), by Monte
// Carlo with multiple importance sampling (Veach 1997, power heuristic) of GGX half-vector,
// cosine and environment sampling, and with a coat GGX sampling of the coat's roughness; the model's f under an environment (environmentVisibility).
// The analytic lights are added exactly (no error) but sphere and tube lights, which are
// estimated too (area_lights.h). Deterministic for a seed.
ReferenceEstimate referenceRadiance(BrdfModelId model, const shader::SurfaceMaterial& material,
                                    const ReferenceEnvironment& environment,
                                    const std::vector<shader::PackedLight>& lights, glm::vec3 P, glm::vec3 N,
                                    glm::vec3 V, const ReferenceOptions& options);

}  // namespace patina
