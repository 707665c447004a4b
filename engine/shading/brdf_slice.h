#pragma once
// BRDF Explorer's image slice (Burley 2012, "Physically-Based Shading at Disney", section 3 and
// figure 3): the BRDF over the half and difference angles of Rusinkiewicz's parameterisation
// (Rusinkiewicz 1998, "A New Change of Variables for Efficient BRDF Representation"), theta_h
// across and theta_d up, at one phi_d. The specular peak runs up the left edge (theta_h = 0),
// Fresnel brightens the top (theta_d towards 90), retro-reflection shows at the bottom right.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shading/material_parameters.h"

namespace patina {

// L and V of (theta_h, theta_d, phi_d), radians, about N = (0, 0, 1): H at theta_h in the x-z
// plane (phi_h = 0, the BRDF being isotropic), L at (theta_d, phi_d) about H, V its mirror
// image through H.
struct DirectionPair {
    glm::vec3 L, V;
};
DirectionPair halfDifferenceDirections(float thetaH, float thetaD, float phiD);

// Total: the light above, reflected (the layers' own terms in Specular and Total). Transmitted:
// a thin wall's KHR_materials_transmission BTDF (lobe.h's LobeValue::transmitted) from L towards
// V mirrored below the surface, so that theta_h is that of the mirrored direction's half vector:
// the BTDF being glTF's reflection lobe mirrored (docs/SHADING.md S7), its D(theta_h) runs up the
// left edge as the reflection's does and (1 - F(theta_d)) darkens the top where F brightens it;
// 0 without a transmission.
enum class SliceLobe { Total, Diffuse, Specular, Transmitted };

// f at each pixel centre of a size x size slice, row 0 at the top (theta_d near 90 degrees),
// column 0 at theta_h near 0; 1/sr, no cosine. Where L or V is below the horizon, -1 (no value:
// the display leaves it dark).
struct BrdfSlice {
    int size = 0;
    std::vector<glm::vec3> values;
    glm::vec3 at(int x, int y) const { return values[size_t(y) * size_t(size) + size_t(x)]; }
};
BrdfSlice brdfSlice(const MaterialParameters& material, float phiDDegrees, int size, SliceLobe lobe);

// A slice value (1/sr) as shown, sRGB in [0, 1]: times 2^exposure, then linear (clamped at 1)
// or in log scale four decades, 0.01 to 100 1/sr, so a Lambert lobe (c / pi) and a sharp
// specular peak both read; no value (below the horizon, -1) is 0.
glm::vec3 sliceShown(glm::vec3 value, float exposureStops, bool logScale);

// The angles at pixel (x, y)'s centre, degrees: (theta_h, theta_d).
glm::vec2 sliceAngles(int x, int y, int size);

}  // namespace patina
