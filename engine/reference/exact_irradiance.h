#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "common/hdr_image.h"

namespace patina {

// The diffuse ground truth without noise: the irradiance E(n) = integral of Env(l) max(n.l, 0) dl
// summed over every pixel of the full-resolution equirect image, each pixel counted by its own
// moment (environment/irradiance.h's pixelMoment) as max(n.M_p, 0) L_p. That is exact for each
// pixel wholly above n's horizon; the few a horizon cuts are off by at most their part below
// it, for a 1024 x 512 image a few parts in 10^6 of E. What it measures the product's
// irradiance map against, and the Monte Carlo estimate's own bias (docs/LIGHTING.md).
class ExactIrradiance {
public:
    explicit ExactIrradiance(const HdrImage& equirect);
    glm::dvec3 at(glm::vec3 n) const;

private:
    struct Pixel {
        glm::vec3 moment;
        glm::vec3 radiance;
    };
    std::vector<Pixel> pixels_;   // those with any radiance
};

}  // namespace patina
