#include "shading/brdf_slice.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include "shading/brdf_models.h"
#include "shading/layered_brdf.h"
#include "shading/cpu_shading.h"
#include "shading/shading.h"

namespace patina {

DirectionPair halfDifferenceDirections(float thetaH, float thetaD, float phiD) {
    // The difference vector in H's frame, then turned by theta_h about y into N's
    // (Rusinkiewicz 1998, section 3.1: rotate by -phi_h about N, then -theta_h about the binormal).
    const glm::vec3 d(std::sin(thetaD) * std::cos(phiD), std::sin(thetaD) * std::sin(phiD), std::cos(thetaD));
    const float c = std::cos(thetaH), s = std::sin(thetaH);
    const glm::vec3 L(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
    const glm::vec3 H(s, 0.0f, c);
    return {L, 2.0f * glm::dot(H, L) * H - L};
}

glm::vec2 sliceAngles(int x, int y, int size) {
    return {90.0f * (float(x) + 0.5f) / float(size), 90.0f * (float(size - 1 - y) + 0.5f) / float(size)};
}

glm::vec3 sliceShown(glm::vec3 value, float exposureStops, bool logScale) {
    glm::vec3 shown(0.0f);
    for (int c = 0; c < 3; ++c) {
        if (!(value[c] >= 0.0f)) {
            continue;   // below the horizon
        }
        const float v = value[c] * std::exp2(exposureStops);
        const float fraction = logScale ? (std::log10(std::max(v, 1e-12f)) + 2.0f) / 4.0f : v;
        shown[c] = shader::srgbEncode(std::clamp(fraction, 0.0f, 1.0f));
    }
    return shown;
}

BrdfSlice brdfSlice(const MaterialParameters& material, float phiDDegrees, int size, SliceLobe lobe) {
    const shader::SurfaceMaterial surface = surfaceMaterial(material);
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    BrdfSlice slice{size, std::vector<glm::vec3>(size_t(size) * size_t(size), glm::vec3(-1.0f))};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const glm::vec2 angles = glm::radians(sliceAngles(x, y, size));
            const DirectionPair pair = halfDifferenceDirections(angles.x, angles.y, glm::radians(phiDDegrees));
            if (pair.L.z <= 0.0f || pair.V.z <= 0.0f) {
                continue;   // no light arrives from below the surface, none leaves below it
            }
            const glm::vec3 V = glm::normalize(pair.V), L = glm::normalize(pair.L);
            const shader::BrdfValue f = evaluateBrdf(material.model, surface, N, V, L);
            // A clear coat's or a sheen's own terms belong to the specular and total slices; the
            // base's lobes are what gets through them (layered_brdf.h).
            const BrdfLayers layers = brdfLayers(material, N, V);
            const glm::vec3 diffuse = layeredBrdf(f.diffuse, layers, N, V, L, false);
            const glm::vec3 specular = layeredBrdf(f.specular, layers, N, V, L);
            slice.values[size_t(y) * size_t(size) + size_t(x)] =
                lobe == SliceLobe::Diffuse ? diffuse : lobe == SliceLobe::Specular ? specular : diffuse + specular;
        }
    }
    return slice;
}

}  // namespace patina
