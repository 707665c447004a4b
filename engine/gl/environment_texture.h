#pragma once
#include <memory>

#include "environment/environment.h"

namespace patina {

// `chain` as a new GL cube map (RGB32F, trilinear, seamless), bound to the current texture unit;
// the caller owns (and deletes) the texture.
unsigned uploadCubeChain(const CubeChain& chain);

// An environment's prefiltered chain and irradiance map (and, when asked, its source chain) as
// GL cube maps (RGB32F, one mip per level, seamless filtering on, trilinear), uploaded once per
// Environment shown. Needs a current context.
class EnvironmentTexture {
public:
    EnvironmentTexture() = default;
    ~EnvironmentTexture();
    EnvironmentTexture(const EnvironmentTexture&) = delete;
    EnvironmentTexture& operator=(const EnvironmentTexture&) = delete;

    // Uploads `environment` unless it is the one uploaded last, then binds its prefiltered chain
    // to `unit` and its irradiance map to `irradianceUnit`.
    void bind(const std::shared_ptr<const Environment>& environment, int unit, int irradianceUnit);
    // The same for its source and box-filtered mips (sourceMipChain), which the stochastic
    // mode reads.
    void bindSource(const std::shared_ptr<const Environment>& environment, int unit);

private:
    struct Cube {
        unsigned texture = 0;
        std::shared_ptr<const Environment> shown;
    };
    Cube prefiltered_, irradiance_, source_;
    static void bindCube(Cube& cube, const std::shared_ptr<const Environment>& environment, int unit,
                         CubeChain (*chainOf)(const Environment&));
};

}  // namespace patina
