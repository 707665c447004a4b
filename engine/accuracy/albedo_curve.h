#pragma once
// BRDF Explorer's albedo view for one material: the directional albedo
// E(theta_v) = integral over the hemisphere of f(L, V) NoL dL (the white furnace: an environment
// of radiance 1 everywhere), as the product computes it, by the split sum's tables
// (environment BRDF and irradiance, ibl_model.glsl), against the ground truth's Monte Carlo
// estimate of the same integral (reference/radiance.h) with its standard error.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "image/chart.h"
#include "shading/material_parameters.h"

namespace patina {

// With KHR_materials_transmission the furnace's light reaches V through the wall too: `product`
// and `truth` are then the reflected plus the transmitted albedo (the light towards V under a
// white environment all around), and the `transmitted` fields that share alone (0 without).
struct AlbedoPoint {
    float thetaVDegrees = 0.0f;
    glm::vec3 product{0.0f};        // the split sum under the white furnace
    glm::vec3 truth{0.0f};          // the exact integral, estimated
    glm::vec3 standardError{0.0f};  // of `truth`
    glm::vec3 productTransmitted{0.0f};   // of `product`, through the wall (transmission.glsl)
    glm::vec3 truthTransmitted{0.0f};     // of `truth`, through the wall (the BTDF sampled)
};

// `points` angles from 0 to 88.5 degrees (where NoV stays clear of the floor 1e-4), the truth
// by `samples` MIS iterations at each (deterministic).
std::vector<AlbedoPoint> albedoCurve(const MaterialParameters& material, int points, int samples);
// One angle of it, the truth's random numbers from `seed`.
AlbedoPoint albedoAt(const MaterialParameters& material, float thetaVDegrees, int samples, uint64_t seed);

// The curves of named materials on one chart, as luminance: each material's split sum as a
// line, its ground truth as markers with one standard error's bars (the luminance of the
// channels' errors, which bounds the luminance's own).
Chart albedoChart(const std::vector<std::pair<std::string, std::vector<AlbedoPoint>>>& curves);

}  // namespace patina
