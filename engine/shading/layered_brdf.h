#pragma once
// KHR_materials_clearcoat and KHR_materials_sheen over a base BRDF for one direction pair, as
// the lobe views draw them and the ground truth integrates them: the sheen over the base
// (sheen.glsl), the coat over that (clearcoat.glsl), the order shade.frag layers them in.
#include <glm/vec3.hpp>

#include "shading/material_parameters.h"
#include "shading/shading.h"

namespace patina {

// A material's layers at one shading point, derived once for (N, V): each absent where its
// factor is 0 (docs/SHADING.md S5, S6).
struct BrdfLayers {
    bool coated = false;
    bool sheened = false;
    shader::Clearcoat coat;
    shader::Sheen sheen;
};
BrdfLayers brdfLayers(float clearcoat, float clearcoatRoughness, glm::vec3 sheenColor, float sheenRoughness,
                      glm::vec3 N, glm::vec3 V);
inline BrdfLayers brdfLayers(const MaterialParameters& material, glm::vec3 N, glm::vec3 V) {
    return brdfLayers(material.clearcoat, material.clearcoatRoughness, material.sheenColor, material.sheenRoughness,
                      N, V);
}

// The BRDF towards unit L (the layers' normal N) of `lobes` (the base's, any of its lobes) under
// the layers: the sheen's f_base sheenAlbedoScaling(N.V, N.L) + f_sheen, then the coat's
// (1 - clearcoat fr_c) + its own term. `ownLobes` false leaves the layers' own terms out and
// keeps what they take from the base: the base's share alone (linear in `lobes`, so each lobe
// may be weighed apart). Without layers, `lobes`.
glm::vec3 layeredBrdf(glm::vec3 lobes, const BrdfLayers& layers, glm::vec3 N, glm::vec3 V, glm::vec3 L,
                      bool ownLobes = true);

// KHR_materials_transmission's light through a thin wall, `transmitted`, as it leaves the layers
// above it towards V (the layers derived for N, V): weighed by the sheen's albedo scaling towards
// V (sheen.glsl's sheenViewWeight; the light arrives from behind, where N.L has no E of its own),
// then covered by the coat as the base is (clearcoat.glsl's clearcoatOver, no light of its own
// from behind): shade.frag's order (docs/SHADING.md S7). Without layers, `transmitted`.
glm::vec3 layeredTransmission(glm::vec3 transmitted, const BrdfLayers& layers);

}  // namespace patina
