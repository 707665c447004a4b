#pragma once
#include <optional>
#include <vector>

#include <epoxy/gl.h>

#include "environment/environment.h"
#include "scene/light.h"
#include "scene/prepared_scene.h"
#include "shading/material_parameters.h"
#include "shading/shading.h"
#include "gl/program.h"
#include "gl/surface_map_uniforms.h"

namespace patina {

// Embedded GLSL parts of every program that shades: the terms, the lights, the energy table,
// the model dispatch (its PATINA_* defines select the model), image-based lighting, the display
// transform and shade.frag; with `channels`, the inspector's channels (PATINA_CHANNEL) too.
std::vector<const char*> shadingFragmentParts(bool channels = false);

// The LightBlock uniform buffer of shaders/stages/shade.frag: MAX_LIGHTS packed lights and a count.
class LightBuffer {
public:
    static constexpr GLuint kBindingPoint = 0;

    LightBuffer();
    ~LightBuffer();
    LightBuffer(const LightBuffer&) = delete;
    LightBuffer& operator=(const LightBuffer&) = delete;

    // Throws std::runtime_error past MAX_LIGHTS lights.
    void upload(const std::vector<shader::PackedLight>& lights);
    void bind() const;
    // Points the program's LightBlock at kBindingPoint.
    static void attach(const GlProgram& program);

private:
    GLuint buffer_ = 0;
};

// uBaseColor, uRoughness, uSpecular, uMetallic of shade.frag, looked up once.
class MaterialUniforms {
public:
    explicit MaterialUniforms(const GlProgram& program);
    void set(const MaterialParameters& material) const;   // its program in use

private:
    GLint baseColor_, roughness_, specular_, metallic_, clearcoat_, clearcoatRoughness_, sheenColor_,
        sheenRoughness_, transmission_, thickness_, attenuationColor_, attenuationDistance_, anisotropyStrength_,
        anisotropyDirection_, specularTint_, specularWeight_, iridescence_, iridescenceIor_, iridescenceThickness_;
};
// The same, for one draw (program must be in use).
void setMaterialUniforms(const GlProgram& program, const MaterialParameters& material);

// What one draw item sets of mesh.vert and shade.frag (uModel, uNormalMatrix, the material,
// uReverseBackNormals), looked up once per program: a model may have thousands of items. A
// program without some of them (the depth pre-pass's) ignores those.
// With `textures`, a textured program's maps too (surface_map_uniforms.h; `program` in use
// when made, as it points the samplers at their units).
class DrawUniforms {
public:
    explicit DrawUniforms(const GlProgram& program, ModelTextures* textures = nullptr);
    void set(const SceneDraw& draw) const;   // its program in use

private:
    GLint model_, normalMatrix_, reverseBackNormals_, channelAlpha_, thicknessScale_;
    MaterialUniforms material_;
    ModelTextures* textures_;
    std::optional<SurfaceMapUniforms> maps_;
};
// environment.glsl's uniforms for `light` (an environment light) showing `environment`, its
// cube map on `unit` (program must be in use).
void setEnvironmentUniforms(const GlProgram& program, const Environment& environment, const Light& light, int unit);

}  // namespace patina
