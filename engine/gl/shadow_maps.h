#pragma once
// Shadow maps (docs/LIGHTING.md "Shadows"): for each enabled light with `shadows` on, the depth
// of the model's opaque items seen from the light, one layer each of a depth texture array that
// shade.frag reads with PCF (PATINA_SHADOWS). A directional light looks along its direction
// with an orthographic view fitted to the model's bounding sphere; a point, sphere or tube light
// looks from its centre at the sphere with the narrowest perspective that holds it, or, inside
// the sphere, every way: six layers, a cube map's faces. The maps
// are fitted to the casters only: the ground casts nothing, and a receiver outside the view (or
// beyond its far plane, whose depth clamps to 1) is one no caster can shadow from there.
#include <optional>
#include <vector>

#include <epoxy/gl.h>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/shadow_settings.h"
#include "shading/shading.h"

namespace patina {

// Layers at most (shade.frag's MAX_SHADOW_MAPS), and shadowed lights at most: a fifth shadowed
// light, or one whose views the layers left cannot hold, casts none.
inline constexpr int kMaxShadowMaps = 12;
inline constexpr int kMaxShadowedLights = 4;

// One light's view of the casters.
struct ShadowView {
    glm::mat4 clip{1.0f};      // world to the light's clip space (drawing the map)
    glm::mat4 texture{1.0f};   // world to the map's [0, 1] coordinates and depth (reading it)
    // uShadowTexels' row: x the normal offset's scale (a texel's world size at clip w = 1
    // times the bias scale), y 1 / the map's size, z the PCF taps' spacing in texels (1).
    glm::vec4 texel{0.0f};
    // uShadowSources' row, PCSS's light size: a sphere's or tube's extent across the map's view
    // in texels at view depth 1 (its world size over a texel's at w = 1): xy its half-extent
    // along its longest axis in the map, z across it. Zero (a point or directional light): the
    // fixed 3 x 3 filter.
    glm::vec4 source{0.0f};
    glm::vec2 range{0.0f};   // uShadowRanges' row: the view's near and far depths (perspective)
};

// The views of a sphere (centre, radius) around the casters from `light` (packed), maps of
// `maps.size` texels square, their normal offset scaled by `maps.biasScale`: one for a
// directional light, or a point, sphere or tube light outside the sphere; six for one inside it,
// a cube map's faces in shade.frag's cubeFace order (+X, -X, +Y, -Y, +Z, -Z), each a view a
// little wider than 90 degrees from the light reaching the sphere's far side (Williams 1978's depth map, taken six ways
// as Gerasimov 2004, "Omnidirectional Shadow Mapping", GPU Gems ch. 12); none for a hemisphere
// light or an empty sphere.
std::vector<ShadowView> shadowViewsOf(const shader::PackedLight& light, glm::vec3 centre, float radius,
                                      const ShadowMapSettings& maps);

// The depth texture array and the framebuffer that draws into it, made on first use and kept.
class ShadowMaps {
public:
    ShadowMaps() = default;
    ~ShadowMaps();
    ShadowMaps(const ShadowMaps&) = delete;
    ShadowMaps& operator=(const ShadowMaps&) = delete;

    // Makes room for `layers` maps (at least 1) of `size` texels square and binds the
    // framebuffer to draw layer `layer`, cleared to the far depth, with the viewport the map's.
    void beginLayer(int layers, int layer, int size);
    GLuint texture() const { return texture_; }
    // A sampler object that reads the same texture's raw depths, without the comparison
    // (nearest, the same border): PCSS's blocker search. Made on first use.
    GLuint depthSampler();

private:
    GLuint texture_ = 0, framebuffer_ = 0, depthSampler_ = 0;
    int layers_ = 0, size_ = 0;
};

}  // namespace patina
