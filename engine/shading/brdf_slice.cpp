#include "shading/brdf_slice.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include "shading/lobe.h"
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
    BrdfSlice slice{size, std::vector<glm::vec3>(size_t(size) * size_t(size), glm::vec3(-1.0f))};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const glm::vec2 angles = glm::radians(sliceAngles(x, y, size));
            const DirectionPair pair = halfDifferenceDirections(angles.x, angles.y, glm::radians(phiDDegrees));
            if (pair.L.z <= 0.0f || pair.V.z <= 0.0f) {
                continue;   // no light arrives from below the surface, none leaves below it
            }
            // A clear coat's or a sheen's own terms belong to the specular and total slices; the
            // base's lobes are what gets through them, the diffuse what a transmission leaves of
            // it, the transmitted lobe the wall's towards V mirrored below (lobe.h).
            const LobeValue f = lobeValue(material, glm::normalize(pair.L), glm::normalize(pair.V));
            slice.values[size_t(y) * size_t(size) + size_t(x)] = lobe == SliceLobe::Diffuse     ? f.diffuse
                                                                 : lobe == SliceLobe::Specular  ? f.specular + f.layers
                                                                 : lobe == SliceLobe::Transmitted ? f.transmitted
                                                                                                  : f.total();
        }
    }
    return slice;
}

}  // namespace patina
