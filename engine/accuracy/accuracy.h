#pragma once
// How wrong each BRDF model is: against itself in double (implementation accuracy) and against
// "reference" in double (physical accuracy), over a fixed, seeded, stratified sample set.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "shading/brdf_models.h"
#include "scene/probe.h"

namespace patina {

// One configuration: a material (r, m, s; base colour fixed) and N, V, L with NoV, NoL >= 0.01.
struct AccuracySample {
    Material material;
    glm::dvec3 N, V, L;
};

// `materials` material strata (roughness x metallic x specular, jittered) times `perMaterial`
// angle samples (theta_v, theta_l, phi by Latin hypercube). Directional light along +z: L is the
// same in every sample, N and V vary, so a GPU draw can hold one material's samples.
struct AccuracySet {
    std::vector<AccuracySample> samples;
    std::vector<size_t> materialStart;   // index of each material's first sample, plus the end
};
AccuracySet stratifiedAccuracySet(int roughnessStrata, int metallicStrata, int specularStrata, int perMaterial,
                                  uint32_t seed);

// Relative RMSE (sqrt(sum (a - b)^2 / sum b^2)) and max relative error (|a - b| / b where
// b > 1e-4) of f * NoL, all three channels.
struct ErrorStats {
    double relativeRmse = 0.0;
    double maxRelative = 0.0;
};
class ErrorAccumulator {
public:
    void add(glm::dvec3 value, glm::dvec3 expected);
    ErrorStats stats() const;

private:
    double squaredError_ = 0.0, squaredExpected_ = 0.0, maxRelative_ = 0.0;
};

// f * NoL of `model` in double, and the fp32 CPU evaluation of the same configuration.
glm::dvec3 reflectedF64(BrdfModelId model, const AccuracySample& sample);
glm::dvec3 reflectedF32(BrdfModelId model, const AccuracySample& sample);

ErrorStats cpuImplementationError(BrdfModelId model, const AccuracySet& set);   // fp32 vs fp64
ErrorStats physicalError(BrdfModelId model, const AccuracySet& set);             // fp64 vs reference fp64

// The GPU probe's version of a set: one probe batch per material, with a unit directional light
// along +z, so the radiance is f * NoL.
std::vector<ProbeSample> probeSamples(const AccuracySet& set, size_t material);
Light accuracyLight();

}  // namespace patina
