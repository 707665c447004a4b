#pragma once
// Small ImGui widgets shared by the panels. Each writes straight into the value it edits and
// returns whether it changed it, as ImGui's own do.
#include <string>

#include <glm/vec3.hpp>
#include <imgui.h>

namespace patina::editor {

// A slider (Ctrl+click types a value) with a reset button that restores `defaultValue`.
bool sliderWithReset(const char* label, float* value, float minimum, float maximum, float defaultValue,
                     const char* format = "%.3f");
// Shows and edits the colour in sRGB, stores linear RGB (values above 1 are kept as HDR).
bool colorEditLinear(const char* label, glm::vec3* linear, bool hdr = false, ImGuiColorEditFlags flags = 0);
// A swatch of a linear colour, shown in sRGB, with its numbers.
void linearSwatch(const char* label, glm::vec3 linear);
// InputText over a std::string (libimgui-dev ships no imgui_stdlib implementation).
bool inputString(const char* label, std::string* text, ImGuiInputTextFlags flags = 0);

// Remembers the screen rectangle of the last item under `name`, for tests and automation
// (PATINA_UI_LAYOUT, see editor_app.cpp).
void recordItem(const std::string& name);
bool itemRect(const std::string& name, ImVec2* min, ImVec2* max);
std::string layoutJson();

}  // namespace patina::editor
