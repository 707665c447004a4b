#include "panels/viewport_overlays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/glm.hpp>

#include "environment/builtin_environments.h"
#include "window/editor_services.h"
#include "state/editor_state.h"
#include "state/part_picking.h"
#include "scene/view.h"
#include "views/screenshot_comparison.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
// A side's label ("A: gold") at the top of its part of the view, `room` pixels wide: left
// aligned at `x`, or with `rightAligned` ending there; on a dark box so it reads over any
// picture. The tooltip has it whole when it is cut.
void sideLabel(char side, const Material& material, float x, float y, float room, bool rightAligned) {
    const std::string whole = comparisonLabel(side, material);
    const std::string shown = fittedText(whole, std::max(room, ImGui::CalcTextSize("A...").x));
    const ImVec2 size = ImGui::CalcTextSize(shown.c_str());
    const ImVec2 at(rightAligned ? x - size.x : x, y);
    const float pad = px(3);
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(at.x - pad, at.y - pad),
                                              ImVec2(at.x + size.x + pad, at.y + size.y + pad),
                                              IM_COL32(0, 0, 0, 150), pad);
    ImGui::SetCursorScreenPos(at);
    ImGui::TextUnformatted(shown.c_str());
    const std::string tooltip =
        whole + (side == 'A' ? " (kept with Set A)" : " (the material you edit)");
    recordItem(std::string("label ") + side, tooltip.c_str());
}

}  // namespace

// Which material each part of the view shows, named.
void drawSideLabels(const Document& document, const Interaction& interaction, ImVec2 origin, ImVec2 size) {
    const float margin = px(8);
    const float a = interaction.compareView == CompareView::Split
                        ? size.x * std::clamp(interaction.splitPosition, 0.0f, 1.0f)
                        : std::floor(size.x / 2.0f);
    sideLabel('A', *interaction.compareA, origin.x + margin, origin.y + margin, a - 2.0f * margin, false);
    if (interaction.compareView == CompareView::Split) {
        sideLabel('B', labelledMaterial(document, interaction), origin.x + size.x - margin, origin.y + margin,
                  size.x - a - 2.0f * margin, true);
    } else {
        sideLabel('B', labelledMaterial(document, interaction), origin.x + a + margin, origin.y + margin,
                  size.x - a - 2.0f * margin, false);
    }
}

// The edited part of a model of several parts, outlined over the picture as the camera sees
// it (with the gizmos: hidden with them, and not in Side by side, whose halves differ).
void drawPartOutline(const Document& document, Interaction& interaction, const Preferences& preferences,
                     const ViewArea& area) {
    if (!document.model || modelMaterialCount(document) < 2 || !preferences.showGizmos ||
        interaction.compareView == CompareView::SideBySide) {
        return;
    }
    const glm::mat4 transform = viewProjection(document.scene.camera, area.size.x / area.size.y);
    auto screen = [&](const glm::vec4& clip) {
        return ImVec2(area.origin.x + (clip.x / clip.w + 1.0f) * 0.5f * area.size.x,
                      area.origin.y + (1.0f - clip.y / clip.w) * 0.5f * area.size.y);
    };
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(area.origin, ImVec2(area.origin.x + area.size.x, area.origin.y + area.size.y), true);
    for (const auto& [a, b] : partOutline(document, interaction)) {
        const glm::vec4 clipA = transform * glm::vec4(a, 1.0f), clipB = transform * glm::vec4(b, 1.0f);
        if (clipA.w > 1e-4f && clipB.w > 1e-4f) {   // both in front of the eye
            draw->AddLine(screen(clipA), screen(clipB), IM_COL32(255, 160, 40, 230), px(1.5f));
        }
    }
    draw->PopClipRect();
}

// An environment file being prepared: the picture keeps the one it had until then.
void drawEnvironmentProgress(const Jobs& jobs, const ViewArea& area) {
    if (const std::shared_ptr<EnvironmentLoad>& load = jobs.environmentLoad) {
        char text[160];
        std::snprintf(text, sizeof text, "Preparing the environment %s: %.0f%%", environmentName(load->source()).c_str(),
                      100.0f * load->progress());
        ImGui::GetWindowDrawList()->AddText(
            ImVec2(area.origin.x + 8, area.origin.y + area.size.y - ImGui::GetTextLineHeight() - 8),
            IM_COL32(255, 230, 150, 255), text);
    }
}

// Which channel the viewport shows instead of the picture, at its top left: data, not light.
void drawChannelLabel(const Interaction& interaction, const ViewArea& area) {
    if (interaction.channel.channel < 0) {
        return;
    }
    const std::string text = "Channel: " + channelName(interaction.channel) +
                             (interaction.channel.srgb ? " (sRGB)" : " (values)") +
                             "   View > Channel > Picture to go back";
    ImDrawList* draw = ImGui::GetWindowDrawList();
    // Under the comparison's side labels, which take the top corners.
    const bool labelled = interaction.compareA && interaction.compareView != CompareView::Single;
    const ImVec2 at(area.origin.x + px(8), area.origin.y + px(8) + (labelled ? ImGui::GetTextLineHeight() + px(10) : 0.0f));
    draw->AddRectFilled(ImVec2(at.x - px(4), at.y - px(3)),
                        ImVec2(at.x + ImGui::CalcTextSize(text.c_str()).x + px(4), at.y + ImGui::GetTextLineHeight() + px(3)),
                        IM_COL32(0, 0, 0, 170));
    draw->AddText(at, IM_COL32(255, 220, 120, 255), text.c_str());
    recordArea("channel label", at, ImVec2(at.x + ImGui::CalcTextSize(text.c_str()).x, at.y + ImGui::GetTextLineHeight()));
}

// Overlay (Advanced): cost of the last render and what was drawn.
void drawRenderOverlay(const Interaction& interaction, EditorServices& services, const Scene& b, const ViewArea& area) {
    int enabled = 0;
    for (const Light& light : b.lights) {
        enabled += light.enabled;
    }
    char overlay[160];
    std::snprintf(overlay, sizeof overlay, "CPU %.1f ms  GPU %.1f ms  lights %d  %s pass",
                  services.lastRenderMilliseconds(), services.lastGpuMilliseconds(), enabled,
                  std::string(renderPathName(interaction.renderPath)).c_str());
    const float line = ImGui::GetTextLineHeight();
    const ImVec2 origin = area.origin, size = area.size;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(ImVec2(origin.x + px(4), origin.y + size.y - line - px(8)),
                        ImVec2(origin.x + px(12) + ImGui::CalcTextSize(overlay).x, origin.y + size.y - px(4)),
                        IM_COL32(0, 0, 0, 150));
    draw->AddText(ImVec2(origin.x + px(8), origin.y + size.y - line - px(6)), IM_COL32(220, 220, 220, 255), overlay);
}

}  // namespace patina::editor
