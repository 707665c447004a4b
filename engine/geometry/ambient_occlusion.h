#pragma once
// Ambient occlusion by rays: the share of the hemisphere about a surface point's normal, weighted
// by the cosine, that no triangle blocks. Under a uniform sky of radiance L a Lambert surface of
// albedo a reflects a L times it (what the ground truth with visibility gives exactly), so it is
// the environment's visibility as diffuse light sees it. scene/ambient_occlusion.h bakes it per
// vertex for a model and its ground.
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geometry/ray_caster.h"

namespace patina {

// A unit vector about unit N distributed as cos(theta) / pi (Malley's method: a uniform point
// of the unit disc, u.x its squared radius and u.y its turn, lifted onto the hemisphere).
glm::vec3 sampleCosine(glm::vec2 u, glm::vec3 N);

struct OcclusionRays {
    // Rays a point, cosine-distributed over a side x side stratified grid (64 by default).
    int side = 8;
    // How far a ray looks for a blocker; infinity: the whole ray, as the ground truth looks.
    float reach = std::numeric_limits<float>::infinity();
};

// The cosine-weighted unoccluded share of the hemisphere about N at P, in [0, 1]: the share of
// `rays` stratified rays (jittered within their strata by `seed`, so neighbouring points do
// not share one pattern) that reach `reach` unblocked.
float unoccludedShare(const RayCaster& occluders, glm::vec3 P, glm::vec3 N, const OcclusionRays& rays, uint32_t seed);

// unoccludedShare at each point (normals beside positions), on every core; the point's index
// seeds its jitter, so the result does not depend on the threads.
std::vector<float> unoccludedShares(const RayCaster& occluders, const std::vector<glm::vec3>& positions,
                                    const std::vector<glm::vec3>& normals, const OcclusionRays& rays);

}  // namespace patina
