#include <algorithm>

#include <imgui.h>

#include "panel_guard.h"
#include "panels.h"
#include "widgets.h"

namespace patina::editor {

namespace {
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus;

// A panel fixed to one side; its free edge can be dragged and the new size is kept in `extent`.
bool beginPanel(const char* name, ImVec2 position, ImVec2 size, bool horizontal, float* extent) {
    ImGui::SetNextWindowPos(position, ImGuiCond_Always);
    ImGui::SetNextWindowSize(size, ImGuiCond_Always);
    const bool open = ImGui::Begin(name, nullptr, kPanelFlags);
    const ImVec2 actual = ImGui::GetWindowSize();
    *extent = horizontal ? actual.x : actual.y;
    return open;
}

// Errors float over the top of the viewport until dismissed, so no panel's widgets move.
void drawError(EditorState& state, ImVec2 at, float width) {
    if (state.error.empty()) {
        return;
    }
    ImGui::SetNextWindowPos(at, ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(width, 400));
    ImGui::SetNextWindowBgAlpha(0.92f);
    if (ImGui::Begin("##error", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                             ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
        ImGui::PushTextWrapPos(width - 16.0f);
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.5f, 0.45f, 1.0f));
        ImGui::TextUnformatted(state.error.c_str());
        ImGui::PopStyleColor();
        ImGui::PopTextWrapPos();
        if (ImGui::SmallButton("Dismiss")) {
            state.error.clear();
        }
        recordItem("error:dismiss");
    }
    ImGui::End();
}
}  // namespace

void drawEditorFrame(EditorState& state, EditorServices& services) {
    resolveEnvironmentShown(state);
    drawGuarded(state, "The menu", [&] { drawMenuBar(state, services); });
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float top = ImGui::GetFrameHeight();
    const float height = std::max(display.y - top, 100.0f);
    PanelLayout& layout = state.layout;
    layout.leftWidth = std::clamp(layout.leftWidth, 200.0f, std::max(200.0f, display.x * 0.45f));
    layout.rightWidth = std::clamp(layout.rightWidth, 220.0f, std::max(220.0f, display.x * 0.45f));
    layout.lobeHeight = std::clamp(layout.lobeHeight, 120.0f, std::max(120.0f, height * 0.6f));
    const float centreWidth = std::max(display.x - layout.leftWidth - layout.rightWidth, 100.0f);

    if (beginPanel("Material", ImVec2(0, top), ImVec2(layout.leftWidth, height), true, &layout.leftWidth)) {
        drawGuarded(state, "The material panel", [&] {
            drawMaterialPanel(state);
            ImGui::Separator();
            ImGui::TextDisabled("Presets");
            drawPresetsPanel(state, services);
        });
    }
    ImGui::End();
    if (beginPanel("Lights", ImVec2(display.x - layout.rightWidth, top), ImVec2(layout.rightWidth, height), true,
                   &layout.rightWidth)) {
        drawGuarded(state, "The lights panel", [&] { drawLightsPanel(state); });
    }
    ImGui::End();
    const float viewportHeight = std::max(height - layout.lobeHeight, 80.0f);
    ImGui::SetNextWindowPos(ImVec2(layout.leftWidth, top), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(centreWidth, viewportHeight), ImGuiCond_Always);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
    if (ImGui::Begin("Viewport", nullptr, kPanelFlags | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoScrollbar |
                                              ImGuiWindowFlags_NoScrollWithMouse)) {
        drawGuarded(state, "The viewport", [&] { drawViewportPanel(state, services); });
    }
    ImGui::End();
    ImGui::PopStyleVar();
    if (beginPanel("Lobe", ImVec2(layout.leftWidth, top + viewportHeight), ImVec2(centreWidth, layout.lobeHeight),
                   false, &layout.lobeHeight)) {
        drawGuarded(state, "The lobe panel", [&] {
            if (ImGui::BeginTabBar("bottom")) {
                if (ImGui::BeginTabItem("Lobe")) {
                    drawLobePanel(state);
                    ImGui::EndTabItem();
                }
                if (ImGui::BeginTabItem("Accuracy")) {
                    drawAccuracyPanel(state, services);
                    ImGui::EndTabItem();
                }
                ImGui::EndTabBar();
            }
        });
    }
    ImGui::End();

    drawError(state, ImVec2(layout.leftWidth + 8.0f, top + 64.0f), centreWidth - 16.0f);
    drawGuarded(state, "A dialog", [&] { drawDialogs(state, services); });
    drawGuarded(state, "A shortcut", [&] { handleShortcuts(state, services); });
    // Whatever the widgets changed becomes one undo step once none of them is active.
    if (!ImGui::IsAnyItemActive()) {
        commitEdits(state);
    }
}

}  // namespace patina::editor
