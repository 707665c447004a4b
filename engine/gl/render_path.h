#pragma once
#include <optional>
#include <string_view>

namespace patina {

// multi: one additive pass per enabled light after a depth pre-pass (the seed's design);
// single: every light in one pass from the LightBlock uniform buffer;
// specialised: one pass compiled for the scene's light types and count (shader_specialisation.h).
// The three agree to rounding. A header of its own so that whoever only names a path (the
// editor's state, options) need not include the renderer.
enum class RenderPath { Single, Multi, Specialised };
std::string_view renderPathName(RenderPath mode);
// single, multi or specialised.
std::optional<RenderPath> renderPathFromName(std::string_view name);

}  // namespace patina
