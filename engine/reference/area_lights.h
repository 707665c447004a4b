#pragma once
// The ground truth of sphere and tube lights (docs/LIGHTING.md L4): the
// integral of Le f(L, V) NoL over the directions that reach the light, by Monte Carlo, against
// which Karis's representative point (shaders/shared/brdf_model.glsl) is measured.
//
// Radiance. A sphere of radius s radiates Le = I / (pi s^2), so that it gives the point light's
// I cos / d^2 while above the horizon (lighting.md); a tube, the capsule of radius s around a
// segment of length l, radiates the point light's power 4 pi I over its area 4 pi s^2 + 2 pi s l:
// Le = I / (pi s (s + l / 2)). The point light's falloff window and denominator are not physical;
// both sides take them as the point light does, at the distance t the approximation takes
// (the centre's for a sphere, lineIrradianceDistanceSquared's for a tube): Le is scaled by
// pointLightAttenuation(t) t^2, which is exactly 1 for attenuation (0, 0, 1) without a window.
#include <vector>

#include <glm/vec3.hpp>

#include "reference/radiance.h"

namespace patina {

// A packed sphere or tube light: estimated by areaLightReference rather than added exactly.
bool isAreaLight(const shader::PackedLight& light);

// Sum over the area lights of `lights` (the others are left out) of the outgoing radiance
// towards V, with its standard error. Spheres: uniform sampling of the cone the sphere subtends,
// cos theta_max = sqrt(1 - s^2 / d^2), pdf 1 / (2 pi (1 - cos theta_max)); inside the sphere,
// uniform sampling of its area. Tubes: uniform sampling of the capsule's area (a point facing
// away from an outside P is hidden: no light). Each combined by MIS (Veach 1997, power
// heuristic) with GGX half-vector sampling, whose ray counts where it hits the light: that keeps
// r -> 0 converging. `options.samples` iterations draw one direction from each strategy and
// each light; diffuse and specular as options says. The model's f under analytic lights.
ReferenceEstimate areaLightReference(BrdfModelId model, const shader::SurfaceMaterial& material,
                                     const std::vector<shader::PackedLight>& lights, glm::vec3 P, glm::vec3 N,
                                     glm::vec3 V, const ReferenceOptions& options);

// Le of the header's convention for a packed sphere or tube light seen from P.
glm::dvec3 areaLightRadiance(const shader::PackedLight& light, glm::vec3 P);

}  // namespace patina
