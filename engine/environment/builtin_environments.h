#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "common/hdr_image.h"

namespace patina {

// Environments generated in code, named after "builtin:" in a scene's source:
//   white   radiance 1 everywhere (the furnace tests)
//   studio  a neutral studio: four soft boxes over a grey gradient and a darker floor, the
//           embedded default scene's environment
std::span<const std::string_view> builtinEnvironmentNames();

// An environment light's source names a built-in as "builtin:NAME" (else it is a file's path):
// the one place that spells the form.
inline constexpr std::string_view kBuiltinPrefix = "builtin:";
inline std::string builtinSource(std::string_view name) {
    return std::string(kBuiltinPrefix) + std::string(name);
}
// NAME of "builtin:NAME"; nothing for a file's path.
inline std::optional<std::string_view> builtinName(std::string_view source) {
    if (!source.starts_with(kBuiltinPrefix)) {
        return std::nullopt;
    }
    return source.substr(kBuiltinPrefix.size());
}
// What a source is called in a list or a message: "studio" for builtin:studio, a file's stem.
std::string environmentName(std::string_view source);
std::optional<HdrImage> builtinEnvironment(std::string_view name);

}  // namespace patina
