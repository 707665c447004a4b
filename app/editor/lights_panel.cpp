#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <imgui.h>

#include "panels.h"
#include "widgets.h"

namespace patina::editor {

namespace {
const char* typeIcon(LightType type) {
    switch (type) {
    case LightType::Point: return "(o)";
    case LightType::Directional: return "-->";
    case LightType::Hemisphere: return "(^)";
    }
    return "?";
}

// A directional light as azimuth (about +y, from +z towards +x) and elevation of the
// direction it comes from, in degrees: the angles an artist thinks in.
void editDirection(Light& light) {
    const glm::vec3 toLight = -glm::normalize(light.direction);
    float azimuth = glm::degrees(std::atan2(toLight.x, toLight.z));
    float elevation = glm::degrees(std::asin(glm::clamp(toLight.y, -1.0f, 1.0f)));
    bool changed = ImGui::SliderFloat("Azimuth", &azimuth, -180.0f, 180.0f, "%.1f deg");
    recordItem("Azimuth");
    changed |= ImGui::SliderFloat("Elevation", &elevation, -90.0f, 90.0f, "%.1f deg");
    if (changed) {
        const float a = glm::radians(azimuth), e = glm::radians(elevation);
        light.direction = -glm::vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
    }
    if (ImGui::DragFloat3("Direction", &light.direction.x, 0.01f)) {
        if (glm::dot(light.direction, light.direction) == 0.0f) {
            light.direction = {0.0f, -1.0f, 0.0f};   // a zero direction has no light
        }
    }
}

void editLight(Light& light) {
    // Written as typed, as the material's name: the edit commits when the field lets go, by
    // Enter or by a click elsewhere (it used to be lost unless Enter was pressed).
    inputString("Name", &light.name);
    recordItem("Light name");
    ImGui::Checkbox("Enabled", &light.enabled);
    colorEditLinear("Colour", &light.color, true);
    // Each pixel of drag changes the intensity by 1% of itself: 8 to 100 is about 250 pixels,
    // not 1800 as at a fixed step, and small values stay as easy to set as large ones.
    ImGui::DragFloat("Intensity", &light.intensity, std::max(light.intensity, 0.1f) * 0.01f, 0.0f, 1e6f, "%.3f",
                     ImGuiSliderFlags_AlwaysClamp);
    recordItem("Intensity");
    switch (light.type) {
    case LightType::Point:
        ImGui::DragFloat3("Position", &light.position.x, 0.01f);
        ImGui::DragFloat("Range", &light.range, 0.05f, 0.0f, 1e4f, light.range > 0 ? "%.3f" : "none",
                         ImGuiSliderFlags_AlwaysClamp);
        ImGui::DragFloat("a_c", &light.attenuation.x, 0.01f, 0.0f, 1e4f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        ImGui::DragFloat("a_l", &light.attenuation.y, 0.01f, 0.0f, 1e4f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        ImGui::DragFloat("a_q", &light.attenuation.z, 0.01f, 0.0f, 1e4f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        break;
    case LightType::Directional: editDirection(light); break;
    case LightType::Hemisphere:
        colorEditLinear("Sky", &light.sky, true);
        colorEditLinear("Ground", &light.ground, true);
        break;
    }
}
}  // namespace

void drawLightsPanel(EditorState& state) {
    if (ImGui::Button("Add point")) {
        addLight(state, LightType::Point);
    }
    recordItem("Add point");
    ImGui::SameLine();
    if (ImGui::Button("Add directional")) {
        addLight(state, LightType::Directional);
    }
    ImGui::SameLine();
    if (ImGui::Button("Add hemisphere")) {
        addLight(state, LightType::Hemisphere);
    }

    std::vector<Light>& lights = state.scene.lights;
    if (ImGui::BeginTable("lights", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH)) {
        ImGui::TableSetupColumn("on", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("solo", ImGuiTableColumnFlags_WidthFixed);
        for (int i = 0; i < int(lights.size()); ++i) {
            ImGui::PushID(i);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Checkbox("##enabled", &lights[size_t(i)].enabled);
            ImGui::TableNextColumn();
            const std::string label = std::string(typeIcon(lights[size_t(i)].type)) + " " + lights[size_t(i)].name;
            if (ImGui::Selectable(label.c_str(), state.selectedLight == i)) {
                state.selectedLight = i;
            }
            ImGui::TableNextColumn();
            const bool solo = state.soloLight == i;
            if (solo) {
                ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.8f, 0.6f, 0.1f, 1.0f));
            }
            if (ImGui::SmallButton("S")) {
                toggleSolo(state, i);
            }
            if (solo) {
                ImGui::PopStyleColor();
            }
            if (ImGui::IsItemHovered()) {
                ImGui::SetTooltip("Solo: render only this light");
            }
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    const int selected = state.selectedLight;
    const bool hasSelection = selected >= 0 && selected < int(lights.size());
    ImGui::BeginDisabled(!hasSelection);
    if (ImGui::Button("Duplicate")) {
        duplicateLight(state, selected);
    }
    ImGui::SameLine();
    if (ImGui::Button("Delete")) {
        deleteLight(state, selected);
    }
    ImGui::SameLine();
    if (ImGui::ArrowButton("up", ImGuiDir_Up)) {
        moveLight(state, selected, -1);
    }
    ImGui::SameLine();
    if (ImGui::ArrowButton("down", ImGuiDir_Down)) {
        moveLight(state, selected, +1);
    }
    ImGui::EndDisabled();
    if (state.selectedLight >= 0 && state.selectedLight < int(lights.size())) {
        ImGui::Separator();
        editLight(lights[size_t(state.selectedLight)]);
    }
}

}  // namespace patina::editor
