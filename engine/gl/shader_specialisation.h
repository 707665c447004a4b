#pragma once
// What a shader specialised to one scene compiles (shaders/stages/shade.frag, PATINA_SPECIALISED):
// exactly the scene's enabled lights, in order, each with only its type's code; no attenuation
// window for a point, sphere or tube light of range <= 0, and constant coefficients for one with
// KARIS_ATTENUATION; no diffuse term (and no hemisphere light, which is
// diffuse only) for a material whose c_diff is exactly 0. Values the artist drags (positions,
// colours, material parameters) stay uniforms, so only a change of this key recompiles.
//
// The first `flatSlots` lights reach the fragment shader as flat inputs written by mesh.vert
// (FLAT(i)) rather than from the uniform block (BLOCK(i)): with a light count fixed at compile
// time the fragment shader needs no indexing, and on llvmpipe a flat input costs one load per
// block of pixels where a uniform costs a gather per lane (docs/PERFORMANCE.md).
#include <compare>
#include <string>
#include <vector>

#include "shading/material_parameters.h"
#include "shading/shading.h"

namespace patina {

struct ShaderSpecialisation {
    std::string lights;       // PATINA_LIGHTS: "SHADE_POINT(FLAT(0), true, true) SHADE_DIRECTIONAL(FLAT(1)) ..."
    std::string flatLightRows;   // PATINA_FLAT_LIGHTS, for mesh.vert: "FLAT_POINT(0) FLAT_DIRECTIONAL(1) ..."
    int flatLightCount = 0;   // lights 0 to flatLightCount - 1 are flat inputs
    bool noDiffuse = false;
    bool environment = false;   // PATINA_ENVIRONMENT: the scene's environment after the lights
    // PATINA_MAP_SET (a textured program's): the maps the item drawn has (mapSetOf); the code of
    // every other map is left out. -1: whichever maps the uniforms say.
    int mapSet = -1;
    // PATINA_SHADOWS: a light of the list has a shadow map (PackedLight::shadowMap, set by the
    // renderer), and its entry weighs it by its map (SHADOWED).
    bool shadows = false;

    auto operator<=>(const ShaderSpecialisation&) const = default;
    std::vector<std::string> defines() const;
};

// Whether `material`'s diffuse colour, c_diff, is exactly 0: the same fp32 product as
// deriveSurfaceMaterial, so "exactly 0" means what the shader sees.
bool hasNoDiffuse(const MaterialParameters& material);

// Whether `material` has a clear coat to draw (KHR_materials_clearcoat's factor above 0): the
// items whose programs compile the coat in (PATINA_CLEARCOAT).
inline bool hasClearcoat(const MaterialParameters& material) { return material.clearcoat > 0.0f; }

// Whether `material` has a sheen to draw (KHR_materials_sheen's colour above 0 in a channel):
// the items whose programs compile the sheen in (PATINA_SHEEN).
inline bool hasSheen(const MaterialParameters& material) {
    return material.sheenColor.r > 0.0f || material.sheenColor.g > 0.0f || material.sheenColor.b > 0.0f;
}

// Whether `material` passes light through (KHR_materials_transmission's factor above 0): the
// items whose programs compile the transmission and the volume in (PATINA_TRANSMISSION).
inline bool hasTransmission(const MaterialParameters& material) { return material.transmission > 0.0f; }

// Whether `material`'s specular lobe is stretched (KHR_materials_anisotropy's strength above 0):
// the items whose programs compile the anisotropic terms in (PATINA_ANISOTROPY).
inline bool hasAnisotropy(const MaterialParameters& material) { return material.anisotropyStrength > 0.0f; }

// Whether `material`'s dielectric F0 is tinted or its Fresnel weighted (KHR_materials_specular's
// colour or factor, or an ior whose F0 passes 0.08): the items whose programs compile
// withSpecular in (PATINA_SPECULAR).
inline bool hasSpecularTint(const MaterialParameters& material) {
    return material.specularTint != glm::vec3(1.0f) || material.specularWeight != 1.0f;
}

// Whether `material` has a thin film to draw (KHR_materials_iridescence's strength above 0, and a
// thickness above 0 somewhere in its range): the items whose programs compile it in
// (PATINA_IRIDESCENCE).
inline bool hasIridescence(const MaterialParameters& material) {
    return material.iridescence > 0.0f &&
           (material.iridescenceThicknessMaximum > 0.0f || material.iridescenceThicknessMinimum > 0.0f);
}

// `lights` as packEnabledLights gives them (the uniform block's order); `noDiffuse` when every
// material drawn has none (hasNoDiffuse). `flatSlots`: how many lights the vertex stage can
// hand on as flat inputs (flatLightSlots, engine/gl/renderer.h).
ShaderSpecialisation specialiseFor(const std::vector<shader::PackedLight>& lights, bool noDiffuse, size_t flatSlots);
// For one material.
inline ShaderSpecialisation specialiseFor(const std::vector<shader::PackedLight>& lights,
                                          const MaterialParameters& material, size_t flatSlots) {
    return specialiseFor(lights, hasNoDiffuse(material), flatSlots);
}

// Whether handing lights on as flat inputs pays for a draw: it costs the vertex stage per
// triangle drawn (each vertex writes two more outputs a light, each triangle sets them up) and
// saves the fragment stage a gather per scalar per 8 fragments. On llvmpipe flat won every case
// measured down to 9 pixels a triangle drawn (1080p with MSAA strips, the 512x512 sheet cell,
// 100k triangles at 1080p) and lost only at 1.1 without MSAA (1M triangles at 1080p: 179
// against 143 ms; docs/PERFORMANCE.md). `pixels`: those the mesh can cover; `trianglesDrawn`:
// the mesh's triangles times the draws (MSAA strips) that cover it.
constexpr double kFlatLightPixelsPerTriangle = 4.0;
bool flatLightsPay(double pixels, double trianglesDrawn);

// The pieces of a key, for a caller writing light code of its own (bench/'s BRDF-only floor):
// where light i comes from in the fragment shader ("FLAT(i)" or "BLOCK(i)") and its entry in
// mesh.vert's list (`flatWrite`(i), for a flat one), and adding light i's fragment code.
struct LightSource {
    std::string fragment, vertex;
};
LightSource sourceOf(size_t i, size_t flatSlots, const char* flatWrite);
void addLight(ShaderSpecialisation& key, size_t i, const std::string& code, const LightSource& source);

}  // namespace patina
