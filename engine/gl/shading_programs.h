#pragma once
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "../brdf_model_id.h"
#include "../shader_specialisation.h"
#include "program.h"

namespace patina {

// The shading programs of shaders/shade.frag, one permutation per BRDF model and use, compiled
// on first use (a model nobody selects is never compiled), with the LightBlock attached and,
// for models with energy compensation, their E(NoV, r) table as a texture.
class ShadingPrograms {
public:
    // SinglePassKarisPoints: single for lights whose point lights all have KARIS_ATTENUATION,
    // which it takes as a constant instead of reading (PATINA_KARIS_POINTS).
    enum class Use { SinglePass, SinglePassKarisPoints, MultiPass, Probe };
    // The single pass for `lights` (packEnabledLights' list).
    static Use singlePassFor(const std::vector<shader::PackedLight>& lights);
    // What the fragment shader writes: the linear radiance, or also its display value
    // (PATINA_DISPLAY_OUTPUT, for a pass with nothing to resolve or sum afterwards).
    enum class Output { Linear, LinearAndDisplay };

    ShadingPrograms() = default;
    ~ShadingPrograms();
    ShadingPrograms(const ShadingPrograms&) = delete;
    ShadingPrograms& operator=(const ShadingPrograms&) = delete;

    // Makes the program current (with its energy table bound) and returns it.
    const GlProgram& use(BrdfModelId model, Use use, Output output = Output::Linear);
    // The single-pass program specialised to `key`, compiled on first use. The least recently
    // used of more than kSpecialisedCapacity is deleted: an artist adding and removing lights
    // makes a new key each time.
    const GlProgram& useSpecialised(BrdfModelId model, const ShaderSpecialisation& key,
                                    Output output = Output::Linear);
    static constexpr size_t kSpecialisedCapacity = 16;
    size_t specialisedCount() const { return specialised_.size(); }

private:
    struct Specialised {
        std::unique_ptr<GlProgram> program;
        unsigned long long lastUse = 0;
    };
    std::map<std::tuple<BrdfModelId, Use, Output>, std::unique_ptr<GlProgram>> programs_;
    std::map<std::tuple<BrdfModelId, ShaderSpecialisation, Output>, Specialised> specialised_;
    unsigned long long useCount_ = 0;
    std::map<BrdfModelId, unsigned> energyTextures_;

    unsigned energyTexture(BrdfModelId model);
    std::unique_ptr<GlProgram> build(BrdfModelId model, Output output, const char* vertex,
                                     std::vector<std::string> defines);
    const GlProgram& bind(BrdfModelId model, const GlProgram& program);
};

}  // namespace patina
