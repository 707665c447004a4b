#pragma once
#include <optional>
#include <string_view>

namespace patina {

// How an environment lights the mesh (shaders/shared/ibl_model.glsl): Karis's split sum, the
// split sum read along the dominant direction (Lagarde and de Rousiers 2014), or the stochastic
// mode's filtered importance samples per pixel. docs/LIGHTING.md measures each.
enum class EnvironmentMethod { SplitSum, Dominant, Stochastic };
std::string_view environmentMethodName(EnvironmentMethod method);
// split-sum, dominant or stochastic.
std::optional<EnvironmentMethod> environmentMethodFromName(std::string_view name);

struct EnvironmentShading {
    EnvironmentMethod method = EnvironmentMethod::SplitSum;
    int samples = 16;   // the stochastic mode's per pixel, 1 to 256
    bool operator==(const EnvironmentShading&) const = default;
};

}  // namespace patina
