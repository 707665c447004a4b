#include "gl/shading_inputs.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "gl/shading_programs.h"
#include "scene/light_packing.h"
#include "shading/environment_brdf.h"

namespace patina {

namespace shader_sources {
extern const char* const brdf_glsl;
extern const char* const environment_glsl;
extern const char* const ibl_glsl;
extern const char* const ibl_model_glsl;
extern const char* const channels_glsl;
extern const char* const channel_model_glsl;
extern const char* const lights_glsl;
extern const char* const clearcoat_glsl;
extern const char* const sheen_texel_glsl;
extern const char* const sheen_glsl;
extern const char* const transmission_glsl;
extern const char* const light_block_glsl;
extern const char* const energy_texel_glsl;
extern const char* const energy_table_glsl;
extern const char* const brdf_terms_glsl;
extern const char* const brdf_model_glsl;
extern const char* const iridescence_glsl;
extern const char* const display_glsl;
extern const char* const texture_glsl;
extern const char* const surface_maps_glsl;
extern const char* const shade_frag;
}  // namespace shader_sources

namespace {
// std140 of `PackedLight uLights[MAX_LIGHTS]; ivec4 uLightCount; ivec4 uAreaLightCount;`: vec4
// members pack tightly.
static_assert(sizeof(shader::PackedLight) == 7 * 16, "PackedLight must match std140");
constexpr size_t kLightArraySize = sizeof(shader::PackedLight) * shader::MAX_LIGHTS;
constexpr size_t kLightBlockSize = kLightArraySize + 2 * 16;
}  // namespace

std::vector<const char*> shadingFragmentParts(bool channels) {
    std::vector<const char*> parts{
        shader_sources::brdf_glsl,         shader_sources::iridescence_glsl,  shader_sources::environment_glsl,
        shader_sources::ibl_glsl,
        shader_sources::lights_glsl,       shader_sources::light_block_glsl,  shader_sources::clearcoat_glsl,
        shader_sources::sheen_texel_glsl,  shader_sources::sheen_glsl,       shader_sources::transmission_glsl,
        shader_sources::energy_texel_glsl,
        shader_sources::energy_table_glsl, shader_sources::brdf_terms_glsl,   shader_sources::brdf_model_glsl,
        shader_sources::ibl_model_glsl,    shader_sources::display_glsl,      shader_sources::texture_glsl,
        shader_sources::surface_maps_glsl, shader_sources::shade_frag};
    // The channels' parts only where asked for: every other program would compile them for nothing.
    if (channels) {
        // After display.glsl (channels.glsl encodes sRGB), before texture.glsl.
        parts.insert(parts.end() - 3, {shader_sources::channels_glsl, shader_sources::channel_model_glsl});
    }
    return parts;
}

LightBuffer::LightBuffer() {
    glGenBuffers(1, &buffer_);
    glBindBuffer(GL_UNIFORM_BUFFER, buffer_);
    glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(kLightBlockSize), nullptr, GL_DYNAMIC_DRAW);
}

LightBuffer::~LightBuffer() {
    glDeleteBuffers(1, &buffer_);
}

void LightBuffer::upload(const std::vector<shader::PackedLight>& lights) {
    if (lights.size() > size_t(shader::MAX_LIGHTS)) {
        throw std::runtime_error(std::to_string(lights.size()) + " enabled lights; the renderer holds " +
                                 std::to_string(shader::MAX_LIGHTS));
    }
    const glm::ivec4 counts = packedLightCounts(lights);
    const glm::ivec4 areaCounts = packedAreaLightCounts(lights);
    const GLint count[8] = {counts.x,     counts.y,     counts.z,     counts.w,
                            areaCounts.x, areaCounts.y, areaCounts.z, areaCounts.w};
    glBindBuffer(GL_UNIFORM_BUFFER, buffer_);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, GLsizeiptr(lights.size() * sizeof(shader::PackedLight)),
                    lights.data());
    glBufferSubData(GL_UNIFORM_BUFFER, GLintptr(kLightArraySize), sizeof count, count);
}

void LightBuffer::bind() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, kBindingPoint, buffer_);
}

void LightBuffer::attach(const GlProgram& program) {
    const GLuint index = glGetUniformBlockIndex(program.id(), "LightBlock");
    if (index != GL_INVALID_INDEX) {
        glUniformBlockBinding(program.id(), index, kBindingPoint);
    }
}

void setEnvironmentUniforms(const GlProgram& program, const Environment& environment, const Light& light, int unit) {
    const glm::vec2 rotation = environmentRotation(light.rotationDegrees);   // as the CPU turns it
    glUniform1i(program.uniform("uEnvironmentMap"), unit);
    glUniform1f(program.uniform("uEnvironmentMaxLod"), environment.maxLod());
    glUniform1f(program.uniform("uEnvironmentIntensity"), light.intensity);
    glUniform2f(program.uniform("uEnvironmentRotation"), rotation.x, rotation.y);
    glUniform1f(program.uniform("uEnvironmentSourceSize"), float(environment.prefiltered.front().size));
}

MaterialUniforms::MaterialUniforms(const GlProgram& program)
    : baseColor_(program.uniform("uBaseColor")), roughness_(program.uniform("uRoughness")),
      specular_(program.uniform("uSpecular")), metallic_(program.uniform("uMetallic")),
      clearcoat_(program.uniform("uClearcoat")), clearcoatRoughness_(program.uniform("uClearcoatRoughness")),
      sheenColor_(program.uniform("uSheenColor")), sheenRoughness_(program.uniform("uSheenRoughness")),
      transmission_(program.uniform("uTransmission")), thickness_(program.uniform("uThickness")),
      attenuationColor_(program.uniform("uAttenuationColor")),
      attenuationDistance_(program.uniform("uAttenuationDistance")),
      anisotropyStrength_(program.uniform("uAnisotropyStrength")),
      anisotropyDirection_(program.uniform("uAnisotropyDirection")),
      specularTint_(program.uniform("uSpecularTint")), specularWeight_(program.uniform("uSpecularWeight")),
      iridescence_(program.uniform("uIridescence")), iridescenceIor_(program.uniform("uIridescenceIor")),
      iridescenceThickness_(program.uniform("uIridescenceThickness")) {}

void MaterialUniforms::set(const MaterialParameters& material) const {
    glUniform3f(baseColor_, material.baseColor.x, material.baseColor.y, material.baseColor.z);
    glUniform1f(roughness_, material.roughness);
    glUniform1f(specular_, material.specular);
    glUniform1f(metallic_, material.metallic);
    if (clearcoat_ >= 0) {   // only a coated program has them (PATINA_CLEARCOAT)
        glUniform1f(clearcoat_, material.clearcoat);
        glUniform1f(clearcoatRoughness_, material.clearcoatRoughness);
    }
    if (sheenColor_ >= 0) {   // only a sheened program has them (PATINA_SHEEN)
        glUniform3f(sheenColor_, material.sheenColor.x, material.sheenColor.y, material.sheenColor.z);
        glUniform1f(sheenRoughness_, material.sheenRoughness);
    }
    if (transmission_ >= 0) {   // only a transmitting program has them (PATINA_TRANSMISSION)
        glUniform1f(transmission_, material.transmission);
        glUniform1f(thickness_, material.thickness);
        const glm::vec3& c = material.attenuationColor;
        glUniform3f(attenuationColor_, c.x, c.y, c.z);
        glUniform1f(attenuationDistance_, material.attenuationDistance);
    }
    if (anisotropyStrength_ >= 0) {   // only an anisotropic program has them (PATINA_ANISOTROPY)
        glUniform1f(anisotropyStrength_, material.anisotropyStrength);
        glUniform2f(anisotropyDirection_, std::cos(material.anisotropyRotation), std::sin(material.anisotropyRotation));
    }
    if (specularTint_ >= 0) {   // only a tinted program has them (PATINA_SPECULAR)
        const glm::vec3& tint = material.specularTint;
        glUniform3f(specularTint_, tint.x, tint.y, tint.z);
        glUniform1f(specularWeight_, material.specularWeight);
    }
    if (iridescence_ >= 0) {   // only an iridescent program has them (PATINA_IRIDESCENCE)
        glUniform1f(iridescence_, material.iridescence);
        glUniform1f(iridescenceIor_, material.iridescenceIor);
        glUniform2f(iridescenceThickness_, material.iridescenceThicknessMinimum, material.iridescenceThicknessMaximum);
    }
}

void setMaterialUniforms(const GlProgram& program, const MaterialParameters& material) {
    MaterialUniforms(program).set(material);
}

DrawUniforms::DrawUniforms(const GlProgram& program, ModelTextures* textures)
    : model_(program.uniform("uModel")), normalMatrix_(program.uniform("uNormalMatrix")),
      reverseBackNormals_(program.uniform("uReverseBackNormals")), channelAlpha_(program.uniform("uChannelAlpha")),
      thicknessScale_(program.uniform("uThicknessScale")),
      material_(program), textures_(textures) {
    if (textures_) {
        maps_.emplace(program, ShadingPrograms::kFirstMapUnit);
    }
}

void DrawUniforms::set(const SceneDraw& draw) const {
    glUniformMatrix4fv(model_, 1, GL_FALSE, glm::value_ptr(draw.transform));
    glUniformMatrix3fv(normalMatrix_, 1, GL_FALSE, glm::value_ptr(draw.normalTransform));
    glUniform1i(reverseBackNormals_, draw.reverseBackNormals ? 1 : 0);
    if (channelAlpha_ >= 0) {   // only a channel program without maps has it
        glUniform1f(channelAlpha_, draw.alpha);
    }
    if (thicknessScale_ >= 0) {   // PATINA_TRANSMISSION: the volume's thickness times the node's scale
        glUniform1f(thicknessScale_, thicknessScaleOf(draw.transform));
    }
    material_.set(draw.material);
    if (maps_) {
        maps_->set(draw, *textures_);
    }
}

}  // namespace patina
