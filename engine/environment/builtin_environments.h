#pragma once
#include <optional>
#include <span>
#include <string_view>

#include "common/hdr_image.h"

namespace patina {

// Environments generated in code, named after "builtin:" in a scene's source:
//   white   radiance 1 everywhere (the furnace tests)
//   studio  a neutral studio: four soft boxes over a grey gradient and a darker floor, the
//           embedded default scene's environment
std::span<const std::string_view> builtinEnvironmentNames();
std::optional<HdrImage> builtinEnvironment(std::string_view name);

}  // namespace patina
