#include "geometry/ambient_occlusion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "common/parallel_for.h"

namespace patina {

glm::vec3 sampleCosine(glm::vec2 u, glm::vec3 N) {
    const float r = std::sqrt(u.x), phi = 2.0f * std::numbers::pi_v<float> * u.y;
    const glm::vec3 up = std::abs(N.z) < 0.999f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    const glm::vec3 tx = glm::normalize(glm::cross(up, N)), ty = glm::cross(N, tx);
    return tx * (r * std::cos(phi)) + ty * (r * std::sin(phi)) + N * std::sqrt(std::max(0.0f, 1.0f - u.x));
}

namespace {
// A well-mixed 32-bit value of `x` (the "lowbias32" integer hash, Wellons 2018), as a fraction.
float hashFraction(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return float(x >> 8) * (1.0f / 16777216.0f);
}
}  // namespace

float unoccludedShare(const RayCaster& occluders, glm::vec3 P, glm::vec3 N, const OcclusionRays& rays, uint32_t seed) {
    const int side = std::max(rays.side, 1);
    const glm::vec3 n = glm::length(N) > 0.0f ? glm::normalize(N) : glm::vec3(0.0f, 1.0f, 0.0f);
    // One jitter for the whole grid (Cranley-Patterson rotation), its own for each point.
    const glm::vec2 jitter(hashFraction(2u * seed), hashFraction(2u * seed + 1u));
    int open = 0;
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
            const glm::vec2 u = glm::fract((glm::vec2(float(x), float(y)) + jitter) / float(side));
            open += unoccluded(&occluders, P, n, sampleCosine(u, n), rays.reach) ? 1 : 0;
        }
    }
    return float(open) / float(side * side);
}

std::vector<float> unoccludedShares(const RayCaster& occluders, const std::vector<glm::vec3>& positions,
                                    const std::vector<glm::vec3>& normals, const OcclusionRays& rays) {
    std::vector<float> shares(positions.size(), 1.0f);
    parallelFor(positions.size(), [&](size_t i) {
        shares[i] = unoccludedShare(occluders, positions[i], i < normals.size() ? normals[i] : glm::vec3(0, 1, 0), rays,
                                    uint32_t(i));
    });
    return shares;
}

}  // namespace patina
