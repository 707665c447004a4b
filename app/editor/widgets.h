#pragma once
// Small ImGui widgets shared by the panels. Each writes straight into the value it edits and
// returns whether it changed it, as ImGui's own do.
#include <string>

#include <glm/vec3.hpp>
#include <imgui.h>

namespace patina::editor {

// The width that leaves room for the item's label and a resetButton on its line.
float widthBesideReset(const char* label);
// A slider (Ctrl+click types a value) with a resetButton.
bool sliderWithReset(const char* label, float* value, float minimum, float maximum, float fileValue,
                     float defaultValue, const char* format = "%.3f");
// Whether `after` is `before` (sRGB) unchanged or merely rounded to 8 bits a channel, as
// ImGui's hex field writes a colour back on a click without an edit.
bool onlyQuantised(glm::vec3 before, glm::vec3 after);
// Shows and edits the colour in sRGB, stores linear RGB (values above 1 are kept as HDR). A
// write-back that only rounds to 8 bits is not a change (onlyQuantised).
bool colorEditLinear(const char* label, glm::vec3* linear, bool hdr = false, ImGuiColorEditFlags flags = 0);
// A swatch of a linear colour, shown in sRGB, with its numbers.
void linearSwatch(const char* label, glm::vec3 linear);
// InputText over a std::string (libimgui-dev ships no imgui_stdlib implementation).
bool inputString(const char* label, std::string* text, ImGuiInputTextFlags flags = 0);

// Remembers the screen rectangle of the last item under `name`, for tests and automation
// (PATINA_UI_LAYOUT, see editor_app.cpp).
void recordItem(const std::string& name);
bool itemRect(const std::string& name, ImVec2* min, ImVec2* max);

// A small Reset button: a click restores the value of the file the material came from
// (`fileValue`), a right-click the default; greyed out when the value is both already.
// Recorded for automation as "Reset <name>". Returns whether it changed the value.
template <typename T>
bool resetButton(const char* name, T* value, const T& fileValue, const T& defaultValue) {
    ImGui::PushID(name);
    const bool disabled = *value == fileValue && *value == defaultValue;
    ImGui::BeginDisabled(disabled);
    const bool clicked = ImGui::SmallButton("Reset");
    const bool toDefault = !disabled && ImGui::IsItemClicked(ImGuiMouseButton_Right);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("Click: back to the file's value. Right-click: back to the default.");
    }
    ImGui::EndDisabled();
    recordItem(std::string("Reset ") + name);
    ImGui::PopID();
    const T wanted = toDefault ? defaultValue : fileValue;
    if ((clicked || toDefault) && *value != wanted) {
        *value = wanted;
        return true;
    }
    return false;
}

std::string layoutJson();

}  // namespace patina::editor
