#pragma once
// A model's texture maps on the CPU: the twin of shaders/stages/surface_maps.glsl and of
// shade.frag's use of it, through the same shared functions (shaders/shared/texture.glsl), so
// the ground truth of a textured model shades what the GPU shades. Lookups are
// shading/texture_sampling.h's, on the same mip levels as the GPU's and at the level of detail
// texture.glsl computes from the UVs' change between neighbouring pixels, as the GPU's dFdx and
// dFdy give it.
#include <map>
#include <utility>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "model/model.h"
#include "scene/prepared_scene.h"
#include "shading/material_parameters.h"
#include "shading/texture.h"

namespace patina {

// Where a fragment of `draw` is, in its primitive's UVs and its interpolated world tangent.
struct MapCoordinates {
    glm::vec2 uv0{0.0f}, uv1{0.0f};
    glm::vec4 tangent{0.0f};   // w = 0: none
    glm::vec4 color{1.0f};     // the interpolated vertex colour (COLOR_0); 1 without
    // How each UV set changes to the next pixel centre along x and along y (the GPU's dFdx and
    // dFdy, up to sign): what the level of detail is read from. Zero: magnified, level 0.
    glm::vec2 uv0Dx{0.0f}, uv0Dy{0.0f}, uv1Dx{0.0f}, uv1Dy{0.0f};
};

// The images of `model`'s maps as linear texels with their mip levels, each decoded once in the
// colour space its maps read it in (sRGB for base colour and emissive): gl/model_textures.h's
// twin.
class MapTextures {
public:
    explicit MapTextures(const Model& model);
    // `slot`'s texel at the UV set it reads (uv0 or uv1) through its transform, at the level of
    // detail of that set's derivatives through it; `absent` where the slot has no map or its
    // image is not there.
    glm::vec4 texel(const TextureSlot& slot, bool srgb, const MapCoordinates& at, glm::vec4 absent) const;

private:
    std::map<std::pair<int, bool>, std::vector<LinearTexture>> textures_;   // (image, sRGB): its levels
};

// glTF 2.0 section 3.9.4: whether MASK keeps the fragment (alpha, the factor's times the base
// colour map's and the vertex colour's, at least the cutoff); always for OPAQUE and BLEND.
bool keptByMask(const SceneDraw& draw, const MapTextures& textures, const MapCoordinates& at);

// What the maps make of one point of a textured item (SceneDraw::maps).
struct MappedSurface {
    MaterialParameters material;   // the factors times the maps and the vertex colour (3.9.2)
    float alpha = 1.0f;            // the base colour factor's alpha times its map's and the colour's
    glm::vec3 normal;              // the normal map's, about the unit shading normal given (3.9.3)
    float occlusion = 1.0f;        // on the environment and hemisphere lights
    glm::vec3 emission{0.0f};      // linear radiance emitted
};
// `normal` is the unit shading normal (reversed on a back face where the material says so).
MappedSurface mappedSurface(const SceneDraw& draw, const MapTextures& textures, const MapCoordinates& at,
                            glm::vec3 normal);

}  // namespace patina
