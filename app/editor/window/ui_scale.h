#pragma once
// How big the UI is drawn: a real font (DejaVu Sans, Debian's fonts-dejavu-core) and ImGui's
// sizes, both scaled by the monitor's content scale times the user's setting (View menu), so a
// 4K screen at 200% gets the same layout as 1080p at 100%.
#include <filesystem>
#include <string>

namespace patina::editor {

inline const std::filesystem::path kUiFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr float kUiFontPixels = 15.0f;   // at scale 1: readable, and as tall as ImGui's frames expect

// The scale the UI is drawn at: the monitor's content scale times the user's setting, kept to
// what ImGui can draw sensibly.
float uiScaleFor(float contentScale, float setting);

// Rebuilds ImGui's font atlas (the caller re-uploads its texture) and style for `scale`.
// Returns "" or, when `fontFile` cannot be used, a message saying so: the built-in font is
// used then, scaled as well as a bitmap font can be.
std::string applyUiScale(float scale, const std::filesystem::path& fontFile = kUiFontFile);

// The scale last applied (1 before any), and a size given at scale 1 at that scale.
float uiScale();
inline float px(float pixelsAtScaleOne) {
    return pixelsAtScaleOne * uiScale();
}

}  // namespace patina::editor
