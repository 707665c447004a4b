#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <imgui.h>

#include "window/keys.h"
#include "panels/light_gizmos.h"
#include "panels/panels.h"
#include "state/part_picking.h"
#include "scene/camera_control.h"
#include "window/ui_scale.h"
#include "panels/viewport_overlays.h"
#include "panels/viewport_toolbar.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
void image(unsigned texture, ImVec2 size, float u0 = 0.0f, float u1 = 1.0f) {
    // Renderer textures have GL's bottom-up rows: flip v.
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)), size, ImVec2(u0, 1.0f),
                 ImVec2(u1, 0.0f));
}

// View > PBR validation overlay over one picture on screen (at, size; u1: how much of it shows
// from the left), the picture only: a channel is what was asked to be seen. The edited side's
// tally goes to the status line.
void overlayFlags(const Interaction& interaction, EditorServices& services, const PreparedScene& scene,
                  const PictureRequest& request, EditorServices::Shown shown, ImVec2 at, ImVec2 size, float u1 = 1.0f) {
    if (!interaction.pbrOverlay || request.channel.channel >= 0) {
        return;
    }
    const EditorServices::PbrOverlay& overlay = services.pbrOverlay(scene, request, shown);
    ImGui::GetWindowDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(overlay.texture->id())),
                                         at, ImVec2(at.x + size.x, at.y + size.y), ImVec2(0.0f, 0.0f),
                                         ImVec2(u1, 1.0f));
    if (shown == EditorServices::Shown::Edited) {
        services.pbrTally = overlay.tally;
    }
}

// The picture: B, or A and B side by side, or A over B's left part up to the divider; with
// the PBR validation overlay over each when asked.
void drawPictures(const Document& document, const Interaction& interaction, EditorServices& services, const Scene& b,
                  const ViewArea& area) {
    using Shown = EditorServices::Shown;
    // While a widget is held (a slider drag), skip MSAA so the preview keeps up; the full
    // quality frame follows on release.
    const int samples = ImGui::IsAnyItemActive() ? 1 : 4;
    const PictureRequest request{
        area.width, area.height, interaction.renderPath, samples, interaction.environmentShading, interaction.channel};
    const PreparedScene& preparedB = sceneToDraw(document, b);
    if (interaction.compareA && interaction.compareView == CompareView::SideBySide) {
        PictureRequest half = request;
        half.width = std::max(area.width / 2, 8);
        const ImVec2 halfSize(float(half.width), area.size.y);
        const Scene a = withMaterial(document, interaction, *interaction.compareA);
        const PreparedScene& preparedA = sceneToDraw(document, a);
        image(services.viewportTexture(preparedA, half, Shown::A), halfSize);
        ImGui::SameLine(0.0f, 0.0f);
        image(services.viewportTexture(preparedB, half, Shown::Edited), halfSize);
        overlayFlags(interaction, services, preparedA, half, Shown::A, area.origin, halfSize);
        overlayFlags(interaction, services, preparedB, half, Shown::Edited,
                     ImVec2(area.origin.x + float(half.width), area.origin.y), halfSize);
        return;
    }
    image(services.viewportTexture(preparedB, request, Shown::Edited), area.size);
    overlayFlags(interaction, services, preparedB, request, Shown::Edited, area.origin, area.size);
    if (interaction.compareA && interaction.compareView == CompareView::Split) {
        // A left of the divider, B right, one camera: A's image drawn over B's left part.
        const Scene sceneA = withMaterial(document, interaction, *interaction.compareA);
        const PreparedScene& preparedA = sceneToDraw(document, sceneA);
        const unsigned a = services.viewportTexture(preparedA, request, Shown::A);
        const float split = std::clamp(interaction.splitPosition, 0.0f, 1.0f);
        const ImVec2 sizeA(area.size.x * split, area.size.y);
        ImGui::SetCursorScreenPos(area.origin);
        image(a, sizeA, 0.0f, split);
        overlayFlags(interaction, services, preparedA, request, Shown::A, area.origin, sizeA, split);
    }
}

// The split view's divider, drawn and dragged; true while the pointer is on it or drags it.
bool handleDivider(Interaction& interaction, const ViewArea& area, bool hovered) {
    if (!interaction.compareA || interaction.compareView != CompareView::Split) {
        return false;
    }
    const float x = area.origin.x + area.size.x * interaction.splitPosition;
    ImGui::GetWindowDrawList()->AddLine(ImVec2(x, area.origin.y), ImVec2(x, area.origin.y + area.size.y),
                                        IM_COL32(255, 255, 255, 220), 2.0f);
    bool& draggingDivider = interaction.draggingDivider;
    bool onDivider = std::abs(ImGui::GetIO().MousePos.x - x) < 6.0f && hovered;
    if (onDivider && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        draggingDivider = true;
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        draggingDivider = false;
    }
    if (draggingDivider) {
        interaction.splitPosition = std::clamp((ImGui::GetIO().MousePos.x - area.origin.x) / area.size.x, 0.02f, 0.98f);
        onDivider = true;
    }
    if (onDivider) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    }
    return onDivider;
}

void handleCameraInput(Document& document, ImVec2 size) {
    ImGuiIO& io = ImGui::GetIO();
    Camera& camera = document.scene.camera;
    const bool pan = ImGui::IsMouseDragging(ImGuiMouseButton_Middle) ||
                     (ImGui::IsMouseDragging(ImGuiMouseButton_Left) && io.KeyShift);
    if (pan) {
        panCamera(camera, -io.MouseDelta.x / size.y, io.MouseDelta.y / size.y);
    } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
        orbitCamera(camera, -io.MouseDelta.x * 0.01f, io.MouseDelta.y * 0.01f);
    }
    if (io.MouseWheel != 0.0f) {
        dollyCamera(camera, std::pow(0.9f, io.MouseWheel));
    }
    // A right drag turns the environment (lighting and background together), as Marmoset's
    // sky drag: half a degree a pixel, one undo step a drag.
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
        if (Light* environment = editedEnvironment(document)) {
            environment->rotationDegrees =
                std::remainder(environment->rotationDegrees + io.MouseDelta.x * 0.5f, 360.0f);
        }
    }
}

// A left click (a press and release that did not drag) on the picture picks the model's part under
// it, in the half it falls in when Side by side.
void pickOnClick(const Document& document, Interaction& interaction, Prompts& prompts, const ViewArea& area) {
    const ImGuiIO& io = ImGui::GetIO();
    // While the read-out is on a click also pins a pixel; Ctrl+click only pins it.
    if (!document.model || !ImGui::IsMouseReleased(ImGuiMouseButton_Left) || io.KeyShift ||
        (io.KeyCtrl && interaction.pixelReadOut) ||
        io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] > px(3.0f) * px(3.0f)) {
        return;
    }
    float x = (io.MousePos.x - area.origin.x) / area.size.x, width = area.size.x;
    if (interaction.compareA && interaction.compareView == CompareView::SideBySide) {
        x = x < 0.5f ? 2.0f * x : 2.0f * x - 1.0f;
        width *= 0.5f;
    }
    const float y = (io.MousePos.y - area.origin.y) / area.size.y;
    pickPart(document, interaction, prompts, glm::vec2(2.0f * x - 1.0f, 1.0f - 2.0f * y), width / area.size.y);
}

// The pointer over the picture: the divider first, then a light's gizmo, else the camera; a
// click picks a part; F frames the mesh.
void handlePointer(Document& document, Interaction& interaction, const Preferences& preferences, Prompts& prompts,
                   EditorServices& services, const ViewArea& area) {
    ImGui::SetCursorScreenPos(area.origin);
    const bool clicked = ImGui::InvisibleButton("viewport-input", area.size,
                                                ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle |
                                                    ImGuiButtonFlags_MouseButtonRight);
    recordItem("viewport");   // the whole picture, whichever parts of it A and B show
    const bool viewportActive = ImGui::IsItemActive();
    const bool viewportPressed = ImGui::IsItemActivated();
    const bool hovered = ImGui::IsItemHovered();

    const bool onDivider = handleDivider(interaction, area, hovered);
    const bool gizmo = preferences.showGizmos && interaction.compareView != CompareView::SideBySide &&
                       drawLightGizmos(document, interaction, area.origin, area.size, viewportPressed);
    if (viewportActive && !gizmo && !onDivider) {
        handleCameraInput(document, area.size);
    } else if (hovered && ImGui::GetIO().MouseWheel != 0.0f) {
        dollyCamera(document.scene.camera, std::pow(0.9f, ImGui::GetIO().MouseWheel));
    }
    if (clicked && !gizmo && !onDivider) {
        pickOnClick(document, interaction, prompts, area);
    }
    if (hovered && pressed(services.keyPresses, kKeyF) &&
        !ImGui::GetIO().WantTextInput) {
        frameMesh(document);
    }
}
}  // namespace

void drawViewportPanel(EditorState& state, EditorServices& services) {
    drawViewportToolbar(state, state, state, state);
    const ImVec2 available = ImGui::GetContentRegionAvail();
    ViewArea area;
    area.width = std::max(int(available.x), 16);
    area.height = std::max(int(available.y), 16);
    area.origin = ImGui::GetCursorScreenPos();
    area.size = ImVec2(float(area.width), float(area.height));
    services.viewportWidth = area.width;
    services.viewportHeight = area.height;
    // Here, not at the frame's start: the menu may have chosen a channel, the lights panel (drawn
    // before the viewport) switched its light off, in this frame.
    keepChannelShowable(state, state, state);
    const Scene b = renderedScene(state, state);
    services.pbrTally.reset();   // set again below while the overlay or the channel shows it
    drawPictures(state, state, services, b, area);
    if (state.channel.channel == shader::CHANNEL_PBR_VALIDATION) {
        services.pbrTally = services.channelPbrTally(EditorServices::Shown::Edited);
    }
    drawPartOutline(state, state, state, area);
    handlePointer(state, state, state, state, services, area);
    if (state.compareA && state.compareView != CompareView::Single) {
        drawSideLabels(state, state, area.origin, area.size);
    }
    drawEnvironmentProgress(state, area);
    drawChannelLabel(state, area);
    // The read-out tells the story of the picture under the mouse: B, or A and B.
    const PreparedScene preparedB = sceneToDraw(state, b);
    std::optional<Scene> sceneA;   // outlives preparedA, which refers to it
    std::optional<PreparedScene> preparedA;
    std::vector<ReadOutPicture> pictures;
    const ImVec2 end(area.origin.x + area.size.x, area.origin.y + area.size.y);
    if (state.pixelReadOut && state.compareA && state.compareView != CompareView::Single) {
        sceneA = withMaterial(state, state, *state.compareA);
        preparedA.emplace(sceneToDraw(state, *sceneA));
        if (state.compareView == CompareView::SideBySide) {
            const float half = float(std::max(area.width / 2, 8));
            const ImVec2 size(half, area.size.y), middle(area.origin.x + half, area.origin.y);
            pictures.push_back({&*preparedA, area.origin, size, area.origin, ImVec2(middle.x, end.y), "A"});
            pictures.push_back({&preparedB, middle, size, middle, ImVec2(middle.x + half, end.y), "B"});
        } else {
            const float split = area.origin.x + area.size.x * std::clamp(state.splitPosition, 0.0f, 1.0f);
            pictures.push_back({&preparedB, area.origin, area.size, area.origin, end, "B"});
            pictures.push_back({&*preparedA, area.origin, area.size, area.origin, ImVec2(split, end.y), "A"});
            std::swap(pictures[0], pictures[1]);   // B last: the pins' window tells B's story
            pictures[1].hoverMin.x = split;        // B shows right of the divider
        }
    } else {
        pictures.push_back({&preparedB, area.origin, area.size, area.origin, end, ""});
    }
    drawPixelReadOut(state, state, services, pictures,
                     ImGui::IsWindowHovered() && ImGui::IsMouseHoveringRect(area.origin, end));
    if (state.showAdvanced) {
        drawRenderOverlay(state, services, b, area);
    }
}

}  // namespace patina::editor
