#include "gl/shading_programs.h"

#include <algorithm>

#include <epoxy/gl.h>

#include "shading/brdf_models.h"
#include "shading/energy_table.h"
#include "shading/sheen_table.h"
#include "shading/environment_brdf.h"
#include "scene/light_packing.h"
#include "gl/shading_inputs.h"

namespace patina {

namespace shader_sources {
extern const char* const brdf_glsl;
extern const char* const mesh_vert;
extern const char* const probe_vert;
extern const char* const lights_glsl;
extern const char* const light_block_glsl;
}  // namespace shader_sources

namespace {
// Texture unit of uEnergyTable; unit 0 stays free for the display pass.
constexpr int kEnergyUnit = 1;

// mesh.vert reads the light block for a specialised shader's flat lights (lights.glsl comes after
// brdf.glsl, whose constants it uses).
std::vector<const char*> meshVertexParts() {
    return {shader_sources::brdf_glsl, shader_sources::lights_glsl, shader_sources::light_block_glsl,
            shader_sources::mesh_vert};
}
}  // namespace

ShadingPrograms::~ShadingPrograms() {
    for (const auto* textures : {&energyTextures_, &environmentBrdfTextures_}) {
        for (const auto& [model, texture] : *textures) {
            glDeleteTextures(1, &texture);
        }
    }
    if (sheenTexture_) {
        glDeleteTextures(1, &sheenTexture_);
    }
}

std::unique_ptr<GlProgram> ShadingPrograms::build(BrdfModelId model, Output output, Surface surface,
                                                  const std::vector<const char*>& vertexParts,
                                                  std::vector<std::string> defines) {
    const std::vector<std::string> modelDefines = brdfModelDefines(model);
    defines.insert(defines.begin(), modelDefines.begin(), modelDefines.end());
    if (output == Output::LinearAndDisplay) {
        defines.push_back("PATINA_DISPLAY_OUTPUT");
    }
    if (has(surface, Surface::Maps)) {
        defines.push_back("PATINA_TEXTURED");
    }
    if (has(surface, Surface::Clearcoat)) {
        defines.push_back("PATINA_CLEARCOAT");
    }
    if (has(surface, Surface::Sheen)) {
        defines.push_back("PATINA_SHEEN");
    }
    if (has(surface, Surface::Transmission)) {
        defines.push_back("PATINA_TRANSMISSION");
    }
    if (has(surface, Surface::Anisotropy)) {
        defines.push_back("PATINA_ANISOTROPY");
    }
    if (has(surface, Surface::AmbientOcclusion)) {
        defines.push_back("PATINA_AMBIENT_OCCLUSION");
    }
    if (has(surface, Surface::VertexColors)) {
        defines.push_back("PATINA_VERTEX_COLOR");
    }
    if (has(surface, Surface::Specular)) {
        defines.push_back("PATINA_SPECULAR");
    }
    if (has(surface, Surface::Iridescence)) {
        defines.push_back("PATINA_IRIDESCENCE");
    }
    if (std::find(defines.begin(), defines.end(), "PATINA_ENVIRONMENT") != defines.end()) {
        if (environmentShading_.method == EnvironmentMethod::Dominant) {
            defines.push_back("PATINA_ENVIRONMENT_DOMINANT");
        } else if (environmentShading_.method == EnvironmentMethod::Stochastic) {
            defines.push_back("PATINA_ENVIRONMENT_STOCHASTIC " + std::to_string(environmentShading_.samples));
        }
    }
    const bool channels = std::any_of(defines.begin(), defines.end(),
                                      [](const std::string& define) { return define.starts_with("PATINA_CHANNEL "); });
    auto program = std::make_unique<GlProgram>(vertexParts, shadingFragmentParts(channels), defines);
    LightBuffer::attach(*program);
    return program;
}

const GlProgram& ShadingPrograms::bind(BrdfModelId model, const GlProgram& program, bool environment) {
    program.use();
    if (brdfModel(model).multipleScattering()) {
        glActiveTexture(GL_TEXTURE0 + kEnergyUnit);
        glBindTexture(GL_TEXTURE_2D, energyTexture(model));
        glActiveTexture(GL_TEXTURE0);
    }
    glUniform1i(program.uniform("uEnergyTable"), kEnergyUnit);
    // Only a sheened program reads the sheen's table (the others have no such uniform).
    if (const GLint sheenTable = program.uniform("uSheenTable"); sheenTable >= 0) {
        glActiveTexture(GL_TEXTURE0 + kSheenTableUnit);
        glBindTexture(GL_TEXTURE_2D, sheenTexture());
        glActiveTexture(GL_TEXTURE0);
        glUniform1i(sheenTable, kSheenTableUnit);
    }
    if (environment) {
        glActiveTexture(GL_TEXTURE0 + kEnvironmentBrdfUnit);
        glBindTexture(GL_TEXTURE_2D, environmentBrdfTexture(model));
        glActiveTexture(GL_TEXTURE0);
        glUniform1i(program.uniform("uEnvironmentBrdf"), kEnvironmentBrdfUnit);
        glUniform1i(program.uniform("uEnvironmentMap"), kEnvironmentMapUnit);
        glUniform1i(program.uniform("uEnvironmentSource"), kEnvironmentSourceUnit);
        glUniform1i(program.uniform("uEnvironmentIrradiance"), kEnvironmentIrradianceUnit);
    }
    return program;
}

void ShadingPrograms::setEnvironmentShading(const EnvironmentShading& shading) {
    if (shading == environmentShading_) {
        return;
    }
    environmentShading_ = shading;
    auto dropEnvironment = [](auto& programs, auto hasEnvironment) {
        for (auto it = programs.begin(); it != programs.end();) {
            it = hasEnvironment(it->first) ? programs.erase(it) : std::next(it);
        }
    };
    dropEnvironment(programs_, [](const auto& key) { return std::get<3>(key); });
    dropEnvironment(singles_, [](const auto& key) { return std::get<1>(key).environment; });
    dropEnvironment(specialised_, [](const auto& key) { return std::get<1>(key).environment; });
}

ShadingPrograms::SinglePass ShadingPrograms::singlePassFor(const std::vector<shader::PackedLight>& lights) {
    const glm::ivec4 counts = packedLightCounts(lights);   // all, points, directionals, hemispheres
    const glm::ivec4 areaCounts = packedAreaLightCounts(lights);   // spheres, tubes
    SinglePass pass;
    pass.points = counts.y > 0;
    pass.directionals = counts.z > 0;
    pass.hemispheres = counts.w > 0;
    pass.spheres = areaCounts.x > 0;
    pass.tubes = areaCounts.y > 0;
    pass.karisPoints = std::all_of(lights.begin(), lights.end(), [](const shader::PackedLight& light) {
        return light.type == shader::LIGHT_DIRECTIONAL || light.type == shader::LIGHT_HEMISPHERE ||
               hasKarisAttenuation(light);
    });
    return pass;
}

std::vector<std::string> ShadingPrograms::SinglePass::defines() const {
    std::vector<std::string> defines{"PATINA_SINGLE_PASS"};
    if (karisPoints) {
        defines.push_back("PATINA_KARIS_POINTS");
    }
    if (environment) {
        defines.push_back("PATINA_ENVIRONMENT");
    }
    if (channel >= 0) {
        defines.push_back("PATINA_CHANNEL " + std::to_string(channel));
    }
    if (shadows) {
        defines.push_back("PATINA_SHADOWS");
    }
    if (catcher) {
        defines.push_back("PATINA_SHADOW_CATCHER");
    }
    for (const auto& [present, define] : {std::pair{points, "PATINA_NO_POINT_LIGHTS"},
                                          std::pair{directionals, "PATINA_NO_DIRECTIONAL_LIGHTS"},
                                          std::pair{hemispheres, "PATINA_NO_HEMISPHERE_LIGHTS"},
                                          std::pair{spheres, "PATINA_NO_SPHERE_LIGHTS"},
                                          std::pair{tubes, "PATINA_NO_TUBE_LIGHTS"}}) {
        if (!present) {
            defines.push_back(define);
        }
    }
    return defines;
}

const GlProgram& ShadingPrograms::use(BrdfModelId model, Use use, Output output, bool environment,
                                      Surface surface, bool shadows) {
    std::unique_ptr<GlProgram>& program = programs_[{model, use, output, environment, surface, shadows}];
    if (!program) {
        std::vector<std::string> defines;
        if (environment) {
            defines.push_back("PATINA_ENVIRONMENT");
        }
        if (shadows && use == Use::MultiPass) {
            defines.push_back("PATINA_SHADOWS");
        }
        if (use == Use::Probe) {
            defines.insert(defines.end(), {"PATINA_SINGLE_PASS", "PATINA_PROBE"});
            program = build(model, output, surface, {shader_sources::probe_vert}, defines);
        } else {
            program = build(model, output, surface, meshVertexParts(), defines);
        }
    }
    return bind(model, *program, environment);
}

const GlProgram& ShadingPrograms::useSingle(BrdfModelId model, const SinglePass& pass, Output output,
                                            Surface surface) {
    std::unique_ptr<GlProgram>& program = singles_[{model, pass, output, surface}];
    if (!program) {
        program = build(model, output, surface, meshVertexParts(), pass.defines());
    }
    return bind(model, *program, pass.environment);
}

const GlProgram& ShadingPrograms::useSpecialised(BrdfModelId model, const ShaderSpecialisation& key,
                                                 Output output, Surface surface) {
    Specialised& entry = specialised_[{model, key, output, surface}];
    if (!entry.program) {
        try {
            entry.program = build(model, output, surface, meshVertexParts(), key.defines());
        } catch (...) {
            specialised_.erase({model, key, output, surface});
            throw;
        }
    }
    entry.lastUse = ++useCount_;
    const GlProgram& program = *entry.program;
    while (specialised_.size() > kSpecialisedCapacity) {
        auto oldest = specialised_.end();
        for (auto it = specialised_.begin(); it != specialised_.end(); ++it) {
            const bool older = oldest == specialised_.end() || it->second.lastUse < oldest->second.lastUse;
            const bool evictable = it->second.lastUse < frameStart_ && &it->second != &entry;
            oldest = evictable && older ? it : oldest;
        }
        if (oldest == specialised_.end()) {
            break;   // every one is this frame's: kept until a later frame
        }
        specialised_.erase(oldest);
    }
    return bind(model, program, key.environment);
}

namespace {
// A square table of 32-bit floats, read by texelFetch only: the shared GLSL interpolates it
// itself (energy_table.glsl's tableCoordinate), so the CPU and the GPU use the same arithmetic.
// Never 8 bits or sRGB: a table of those bands (docs/LIGHTING.md L2).
unsigned tableTexture(GLint internalFormat, GLenum format, int size, const void* data) {
    unsigned texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, size, size, 0, format, GL_FLOAT, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return texture;
}
}  // namespace

unsigned ShadingPrograms::environmentBrdfTexture(BrdfModelId model) {
    unsigned& texture = environmentBrdfTextures_[model];
    if (!texture) {
        texture = tableTexture(GL_RG32F, GL_RG, kEnvironmentBrdfSize, environmentBrdfTable(model).data());
    }
    return texture;
}

unsigned ShadingPrograms::sheenTexture() {
    if (!sheenTexture_) {
        sheenTexture_ = tableTexture(GL_R32F, GL_RED, kSheenTableSize, sheenAlbedoTable().data());
    }
    return sheenTexture_;
}

unsigned ShadingPrograms::energyTexture(BrdfModelId model) {
    unsigned& texture = energyTextures_[model];
    if (!texture) {
        texture = tableTexture(GL_R32F, GL_RED, kEnergyTableSize, energyTable(model).data());
    }
    return texture;
}

}  // namespace patina
