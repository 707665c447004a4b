#include "shading_programs.h"

#include <epoxy/gl.h>

#include "../brdf_models.h"
#include "../energy_table.h"
#include "shading_inputs.h"

namespace patina {

namespace shader_sources {
extern const char* const mesh_vert;
extern const char* const probe_vert;
}  // namespace shader_sources

namespace {
// Texture unit of uEnergyTable; unit 0 stays free for the display pass.
constexpr int kEnergyUnit = 1;
}  // namespace

ShadingPrograms::~ShadingPrograms() {
    for (const auto& [model, texture] : energyTextures_) {
        glDeleteTextures(1, &texture);
    }
}

const GlProgram& ShadingPrograms::use(BrdfModelId model, Use use) {
    std::unique_ptr<GlProgram>& program = programs_[{model, use}];
    if (!program) {
        std::vector<std::string> defines = brdfModelDefines(model);
        if (use != Use::MultiPass) {
            defines.push_back("PATINA_SINGLE_PASS");
        }
        if (use == Use::Probe) {
            defines.push_back("PATINA_PROBE");
        }
        program = std::make_unique<GlProgram>(
            std::vector<const char*>{use == Use::Probe ? shader_sources::probe_vert : shader_sources::mesh_vert},
            shadingFragmentParts(), defines);
        LightBuffer::attach(*program);
    }
    program->use();
    if (brdfModel(model).multipleScattering()) {
        glActiveTexture(GL_TEXTURE0 + kEnergyUnit);
        glBindTexture(GL_TEXTURE_2D, energyTexture(model));
        glActiveTexture(GL_TEXTURE0);
    }
    glUniform1i(program->uniform("uEnergyTable"), kEnergyUnit);
    return *program;
}

unsigned ShadingPrograms::energyTexture(BrdfModelId model) {
    unsigned& texture = energyTextures_[model];
    if (!texture) {
        const std::vector<float>& table = energyTable(model);
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, kEnergyTableSize, kEnergyTableSize, 0, GL_RED, GL_FLOAT,
                     table.data());
        // texelFetch only: shaders/energy_table.glsl interpolates itself.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    return texture;
}

}  // namespace patina
