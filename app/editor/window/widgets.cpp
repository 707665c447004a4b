#include "window/widgets.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string_view>
#include <vector>

#include <imgui_internal.h>

#include "shading/shading.h"

namespace patina::editor {

namespace {
glm::vec3 toLinear(glm::vec3 srgb) {
    return {shader::srgbDecode(srgb.r), shader::srgbDecode(srgb.g), shader::srgbDecode(srgb.b)};
}

using RecordedItems = std::map<std::string, RecordedItem>;

// Which of an ImGui context's hooks holds its recorded items.
const ImGuiID kRecordedItemsHook = ImHashStr("patina recorded items");

// The current ImGui context's items, made with its first and freed as it shuts down: they are
// of its frames, which a new context (tests make many) counts from 0 again.
RecordedItems& recorded() {
    ImGuiContext& context = *ImGui::GetCurrentContext();
    for (const ImGuiContextHook& hook : context.Hooks) {
        if (hook.Owner == kRecordedItemsHook) {
            return *static_cast<RecordedItems*>(hook.UserData);
        }
    }
    ImGuiContextHook hook;
    hook.Type = ImGuiContextHookType_Shutdown;
    hook.Owner = kRecordedItemsHook;
    hook.UserData = new RecordedItems;
    hook.Callback = [](ImGuiContext*, ImGuiContextHook* self) { delete static_cast<RecordedItems*>(self->UserData); };
    ImGui::AddContextHook(&context, &hook);
    return *static_cast<RecordedItems*>(hook.UserData);
}
}  // namespace

float widthBesideReset(const char* label) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float resetWidth = ImGui::CalcTextSize("Reset").x + style.FramePadding.x * 2;
    return ImGui::GetContentRegionAvail().x - resetWidth - style.ItemSpacing.x - ImGui::CalcTextSize(label).x -
           style.ItemInnerSpacing.x;
}

bool sliderWithReset(const char* label, const char* tooltip, float* value, float minimum, float maximum,
                     float fileValue, float defaultValue, const char* format) {
    ImGui::PushID(label);
    ImGui::SetNextItemWidth(widthBesideReset(label));
    bool changed = ImGui::SliderFloat(label, value, minimum, maximum, format,
                                      ImGuiSliderFlags_AlwaysClamp);
    recordItem(label, tooltip);
    ImGui::SameLine();
    changed |= resetButton(label, value, fileValue, defaultValue);
    ImGui::PopID();
    return changed;
}

bool onlyQuantised(glm::vec3 before, glm::vec3 after) {
    if (before == after) {
        return true;
    }
    for (int c = 0; c < 3; ++c) {
        if (after[c] != std::round(before[c] * 255.0f) / 255.0f) {
            return false;
        }
    }
    return true;
}

bool colorEditLinear(const char* label, const char* tooltip, glm::vec3* linear, bool hdr, ImGuiColorEditFlags flags) {
    // sRGB cannot show components above 1: the picker shows the colour over its peak, and the
    // peak multiplies back in (light colours may be HDR; material colours stay in [0, 1]).
    const float peak = hdr ? std::max({linear->r, linear->g, linear->b, 1.0f}) : 1.0f;
    const glm::vec3 srgb = shader::srgbColor(glm::clamp(*linear / peak, 0.0f, 1.0f));
    float color[3] = {srgb.r, srgb.g, srgb.b};
    // Clicking into the picker's hex field writes the colour back rounded to 8 bits (0.8000 to
    // 0.7991) without any edit: that is no change, and must not dirty the file or make a step.
    // The numbers are sRGB, as captions and screenshots show them: said beside them (the ID
    // stays the bare label), and in the tooltip with what files hold.
    // A label "##NAME" is drawn by the caller (above a narrow field); the item is NAME.
    const bool labelAbove = std::string_view(label).starts_with("##");
    const std::string_view name = labelAbove ? label + 2 : label;
    const bool numbers = (flags & ImGuiColorEditFlags_NoInputs) == 0;
    const std::string shown = numbers && !labelAbove ? std::string(label) + " sRGB###" + label : std::string(label);
    const bool changed = ImGui::ColorEdit3(shown.c_str(), color, ImGuiColorEditFlags_Float | flags) &&
                         !onlyQuantised(srgb, glm::vec3(color[0], color[1], color[2]));
    recordItem(std::string(name), (std::string(tooltip) + " (shown in sRGB; files store linear values)").c_str());
    if (changed) {
        *linear = glm::clamp(toLinear(glm::vec3(color[0], color[1], color[2])), 0.0f, 1.0f) * peak;
    }
    return changed;
}

void linearSwatch(const char* label, const char* tooltip, glm::vec3 linear) {
    const glm::vec3 srgb = shader::srgbColor(glm::clamp(linear, 0.0f, 1.0f));
    ImGui::ColorButton(label, ImVec4(srgb.r, srgb.g, srgb.b, 1.0f), ImGuiColorEditFlags_NoTooltip);
    recordItem(label, tooltip);
    ImGui::SameLine();
    // Linear, as the shader computes it (base colour fields and captions show sRGB): named.
    ImGui::Text("%s  linear %.4f %.4f %.4f", label, double(linear.r), double(linear.g), double(linear.b));
}

bool inputString(const char* label, std::string* text, ImGuiInputTextFlags flags, const char* hint) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "%s", text->c_str());
    if (ImGui::InputTextWithHint(label, hint ? hint : "", buffer, sizeof buffer, flags)) {
        *text = buffer;
        return true;
    }
    return false;
}

namespace {
void remember(const std::string& name, ImVec2 min, ImVec2 max, const char* tooltip) {
    const ImGuiContext& context = *ImGui::GetCurrentContext();
    const ImGuiWindow& window = *context.CurrentWindow;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    RecordedItem& item = recorded()[name];
    item.min = min;
    item.max = max;
    // What the item was drawn clipped to: its window's inside, its table column, its menu bar.
    const ImVec2 clipMin = window.DrawList->GetClipRectMin(), clipMax = window.DrawList->GetClipRectMax();
    item.visibleMin = ImVec2(std::max(clipMin.x, 0.0f), std::max(clipMin.y, 0.0f));
    item.visibleMax = ImVec2(std::min(clipMax.x, display.x), std::min(clipMax.y, display.y));
    item.scrolls = window.ScrollbarY;
    item.dimmed = (context.CurrentItemFlags & ImGuiItemFlags_Disabled) != 0 || context.Style.Alpha < 1.0f;
    item.tooltip = tooltip ? tooltip : "";
    item.frame = ImGui::GetFrameCount();
}
}  // namespace

namespace {
// A tooltip wrapped at 40 ems: a long one (a status with a path in it) stays on the screen.
void wrappedTooltip(const char* text) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}
}  // namespace

void recordItem(const std::string& name, const char* tooltip) {
    remember(name, ImGui::GetItemRectMin(), ImGui::GetItemRectMax(), tooltip);
    if (tooltip && !ImGui::IsItemActive() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        wrappedTooltip(tooltip);
    }
}

void recordArea(const std::string& name, ImVec2 min, ImVec2 max, const char* tooltip) {
    remember(name, min, max, tooltip);
    if (tooltip && ImGui::IsWindowHovered() && ImGui::IsMouseHoveringRect(min, max) && !ImGui::IsAnyMouseDown()) {
        wrappedTooltip(tooltip);
    }
}

bool itemRect(const std::string& name, ImVec2* min, ImVec2* max) {
    const auto it = recorded().find(name);
    if (it == recorded().end()) {
        return false;
    }
    *min = it->second.min;
    *max = it->second.max;
    return true;
}

std::map<std::string, RecordedItem> itemsOfLastFrame() {
    std::map<std::string, RecordedItem> items;
    for (const auto& [name, item] : recorded()) {
        if (item.frame == ImGui::GetFrameCount()) {
            items.emplace(name, item);
        }
    }
    return items;
}

bool clipped(const RecordedItem& item) {
    constexpr float slack = 0.5f;   // rounding of the rectangles
    const bool horizontally = item.min.x < item.visibleMin.x - slack || item.max.x > item.visibleMax.x + slack;
    const bool vertically = item.min.y < item.visibleMin.y - slack || item.max.y > item.visibleMax.y + slack;
    return horizontally || (vertically && !item.scrolls);
}

std::string fittedText(const std::string& text, float width) {
    if (ImGui::CalcTextSize(text.c_str()).x <= width) {
        return text;
    }
    std::string cut = text;
    while (!cut.empty() && ImGui::CalcTextSize((cut + "...").c_str()).x > width) {
        cut.pop_back();
    }
    return cut + "...";
}

void sameLineIfFits(float width) {
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < width) {
        ImGui::NewLine();
    }
}

float labelledWidth(float fieldWidth, const char* label) {
    return fieldWidth + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
}

std::string layoutJson(bool asleep) {
    // The frame it was written after: automation waits for its input to have been drawn; and
    // whether the editor sleeps after it (what it drew stays as it is until the next input).
    std::string json = "{\"frame\": " + std::to_string(ImGui::GetFrameCount()) +
                       ", \"asleep\": " + (asleep ? "true" : "false");
    for (const auto& [name, item] : recorded()) {
        char entry[256];
        std::snprintf(entry, sizeof entry, ", \"%s\": [%.1f, %.1f, %.1f, %.1f]",
                      name.c_str(), double(item.min.x), double(item.min.y), double(item.max.x),
                      double(item.max.y));
        json += entry;
    }
    // The items the last frame drew (the rectangles above are each item's last): what is on
    // screen now, as a message that went away.
    std::string shown;
    for (const auto& [name, item] : itemsOfLastFrame()) {
        shown += (shown.empty() ? "\"" : ", \"") + name + "\"";
    }
    return json + ", \"shown\": [" + shown + "]}\n";
}

}  // namespace patina::editor
