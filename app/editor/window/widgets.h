#pragma once
// Small ImGui widgets shared by the panels. Each writes straight into the value it edits and
// returns whether it changed it, as ImGui's own do.
#include <map>
#include <string>

#include <glm/vec3.hpp>
#include <imgui.h>

namespace patina::editor {

// Amber: what asks to be looked at (PBR texels flagged, what a model's file has that is not drawn).
inline const ImVec4 kWarningColour{1.0f, 0.75f, 0.3f, 1.0f};

// The width that leaves room for the item's label and a resetButton on its line.
float widthBesideReset(const char* label);
// A slider (Ctrl+click types a value) with a resetButton; `tooltip` says what it does.
bool sliderWithReset(const char* label, const char* tooltip, float* value, float minimum, float maximum,
                     float fileValue, float defaultValue, const char* format = "%.3f");
// Whether `after` is `before` (sRGB) unchanged or merely rounded to 8 bits a channel, as
// ImGui's hex field writes a colour back on a click without an edit.
bool onlyQuantised(glm::vec3 before, glm::vec3 after);
// Shows and edits the colour in sRGB, stores linear RGB (values above 1 are kept as HDR). A
// write-back that only rounds to 8 bits is not a change (onlyQuantised).
bool colorEditLinear(const char* label, const char* tooltip, glm::vec3* linear, bool hdr = false,
                     ImGuiColorEditFlags flags = 0);
// A swatch of a linear colour, shown in sRGB, with its numbers; named `label` for automation.
void linearSwatch(const char* label, const char* tooltip, glm::vec3 linear);
// InputText over a std::string (libimgui-dev ships no imgui_stdlib implementation); `hint`
// shows greyed in it while it is empty.
bool inputString(const char* label, std::string* text, ImGuiInputTextFlags flags = 0, const char* hint = nullptr);

// Names the last item: its screen rectangle is remembered under `name` for tests and
// automation (PATINA_UI_LAYOUT, see editor_app.cpp), and `tooltip`, when given, is shown while
// the mouse rests on it (not while it is being dragged).
void recordItem(const std::string& name, const char* tooltip = nullptr);
// The same for what ImGui knows no item of (a light's handle over the viewport): `min` to `max`
// on screen, the tooltip shown while the mouse rests there with no button down.
void recordArea(const std::string& name, ImVec2 min, ImVec2 max, const char* tooltip = nullptr);
bool itemRect(const std::string& name, ImVec2* min, ImVec2* max);

// What recordItem remembers of an item.
struct RecordedItem {
    ImVec2 min, max;                 // the item
    ImVec2 visibleMin, visibleMax;   // what of its window is on screen (inside the display)
    bool scrolls = false;            // its window scrolls vertically: below the fold is not clipped
    bool dimmed = false;             // drawn faded: disabled, or a light that solo leaves out
    std::string tooltip;
    int frame = 0;                   // ImGui's frame count when it was last drawn
};
// The items drawn in the current (or last rendered) frame, by name. Each ImGui context keeps
// its own, from its first frame until it is destroyed.
std::map<std::string, RecordedItem> itemsOfLastFrame();
// Whether an item is cut by the edge of its window or of the display.
bool clipped(const RecordedItem& item);
// `text` cut with "..." to fit `width` pixels in the current font.
std::string fittedText(const std::string& text, float width);
// Puts the next item on this line when `width` pixels still fit, else on a new line.
void sameLineIfFits(float width);
// The width of an item with a `fieldWidth` field and a label beside it.
float labelledWidth(float fieldWidth, const char* label);

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
    recordItem(std::string("Reset ") + name, "Click: back to the file's value. Right-click: back to the default.");
    ImGui::EndDisabled();
    ImGui::PopID();
    const T wanted = toDefault ? defaultValue : fileValue;
    if ((clicked || toDefault) && *value != wanted) {
        *value = wanted;
        return true;
    }
    return false;
}

std::string layoutJson(bool asleep);

}  // namespace patina::editor
