#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/probe.h"

namespace patina {

class RayCaster;

// The ground truth of probeOnCpu's rows (scene/probe.h), by referenceRadiance (radiance.h): the
// lights exactly, the environment by Monte Carlo with `samples` iterations a row, each row with
// its own seed, on every core. value and standard error per row. Estimates with another `pass` draw other
// random numbers: independent, so a progressive render averages them.
struct ReferenceRow {
    glm::vec3 value;
    glm::vec3 standardError;
};
std::vector<ReferenceRow> probeReference(const MaterialParameters& material, const std::vector<Light>& lights,
                                         const std::vector<ProbeSample>& samples,
                                         const std::shared_ptr<const Environment>& environment, int samplesPerRow,
                                         uint64_t pass = 0);
// The same with each row's own material: samples[i] shaded with materials[materialOfSample[i]]
// (the same seeds as above, so one material gives the same rows), and where `occlusion` is not
// empty, its environment and hemisphere light scaled by occlusion[i] (ReferenceOptions), and
// with `occluders`, the light each row's point cannot see left out (ReferenceOptions::occluders).
// `tangents`, where not empty, is each row's world tangent (w the bitangent's sign; 0: none, the
// fallback's), which KHR_materials_anisotropy's direction turns from, as shade.frag's does.
std::vector<ReferenceRow> probeReference(const std::vector<MaterialParameters>& materials,
                                         const std::vector<int32_t>& materialOfSample,
                                         const std::vector<Light>& lights, const std::vector<ProbeSample>& samples,
                                         const std::shared_ptr<const Environment>& environment, int samplesPerRow,
                                         uint64_t pass = 0, const std::vector<float>& occlusion = {},
                                         const RayCaster* occluders = nullptr,
                                         const std::vector<glm::vec4>& tangents = {});

}  // namespace patina
