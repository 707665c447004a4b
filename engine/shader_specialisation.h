#pragma once
// What a shader specialised to one scene compiles (shaders/shade.frag, PATINA_SPECIALISED):
// exactly the scene's enabled lights, in order, each with only its type's code; no attenuation
// window for a point light of radius <= 0, and constant coefficients for one with
// KARIS_ATTENUATION; no diffuse term (and no hemisphere light, which is
// diffuse only) for a material whose c_diff is exactly 0. Values the artist drags (positions,
// colours, material parameters) stay uniforms, so only a change of this key recompiles.
#include <compare>
#include <string>
#include <vector>

#include "material.h"
#include "shading.h"

namespace patina {

struct ShaderSpecialisation {
    std::string lights;   // PATINA_LIGHTS: "SHADE_POINT(0, true, true) SHADE_DIRECTIONAL(1) ..."
    bool noDiffuse = false;

    auto operator<=>(const ShaderSpecialisation&) const = default;
    std::vector<std::string> defines() const;
};

// `lights` as packEnabledLights gives them (the uniform block's order).
ShaderSpecialisation specialiseFor(const std::vector<shader::PackedLight>& lights, const Material& material);

// The benchmark floor's key: BRDF_ONLY(i) for each of `count` lights (shade.frag).
ShaderSpecialisation brdfFloorFor(size_t count);

}  // namespace patina
