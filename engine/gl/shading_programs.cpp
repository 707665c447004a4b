#include "shading_programs.h"

#include <algorithm>

#include <epoxy/gl.h>

#include "../brdf_models.h"
#include "../energy_table.h"
#include "../light_packing.h"
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

std::unique_ptr<GlProgram> ShadingPrograms::build(BrdfModelId model, Output output, const char* vertex,
                                                  std::vector<std::string> defines) {
    const std::vector<std::string> modelDefines = brdfModelDefines(model);
    defines.insert(defines.begin(), modelDefines.begin(), modelDefines.end());
    if (output == Output::LinearAndDisplay) {
        defines.push_back("PATINA_DISPLAY_OUTPUT");
    }
    auto program = std::make_unique<GlProgram>(std::vector<const char*>{vertex}, shadingFragmentParts(), defines);
    LightBuffer::attach(*program);
    return program;
}

const GlProgram& ShadingPrograms::bind(BrdfModelId model, const GlProgram& program) {
    program.use();
    if (brdfModel(model).multipleScattering()) {
        glActiveTexture(GL_TEXTURE0 + kEnergyUnit);
        glBindTexture(GL_TEXTURE_2D, energyTexture(model));
        glActiveTexture(GL_TEXTURE0);
    }
    glUniform1i(program.uniform("uEnergyTable"), kEnergyUnit);
    return program;
}

ShadingPrograms::Use ShadingPrograms::singlePassFor(const std::vector<shader::PackedLight>& lights) {
    const bool karis = std::all_of(lights.begin(), lights.end(), [](const shader::PackedLight& light) {
        return light.type != shader::LIGHT_POINT || hasKarisAttenuation(light);
    });
    return karis ? Use::SinglePassKarisPoints : Use::SinglePass;
}

const GlProgram& ShadingPrograms::use(BrdfModelId model, Use use, Output output) {
    std::unique_ptr<GlProgram>& program = programs_[{model, use, output}];
    if (!program) {
        std::vector<std::string> defines;
        if (use != Use::MultiPass) {
            defines.push_back("PATINA_SINGLE_PASS");
        }
        if (use == Use::SinglePassKarisPoints) {
            defines.push_back("PATINA_KARIS_POINTS");
        }
        if (use == Use::Probe) {
            defines.push_back("PATINA_PROBE");
        }
        program = build(model, output, use == Use::Probe ? shader_sources::probe_vert : shader_sources::mesh_vert,
                        defines);
    }
    return bind(model, *program);
}

const GlProgram& ShadingPrograms::useSpecialised(BrdfModelId model, const ShaderSpecialisation& key,
                                                 Output output) {
    Specialised& entry = specialised_[{model, key, output}];
    if (!entry.program) {
        try {
            entry.program = build(model, output, shader_sources::mesh_vert, key.defines());
        } catch (...) {
            specialised_.erase({model, key, output});
            throw;
        }
    }
    entry.lastUse = ++useCount_;
    const GlProgram& program = *entry.program;
    if (specialised_.size() > kSpecialisedCapacity) {
        auto oldest = specialised_.begin();
        for (auto it = specialised_.begin(); it != specialised_.end(); ++it) {
            oldest = it->second.lastUse < oldest->second.lastUse ? it : oldest;
        }
        specialised_.erase(oldest);   // never `entry`: it was used last
    }
    return bind(model, program);
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
