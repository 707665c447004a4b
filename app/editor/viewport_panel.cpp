#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <glm/glm.hpp>
#include <imgui.h>

#include "scene/camera_control.h"
#include "panels.h"
#include "keys.h"
#include "ui_scale.h"
#include "widgets.h"

namespace patina::editor {

namespace {
// A light's dot, at the UI's scale.
float gizmoRadius() {
    return px(7.0f);
}

// The toolbar's controls wrap onto a second line when the viewport is narrow, rather than
// being cut off at its edge.
void drawToolbar(EditorState& state) {
    DisplaySettings& display = state.scene.display;
    // sphere, torus, or the glTF file opened or dropped on the window.
    const std::string current = state.scene.meshFile.empty()
                                    ? std::string(meshKindName(state.scene.mesh))
                                    : std::filesystem::path(state.scene.meshFile).filename().string();
    ImGui::SetNextItemWidth(px(110));
    if (ImGui::BeginCombo("Mesh", current.c_str())) {
        for (MeshKind kind : {MeshKind::Sphere, MeshKind::Torus}) {
            if (ImGui::Selectable(std::string(meshKindName(kind)).c_str(),
                                  state.scene.meshFile.empty() && state.scene.mesh == kind)) {
                state.scene.mesh = kind;
                state.scene.meshFile.clear();
                state.scene.resolvedMesh.reset();   // the built-in kind's
            }
        }
        ImGui::TextDisabled("or open / drop a .gltf or .glb");
        ImGui::EndCombo();
    }
    recordItem("Mesh", "The shape the material is shown on; open or drop a .gltf or .glb for your own");
    sameLineIfFits(labelledWidth(px(110), "Exposure"));
    ImGui::SetNextItemWidth(px(110));
    ImGui::SliderFloat("Exposure", &display.exposure, -8.0f, 8.0f, "%.2f EV");
    recordItem("Exposure", "Brightness of the picture in stops (EV): +1 doubles it. Ctrl+click to type");
    sameLineIfFits(labelledWidth(px(100), "Tone map"));
    int tonemap = int(display.tonemap);
    ImGui::SetNextItemWidth(px(100));
    ImGui::Combo("Tone map", &tonemap, "none\0aces\0reinhard\0pbr neutral\0");
    recordItem("Tone map", "How light above white is brought into the screen's range; PBR Neutral keeps colours true");
    display.tonemap = Tonemap(tonemap);
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Background"));
    colorEditLinear("Background", "The colour behind the mesh", &display.background, false,
                    ImGuiColorEditFlags_NoInputs);

    const ImGuiStyle& style = ImGui::GetStyle();
    auto radioWidth = [&](const char* label) { return labelledWidth(ImGui::GetFrameHeight(), label); };
    if (ImGui::Button("Set A")) {
        state.compareA = state.scene.material;
        if (state.compareView == CompareView::Single) {
            state.compareView = CompareView::Split;
        }
    }
    recordItem("Set A", "Keep the current material as A, to compare with what you edit next (B)");
    sameLineIfFits(radioWidth("Single"));
    ImGui::BeginDisabled(!state.compareA);
    int view = int(state.compareView);
    ImGui::RadioButton("Single", &view, int(CompareView::Single));
    recordItem("Single", "Show B, the material being edited, alone");
    sameLineIfFits(radioWidth("Split"));
    ImGui::RadioButton("Split", &view, int(CompareView::Split));
    recordItem("Split", "A left of a divider you can drag, B right of it");
    sameLineIfFits(radioWidth("Side by side"));
    ImGui::RadioButton("Side by side", &view, int(CompareView::SideBySide));
    recordItem("Side by side", "A and B next to each other, each half as wide");
    state.compareView = state.compareA ? CompareView(view) : CompareView::Single;
    sameLineIfFits(ImGui::CalcTextSize("Clear A").x + style.FramePadding.x * 2);
    if (ImGui::Button("Clear A")) {
        state.compareA.reset();
    }
    recordItem("Clear A", "Forget A and show B alone");
    ImGui::EndDisabled();
}

// Point lights as a marker, directional lights as an arrow from the centre of the view;
// both can be dragged. `pressed`: the viewport's button was clicked this frame (it holds the
// mouse from then on, so ImGui reports the window as not hovered). Drawn clipped to the image.
// Returns true while a gizmo is being dragged.
bool drawLightGizmos(EditorState& state, ImVec2 origin, ImVec2 size, bool pressed) {
    int& dragged = state.draggedLight;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    const glm::vec2 viewSize(size.x, size.y);
    const Camera& camera = state.scene.camera;
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const glm::vec2 local(mouse.x - origin.x, mouse.y - origin.y);
    bool hoveredAny = false;
    for (int i = 0; i < int(state.scene.lights.size()); ++i) {
        Light& light = state.scene.lights[size_t(i)];
        if (light.type == LightType::Hemisphere || light.type == LightType::Environment) {
            continue;   // everywhere at once: nothing to grab
        }
        const glm::vec3 anchor = light.type == LightType::Point
                                     ? light.position
                                     : camera.target - 1.6f * glm::normalize(light.direction);
        const auto screen = projectToViewport(camera, viewSize, anchor);
        if (!screen) {
            continue;
        }
        const ImVec2 at(origin.x + screen->x, origin.y + screen->y);
        const bool hovered = glm::distance(*screen, local) <= gizmoRadius() + 3.0f;
        hoveredAny |= hovered;
        // The selected light in yellow; one that solo leaves out of the picture greyed out.
        const ImU32 color = i == state.selectedLight ? IM_COL32(255, 210, 80, 255)
                            : soloedOut(state, i)    ? IM_COL32(110, 110, 110, 160)
                                                     : IM_COL32(230, 230, 230, 200);
        if (light.type == LightType::Point) {
            draw->AddCircleFilled(at, gizmoRadius(), light.enabled ? color : IM_COL32(90, 90, 90, 200));
            draw->AddCircle(at, gizmoRadius() + 2.0f, IM_COL32(0, 0, 0, 200));
        } else if (const auto centre = projectToViewport(camera, viewSize, camera.target)) {
            const ImVec2 tip(origin.x + centre->x, origin.y + centre->y);
            draw->AddLine(at, tip, color, 2.0f);
            draw->AddCircleFilled(at, gizmoRadius() * 0.7f, color);
            draw->AddTriangleFilled(tip, ImVec2(tip.x - 4, tip.y - 4), ImVec2(tip.x + 4, tip.y - 4), color);
        }
        if (hovered && pressed && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            dragged = i;
            state.selectedLight = i;
        }
    }
    draw->PopClipRect();
    if (dragged >= 0 && dragged < int(state.scene.lights.size()) && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        Light& light = state.scene.lights[size_t(dragged)];
        if (light.type == LightType::Point) {
            light.position = unprojectAtDepthOf(camera, viewSize, local, light.position);
        } else {
            // The arrow's tail follows the mouse on a sphere around the target.
            const glm::vec3 onPlane = unprojectAtDepthOf(camera, viewSize, local, camera.target);
            glm::vec3 fromTarget = onPlane - camera.target;
            const float reach = 1.6f, planar = glm::length(fromTarget);
            const glm::vec3 toCamera = glm::normalize(camera.position - camera.target);
            fromTarget += toCamera * std::sqrt(std::max(reach * reach - planar * planar, 0.0f));
            if (glm::dot(fromTarget, fromTarget) > 1e-6f) {
                light.direction = -glm::normalize(fromTarget);
            }
        }
        return true;
    }
    dragged = -1;
    if (hoveredAny) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
    }
    return hoveredAny;
}

void handleCameraInput(EditorState& state, ImVec2 size) {
    ImGuiIO& io = ImGui::GetIO();
    Camera& camera = state.scene.camera;
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
        if (Light* environment = editedEnvironment(state)) {
            environment->rotationDegrees =
                std::remainder(environment->rotationDegrees + io.MouseDelta.x * 0.5f, 360.0f);
        }
    }
}

void image(unsigned texture, ImVec2 size, float u0 = 0.0f, float u1 = 1.0f) {
    // Renderer textures have GL's bottom-up rows: flip v.
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)), size, ImVec2(u0, 1.0f),
                 ImVec2(u1, 0.0f));
}
}  // namespace

void drawViewportPanel(EditorState& state, EditorServices& services) {
    drawToolbar(state);
    const ImVec2 available = ImGui::GetContentRegionAvail();
    const int width = std::max(int(available.x), 16), height = std::max(int(available.y), 16);
    services.viewportWidth = width;
    services.viewportHeight = height;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size{float(width), float(height)};
    const Scene b = renderedScene(state);
    // While a widget is held (a slider drag), skip MSAA so the preview keeps up; the full
    // quality frame follows on release.
    const int samples = ImGui::IsAnyItemActive() ? 1 : 4;

    if (state.compareA && state.compareView == CompareView::SideBySide) {
        const int half = std::max(width / 2, 8);
        const ImVec2 halfSize(float(half), size.y);
        image(services.viewportTexture(withMaterial(state, *state.compareA), half, height, state.renderPath,
                                            EditorServices::Shown::A, samples), halfSize);
        ImGui::SameLine(0.0f, 0.0f);
        image(services.viewportTexture(b, half, height, state.renderPath, EditorServices::Shown::Edited, samples), halfSize);
    } else {
        image(services.viewportTexture(b, width, height, state.renderPath, EditorServices::Shown::Edited, samples), size);
        if (state.compareA && state.compareView == CompareView::Split) {
            // A left of the divider, B right, one camera: A's image drawn over B's left part.
            const unsigned a = services.viewportTexture(withMaterial(state, *state.compareA), width, height,
                                                        state.renderPath, EditorServices::Shown::A, samples);
            const float split = std::clamp(state.splitPosition, 0.0f, 1.0f);
            ImGui::SetCursorScreenPos(origin);
            image(a, ImVec2(size.x * split, size.y), 0.0f, split);
        }
    }
    recordItem("viewport");
    ImGui::SetCursorScreenPos(origin);
    ImGui::InvisibleButton("viewport-input", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle |
                               ImGuiButtonFlags_MouseButtonRight);
    const bool viewportActive = ImGui::IsItemActive();
    const bool viewportPressed = ImGui::IsItemActivated();
    const bool hovered = ImGui::IsItemHovered();

    ImDrawList* draw = ImGui::GetWindowDrawList();
    bool onDivider = false;
    if (state.compareA && state.compareView == CompareView::Split) {
        const float x = origin.x + size.x * state.splitPosition;
        draw->AddLine(ImVec2(x, origin.y), ImVec2(x, origin.y + size.y), IM_COL32(255, 255, 255, 220), 2.0f);
        draw->AddText(ImVec2(origin.x + 8, origin.y + 24), IM_COL32(255, 255, 255, 255), "A");
        draw->AddText(ImVec2(origin.x + size.x - 16, origin.y + 24), IM_COL32(255, 255, 255, 255), "B");
        bool& draggingDivider = state.draggingDivider;
        onDivider = std::abs(ImGui::GetIO().MousePos.x - x) < 6.0f && hovered;
        if (onDivider && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            draggingDivider = true;
        }
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            draggingDivider = false;
        }
        if (draggingDivider) {
            state.splitPosition = std::clamp((ImGui::GetIO().MousePos.x - origin.x) / size.x, 0.02f, 0.98f);
            onDivider = true;
        }
        if (onDivider) {
            ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
        }
    }
    const bool gizmo = state.showGizmos && state.compareView != CompareView::SideBySide &&
                       drawLightGizmos(state, origin, size, viewportPressed);
    if (viewportActive && !gizmo && !onDivider) {
        handleCameraInput(state, size);
    } else if (hovered && ImGui::GetIO().MouseWheel != 0.0f) {
        dollyCamera(state.scene.camera, std::pow(0.9f, ImGui::GetIO().MouseWheel));
    }
    if (hovered && pressed(services.keyPresses, kKeyF) &&
        !ImGui::GetIO().WantTextInput) {
        frameMesh(state);
    }

    // An environment file being prepared: the picture keeps the one it had until then.
    if (const std::shared_ptr<EnvironmentLoad>& load = state.environmentLoad) {
        char text[160];
        std::snprintf(text, sizeof text, "Preparing the environment %s: %.0f%%", environmentName(load->source()).c_str(),
                      100.0f * load->progress());
        draw->AddText(ImVec2(origin.x + 8, origin.y + size.y - ImGui::GetTextLineHeight() - 8),
                      IM_COL32(255, 230, 150, 255), text);
    }

    // Overlay (Advanced): cost of the last render and what was drawn.
    if (!state.showAdvanced) {
        return;
    }
    int enabled = 0;
    for (const Light& light : b.lights) {
        enabled += light.enabled;
    }
    char overlay[160];
    std::snprintf(overlay, sizeof overlay, "CPU %.1f ms  GPU %.1f ms  lights %d  %s pass",
                  services.lastRenderMilliseconds(), services.lastGpuMilliseconds(), enabled,
                  std::string(renderPathName(state.renderPath)).c_str());
    const float line = ImGui::GetTextLineHeight();
    draw->AddRectFilled(ImVec2(origin.x + px(4), origin.y + size.y - line - px(8)),
                        ImVec2(origin.x + px(12) + ImGui::CalcTextSize(overlay).x, origin.y + size.y - px(4)),
                        IM_COL32(0, 0, 0, 150));
    draw->AddText(ImVec2(origin.x + px(8), origin.y + size.y - line - px(6)), IM_COL32(220, 220, 220, 255), overlay);
}

}  // namespace patina::editor
