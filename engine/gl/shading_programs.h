#pragma once
#include <map>
#include <memory>
#include <utility>

#include "../brdf_model_id.h"
#include "program.h"

namespace patina {

// The shading programs of shaders/shade.frag, one permutation per BRDF model and use, compiled
// on first use (a model nobody selects is never compiled), with the LightBlock attached and,
// for models with energy compensation, their E(NoV, r) table as a texture.
class ShadingPrograms {
public:
    enum class Use { SinglePass, MultiPass, Probe };

    ShadingPrograms() = default;
    ~ShadingPrograms();
    ShadingPrograms(const ShadingPrograms&) = delete;
    ShadingPrograms& operator=(const ShadingPrograms&) = delete;

    // Makes the program current (with its energy table bound) and returns it.
    const GlProgram& use(BrdfModelId model, Use use);

private:
    std::map<std::pair<BrdfModelId, Use>, std::unique_ptr<GlProgram>> programs_;
    std::map<BrdfModelId, unsigned> energyTextures_;

    unsigned energyTexture(BrdfModelId model);
};

}  // namespace patina
