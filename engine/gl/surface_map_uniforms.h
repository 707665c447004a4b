#pragma once
// What one draw item sets of shaders/stages/surface_maps.glsl (PATINA_TEXTURED programs): its
// maps bound to their units with their samplers, and the uniforms that say which UV set and
// transform each reads and what the material's map factors are.
#include <array>

#include <epoxy/gl.h>

#include "gl/model_textures.h"
#include "gl/program.h"
#include "scene/prepared_scene.h"

namespace patina {

// The maps in surface_maps.glsl's order; each on texture unit firstUnit + its index.
enum class SurfaceMap {
    BaseColor, MetallicRoughness, Normal, Occlusion, Emissive,
    Clearcoat, ClearcoatRoughness, ClearcoatNormal,   // KHR_materials_clearcoat's
    SheenColor, SheenRoughness,                       // KHR_materials_sheen's
    Transmission, Thickness                           // KHR_materials_transmission's, _volume's
};
inline constexpr int kSurfaceMapCount = kMapCount;   // model/model.h's mapsOf order

// Looked up once per program (a model may have thousands of items); a program without the maps
// (or the depth pre-pass, which reads only the base colour's alpha) ignores what it lacks.
class SurfaceMapUniforms {
public:
    // Points the program's samplers at units firstUnit, firstUnit + 1, ... (program in use).
    SurfaceMapUniforms(const GlProgram& program, int firstUnit);
    // `draw`'s maps (none for an item without maps: its factors alone, no emission), their
    // images from `textures` (a map whose image is not there reads as absent).
    void set(const SceneDraw& draw, ModelTextures& textures) const;

private:
    int firstUnit_;
    GLint placement_, rotationSet_, baseAlpha_, alphaCutoff_, normalScale_, occlusionStrength_, emissive_,
        clearcoatNormalScale_;
};

}  // namespace patina
