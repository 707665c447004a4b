#include <algorithm>
#include <cmath>

#include <imgui.h>
#include <imgui_internal.h>

#include "files/input_error.h"
#include "window/panel_guard.h"
#include "views/panel_layout.h"
#include "panels/panels.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus;

// Whether the mouse holds one of the current window's edges or corners: the only way a user
// sizes a panel.
bool resizedByHand() {
    ImGuiWindow* window = ImGui::GetCurrentWindow();
    const ImGuiID active = ImGui::GetActiveID();
    for (int n = 0; n < 4; ++n) {
        if (active != 0 && (active == ImGui::GetWindowResizeCornerID(window, n) ||
                            active == ImGui::GetWindowResizeBorderID(window, ImGuiDir(n)))) {
            return true;
        }
    }
    return false;
}

// A panel at `rect`. Its free edge can be dragged: a size the user drags to is kept in
// `wanted` (at UI scale 1). Any other difference (a small window squeezing the panel, ImGui's
// own rounding or minimum) is this frame's only: it once overwrote the preference, and a
// window shrunk for a moment left the lobe 44 pixels high for good.
bool beginPanel(const char* name, const PanelRect& rect, bool horizontal, float* wanted) {
    ImGui::SetNextWindowPos(ImVec2(rect.x, rect.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(rect.width, rect.height), ImGuiCond_Always);
    const bool open = ImGui::Begin(name, nullptr, kPanelFlags);
    const float given = horizontal ? rect.width : rect.height;
    const float actual = horizontal ? ImGui::GetWindowSize().x : ImGui::GetWindowSize().y;
    if (std::abs(actual - given) > 0.5f && resizedByHand()) {
        *wanted = actual / uiScale();
    }
    return open;
}

// Errors float over the top of the viewport until dismissed, so no panel's widgets move.
void drawError(Prompts& prompts, ImVec2 at, float width) {
    if (prompts.error.empty()) {
        return;
    }
    ImGui::SetNextWindowPos(at, ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(width, px(400)));
    ImGui::SetNextWindowBgAlpha(0.92f);
    if (ImGui::Begin("##error", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                             ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
        ImGui::PushTextWrapPos(width - px(16));
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.5f, 0.45f, 1.0f));
        ImGui::TextUnformatted(prompts.error.c_str());
        ImGui::PopStyleColor();
        ImGui::PopTextWrapPos();
        if (ImGui::SmallButton("Dismiss")) {
            prompts.error.clear();
        }
        recordItem("error:dismiss", "Hide this message");
    }
    ImGui::End();
}

// The lobe; with Advanced on, the accuracy numbers beside it, a research tool, in a tab of their own.
void drawBottomPanel(const Document& document, Interaction& interaction, const Preferences& preferences,
                     EditorServices& services) {
    if (!preferences.showAdvanced) {
        drawLobePanel(document, interaction, services);
        return;
    }
    if (!ImGui::BeginTabBar("bottom")) {
        return;
    }
    const bool lobeTab = ImGui::BeginTabItem("Lobe");
    recordItem("Lobe tab", "The BRDF in the plane of incidence");
    if (lobeTab) {
        drawLobePanel(document, interaction, services);
        ImGui::EndTabItem();
    }
    const bool accuracyTab = ImGui::BeginTabItem("Accuracy");
    recordItem("Accuracy tab", "How far this model is from the reference BRDF, and fp32 from fp64");
    if (accuracyTab) {
        drawAccuracyPanel(document, interaction, preferences, services);
        ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
}

}  // namespace

void drawEditorFrame(EditorState& state, EditorServices& services) {
    const std::string statusBefore = state.status;
    if (!promptOpen(state, state)) {   // a load that ends behind a prompt waits for its answer
        finishEnvironmentLoad(state, state, state, state);
        finishModelLoad(state);
    }
    resolveEnvironmentShown(state, state, state);
    resolveAmbientOcclusion(state, state, state);
    // Before anything draws the camera; an edit in the last frame (or a file just opened) pauses
    // it instead. A frame after a long wait turns it a tenth of a second at most.
    advanceTurntable(state.turntable, state, state, std::min(double(ImGui::GetIO().DeltaTime), 0.1));
    drawGuarded(state, "The screenshot", [&] { takeRequestedScreenshot(state, services); });
    drawGuarded(state, "The menu", [&] { drawMenuBar(state, services); });
    // Before the panels and dialogs, so a dialog a key opens (Ctrl+O) appears, and takes the
    // keys, within the frames drawn after the key press.
    drawGuarded(state, "A shortcut", [&] { handleShortcuts(state, services); });
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float top = ImGui::GetFrameHeight();
    PanelLayout& layout = state.layout;
    const PanelPlacement at = placePanels(layout, display.x, std::max(display.y - top, 1.0f), top, uiScale());

    // Fields in the side panels leave room for the longest label beside them.
    const float labelRoom = ImGui::CalcTextSize("Background blur").x + ImGui::GetStyle().ItemInnerSpacing.x;
    if (beginPanel("Material", at.material, true, &layout.leftWidth)) {
        ImGui::PushItemWidth(-labelRoom);
        drawGuarded(state, "The material panel", [&] {
            drawMaterialPanel(state, services);
            ImGui::Separator();
            ImGui::TextDisabled("Presets");
            drawPresetsPanel(state, services);
        });
        ImGui::PopItemWidth();
    }
    ImGui::End();
    if (beginPanel("Lights", at.lights, true, &layout.rightWidth)) {
        ImGui::PushItemWidth(-labelRoom);
        drawGuarded(state, "The lights panel", [&] { drawLightsPanel(state, services); });
        ImGui::PopItemWidth();
    }
    ImGui::End();
    // The menu, a shortcut or a panel may have changed the document this frame (New, Open, an
    // undo): the viewport draws the environment its light names, never one not yet looked up.
    resolveEnvironmentShown(state, state, state);
    resolveAmbientOcclusion(state, state, state);
    ImGui::SetNextWindowPos(ImVec2(at.viewport.x, at.viewport.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(at.viewport.width, at.viewport.height), ImGuiCond_Always);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(px(4), px(4)));
    if (ImGui::Begin("Viewport", nullptr, kPanelFlags | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoScrollbar |
                                              ImGuiWindowFlags_NoScrollWithMouse)) {
        drawGuarded(state, "The viewport", [&] { drawViewportPanel(state, services); });
    }
    ImGui::End();
    ImGui::PopStyleVar();
    if (layout.showLobe) {   // hidden (View menu): the viewport takes the whole column
        if (beginPanel("Lobe", at.lobe, false, &layout.lobeHeight)) {
            drawGuarded(state, "The lobe panel", [&] { drawBottomPanel(state, state, state, services); });
        }
        ImGui::End();
    }

    // Over the picture, below the toolbar however many rows it wraps to (its buttons stay free).
    ImVec2 pictureMin, pictureMax;
    const float errorTop = itemRect("viewport", &pictureMin, &pictureMax) ? pictureMin.y + px(8) : top + px(64);
    drawError(state, ImVec2(at.viewport.x + px(8), errorTop), at.viewport.width - px(16));
    drawGuarded(state, "A dialog", [&] { drawDialogs(state, services); });
    // Whatever the widgets changed becomes one undo step once none of them is active. A step no
    // status line told of (a slider's) leaves an older "(Ctrl+Z undoes it)" saying what Ctrl+Z no
    // longer undoes first: it goes.
    if (!ImGui::IsAnyItemActive() && commitEdits(state) && state.status == statusBefore &&
        state.status.ends_with("(Ctrl+Z undoes it)")) {
        state.status.clear();
    }
}

}  // namespace patina::editor
