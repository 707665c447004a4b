#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <imgui.h>

#include "camera_choice.h"
#include "scene/camera_control.h"
#include "scene/view.h"
#include "part_picking.h"
#include "panels.h"
#include "keys.h"
#include "screenshot_comparison.h"
#include "ui_scale.h"
#include "widgets.h"

namespace patina::editor {

namespace {
// A light's dot, at the UI's scale.
float gizmoRadius() {
    return px(7.0f);
}

// A model being read, last on the toolbar so that no control moves under the pointer while the
// seconds count: the mesh shown stays until it is done, or for good if cancelled.
void drawModelLoad(EditorState& state) {
    const std::shared_ptr<ModelLoad> load = state.modelLoad;
    if (!load) {
        return;
    }
    char text[320];
    const std::string name = load->path().filename().string();
    if (load->fraction() > 0.0f) {
        std::snprintf(text, sizeof text, "Loading %s (%.0f s, images %.0f%%)", name.c_str(), load->seconds(),
                      100.0f * load->fraction());
    } else {
        std::snprintf(text, sizeof text, "Loading %s (%.0f s)", name.c_str(), load->seconds());
    }
    const ImGuiStyle& style = ImGui::GetStyle();
    sameLineIfFits(ImGui::CalcTextSize(text).x + style.ItemSpacing.x + ImGui::CalcTextSize("Cancel").x +
                   style.FramePadding.x * 2);
    ImGui::TextUnformatted(text);
    ImGui::SameLine();
    if (ImGui::Button("Cancel##model")) {
        cancelModelLoad(state);
    }
    recordItem("Model cancel", "Stop waiting for the model being read and keep the mesh shown");
}

// What each tone map is, for its entry's tooltip (docs/FORMATS.md, display.tonemap).
const char* tonemapSummary(Tonemap tonemap) {
    switch (tonemap) {
    case Tonemap::None: return "None: clamped at white, no curve";
    case Tonemap::PbrNeutral: return "Khronos PBR Neutral: colours up to 0.8 kept as they are, highlights compressed "
                                     "towards white (model-viewer's default)";
    case Tonemap::AcesHill: return "ACES as three.js and the Khronos glTF viewer show it: Hill's fit of the RRT + ODT, "
                                   "exposure boosted by 1/0.6";
    case Tonemap::Agx: return "AgX, Blender 4's default view, with its base look, as three.js applies it";
    case Tonemap::AcesNarkowicz: return "ACES by Narkowicz's fit, what Patina called \"aces\": brighter "
                                        "shadows, no colour matrices";
    case Tonemap::Reinhard: return "Reinhard: x / (1 + x)";
    }
    return "";
}

// The Camera list (model-viewer's framing, then the model's own cameras; the view is made when
// one is chosen, so no frame measures the mesh) and the field of view.
void drawCameraControls(EditorState& state) {
    const std::string current = currentCameraName(state);
    // Wide enough for the name shown (up to a limit), as the mesh's.
    const float width = std::clamp(ImGui::CalcTextSize(current.c_str()).x + ImGui::GetFrameHeight() +
                                       ImGui::GetStyle().FramePadding.x * 2.0f,
                                   px(90), px(200));
    sameLineIfFits(labelledWidth(width, "Camera"));
    ImGui::SetNextItemWidth(width);
    if (ImGui::BeginCombo("Camera", current.c_str())) {
        const std::vector<CameraChoice> choices = cameraChoices(state);
        for (size_t i = 0; i < choices.size(); ++i) {
            const CameraChoice& choice = choices[i];
            ImGui::BeginDisabled(!choice.usable);
            const std::string label = choice.name + "##camera" + std::to_string(i);
            if (ImGui::Selectable(label.c_str(), choice.usable && choice.name == current)) {
                chooseCamera(state, choice);
            }
            recordItem("camera:" + std::to_string(i), choice.detail.c_str());   // dimmed when not usable
            ImGui::EndDisabled();
        }
        if (choices.size() == 1) {
            ImGui::TextDisabled("a glTF model's own cameras are listed here");
        }
        ImGui::EndCombo();
    }
    recordItem("Camera", "Look from model-viewer's framing (the front, the whole shape in view) or from one of the "
                         "glTF file's own cameras (render --camera takes the same)");
    sameLineIfFits(labelledWidth(px(80), "FOV"));
    ImGui::SetNextItemWidth(px(80));
    ImGui::DragFloat("FOV", &state.scene.camera.fovYDegrees, 0.2f, 1.0f, 179.0f, "%.1f deg",
                     ImGuiSliderFlags_AlwaysClamp);
    recordItem("FOV", "The camera's vertical field of view in degrees (model-viewer's field-of-view; saved with the "
                      "scene): a wider lens from the same place. Ctrl+click or double-click to type");
}

// The toolbar's controls wrap onto a second line when the viewport is narrow, rather than
// being cut off at its edge.
void drawToolbar(EditorState& state) {
    DisplaySettings& display = state.scene.display;
    // sphere, torus, or the glTF file opened or dropped on the window.
    const std::string current = state.scene.meshFile.empty()
                                    ? std::string(meshKindName(state.scene.mesh))
                                    : std::filesystem::path(state.scene.meshFile).filename().string();
    // Wide enough for a model's file name (up to a limit), so "BoxTextured.glb" is not cut.
    const float nameWidth = ImGui::CalcTextSize(current.c_str()).x + ImGui::GetFrameHeight() +
                            ImGui::GetStyle().FramePadding.x * 2.0f;
    ImGui::SetNextItemWidth(std::clamp(nameWidth, px(110), px(240)));
    if (ImGui::BeginCombo("Mesh", current.c_str())) {
        for (MeshKind kind : {MeshKind::Sphere, MeshKind::Torus}) {
            if (ImGui::Selectable(std::string(meshKindName(kind)).c_str(),
                                  state.scene.meshFile.empty() && state.scene.mesh == kind)) {
                chooseBuiltinMesh(state, kind);
            }
        }
        ImGui::TextDisabled("or open / drop a .gltf or .glb");
        ImGui::EndCombo();
    }
    recordItem("Mesh", "The shape the material is shown on; open or drop a .gltf or .glb for your own");
    drawCameraControls(state);
    sameLineIfFits(labelledWidth(px(110), "Exposure"));
    // A drag, not a slider: 16 stops across 110 pixels moved 8 EV in 60 of them. Fine steps
    // (0.02 EV a pixel) for a look; a big change is typed.
    ImGui::SetNextItemWidth(px(110));
    ImGui::DragFloat("Exposure", &display.exposure, 0.02f, -8.0f, 8.0f, "%.2f EV", ImGuiSliderFlags_AlwaysClamp);
    recordItem("Exposure", "Brightness of the picture in stops (EV): +1 doubles it. Drag for fine steps (0.02 EV a "
                           "pixel); Ctrl+click or double-click to type");
    sameLineIfFits(labelledWidth(px(120), "Tone map"));
    ImGui::SetNextItemWidth(px(120));
    if (ImGui::BeginCombo("Tone map", std::string(tonemapName(display.tonemap)).c_str())) {
        for (const Tonemap tonemap : kTonemaps) {
            const std::string name(tonemapName(tonemap));
            if (ImGui::Selectable(name.c_str(), tonemap == display.tonemap)) {
                display.tonemap = tonemap;
            }
            recordItem("tonemap:" + name, tonemapSummary(tonemap));
        }
        ImGui::EndCombo();
    }
    recordItem("Tone map", "How light above white is brought into the screen's range, as the engines that show the "
                           "asset do (the same names as render --tonemap)");
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Background"));
    colorEditLinear("Background", "The colour behind the mesh", &display.background, false,
                    ImGuiColorEditFlags_NoInputs);

    const ImGuiStyle& style = ImGui::GetStyle();
    auto radioWidth = [&](const char* label) { return labelledWidth(ImGui::GetFrameHeight(), label); };
    if (ImGui::Button("Set A")) {
        state.compareA = labelledMaterial(state);
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
    drawModelLoad(state);
}

// The pixels on screen of a length `radius` across the view at `centre` (perspective: its
// distance counts), for drawing a light at its size.
float screenRadius(const Camera& camera, glm::vec2 viewSize, glm::vec3 centre, float radius) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    glm::vec3 side = glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f));
    side = glm::dot(side, side) > 1e-8f ? glm::normalize(side) : glm::vec3(1.0f, 0.0f, 0.0f);
    const auto a = projectToViewport(camera, viewSize, centre);
    const auto b = projectToViewport(camera, viewSize, centre + radius * side);
    return a && b ? glm::distance(*a, *b) : 0.0f;
}

// A tube as a capsule outline: its two radii's sides and a half circle round each end.
void drawCapsule(ImDrawList* draw, ImVec2 start, ImVec2 end, float startRadius, float endRadius, ImU32 color) {
    const glm::vec2 a(start.x, start.y), b(end.x, end.y);
    if (glm::distance(a, b) < 1.0f) {
        draw->AddCircle(start, std::max(startRadius, endRadius), color, 0, 1.5f);
        return;
    }
    const glm::vec2 along = glm::normalize(b - a), across(-along.y, along.x);
    auto at = [](glm::vec2 v) { return ImVec2(v.x, v.y); };
    draw->AddLine(at(a + startRadius * across), at(b + endRadius * across), color, 1.5f);
    draw->AddLine(at(a - startRadius * across), at(b - endRadius * across), color, 1.5f);
    const float angle = std::atan2(across.y, across.x);
    draw->PathArcTo(end, endRadius, angle - std::numbers::pi_v<float>, angle);
    draw->PathStroke(color, 0, 1.5f);
    draw->PathArcTo(start, startRadius, angle, angle + std::numbers::pi_v<float>);
    draw->PathStroke(color, 0, 1.5f);
}

// How far from the view's centre a directional light's arrow reaches: 1.6 units, less where the
// view shows less (zoomed in, a narrow viewport), so that its tail, the handle, stays on screen
// whichever way the light points (it used to leave the picture, out of reach).
float arrowReach(const Camera& camera, glm::vec2 viewSize) {
    const glm::vec2 centre = 0.5f * viewSize;
    const float halfHeight =
        glm::distance(unprojectAtDepthOf(camera, viewSize, {centre.x, 0.0f}, camera.target), camera.target);
    const float halfWidth =
        glm::distance(unprojectAtDepthOf(camera, viewSize, {0.0f, centre.y}, camera.target), camera.target);
    return std::min(1.6f, 0.75f * std::min(halfHeight, halfWidth));
}

glm::vec3 arrowTail(const Light& light, const Camera& camera, glm::vec2 viewSize) {
    return camera.target - arrowReach(camera, viewSize) * glm::normalize(light.direction);
}

// Where a light can be grabbed: a point's or a sphere's position, a tube's middle and ends, a
// directional light's arrow tail.
struct Grip {
    LightHandle handle;
    glm::vec3 at;
    float radius;   // of its marker, pixels
};

std::vector<Grip> gripsOf(const Light& light, const Camera& camera, glm::vec2 viewSize) {
    switch (light.type) {
    case LightType::Point:
    case LightType::Sphere: return {{LightHandle::Position, light.position, gizmoRadius()}};
    case LightType::Tube:
        return {{LightHandle::TubeStart, light.start, gizmoRadius() * 0.7f},
                {LightHandle::TubeEnd, light.end, gizmoRadius() * 0.7f},
                {LightHandle::Position, 0.5f * (light.start + light.end), gizmoRadius()}};
    case LightType::Directional:
        return {{LightHandle::Position, arrowTail(light, camera, viewSize), gizmoRadius() * 0.7f}};
    case LightType::Hemisphere:
    case LightType::Environment: break;   // everywhere at once: nothing to grab
    }
    return {};
}

// Names a light's handle for automation ("gizmo:2", "gizmo:2 start"), while it is whole on
// the picture.
void recordGrip(int index, const Light& light, const Grip& grip, ImVec2 at, ImVec2 origin, ImVec2 size) {
    const float r = grip.radius;
    if (at.x - r < origin.x || at.y - r < origin.y || at.x + r > origin.x + size.x || at.y + r > origin.y + size.y) {
        return;
    }
    const char* part = grip.handle == LightHandle::TubeStart ? " start"
                       : grip.handle == LightHandle::TubeEnd ? " end"
                                                             : "";
    const std::string tooltip = light.name + ": drag to move it";
    recordArea("gizmo:" + std::to_string(index) + part, ImVec2(at.x - r, at.y - r), ImVec2(at.x + r, at.y + r),
               tooltip.c_str());
}

// What the gizmos are drawn over: the picture on screen, its camera, and where a point of the
// scene lands on it.
struct GizmoView {
    ImVec2 origin, size;
    glm::vec2 viewSize;
    const Camera& camera;
    ImDrawList* draw;

    std::optional<ImVec2> onScreen(glm::vec3 point) const {
        const auto screen = projectToViewport(camera, viewSize, point);
        return screen ? std::optional<ImVec2>(ImVec2(origin.x + screen->x, origin.y + screen->y)) : std::nullopt;
    }
};

// The light at its size: a sphere's outline, a tube's capsule, a directional light's arrow.
void drawLightShape(const GizmoView& view, const Light& light, ImU32 color) {
    const Camera& camera = view.camera;
    if (light.type == LightType::Sphere) {
        if (const auto at = view.onScreen(light.position)) {
            view.draw->AddCircle(*at, screenRadius(camera, view.viewSize, light.position, light.sourceRadius), color,
                                 0, 1.5f);
        }
    } else if (light.type == LightType::Tube) {
        const auto a = view.onScreen(light.start), b = view.onScreen(light.end);
        if (a && b) {
            drawCapsule(view.draw, *a, *b, screenRadius(camera, view.viewSize, light.start, light.sourceRadius),
                        screenRadius(camera, view.viewSize, light.end, light.sourceRadius), color);
        }
    } else if (light.type == LightType::Directional) {
        const auto tail = view.onScreen(arrowTail(light, camera, view.viewSize));
        if (const auto tip = view.onScreen(camera.target); tail && tip) {
            view.draw->AddLine(*tail, *tip, color, 2.0f);
            view.draw->AddTriangleFilled(*tip, ImVec2(tip->x - 4, tip->y - 4), ImVec2(tip->x + 4, tip->y - 4), color);
        }
    }
}

// Light `i`'s handles, drawn; a click on one starts its drag. True when the mouse is over one.
bool drawGrips(EditorState& state, const GizmoView& view, int i, ImU32 color, bool pressed) {
    const Light& light = state.scene.lights[size_t(i)];
    const ImU32 fill = light.enabled ? color : IM_COL32(90, 90, 90, 200);
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const glm::vec2 mouseAt(mouse.x - view.origin.x, mouse.y - view.origin.y);
    bool hoveredAny = false;
    for (const Grip& grip : gripsOf(light, view.camera, view.viewSize)) {
        const auto at = view.onScreen(grip.at);
        if (!at) {
            continue;
        }
        recordGrip(i, light, grip, *at, view.origin, view.size);
        const glm::vec2 gripAt(at->x - view.origin.x, at->y - view.origin.y);
        const bool hovered = glm::distance(gripAt, mouseAt) <= grip.radius + 3.0f;
        hoveredAny |= hovered;
        view.draw->AddCircleFilled(*at, grip.radius, light.type == LightType::Directional ? color : fill);
        if (light.type != LightType::Directional) {
            view.draw->AddCircle(*at, grip.radius + 2.0f, IM_COL32(0, 0, 0, 200));
        }
        if (hovered && pressed && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            state.draggedLight = i;
            state.draggedHandle = grip.handle;
            state.selectedLight = i;
        }
    }
    return hoveredAny;
}

// The held handle follows the mouse at `local` (pixels in the picture).
void dragLight(Light& light, LightHandle handle, const Camera& camera, glm::vec2 viewSize, glm::vec2 local) {
    if (light.type == LightType::Point || light.type == LightType::Sphere) {
        light.position = unprojectAtDepthOf(camera, viewSize, local, light.position);
    } else if (light.type == LightType::Tube) {
        if (handle == LightHandle::TubeStart) {
            light.start = unprojectAtDepthOf(camera, viewSize, local, light.start);
        } else if (handle == LightHandle::TubeEnd) {
            light.end = unprojectAtDepthOf(camera, viewSize, local, light.end);
        } else {   // the middle: both ends move together
            const glm::vec3 middle = 0.5f * (light.start + light.end);
            const glm::vec3 moved = unprojectAtDepthOf(camera, viewSize, local, middle) - middle;
            light.start += moved;
            light.end += moved;
        }
    } else if (light.type == LightType::Directional) {
        // The arrow's tail follows the mouse on a sphere around the target.
        const glm::vec3 onPlane = unprojectAtDepthOf(camera, viewSize, local, camera.target);
        glm::vec3 fromTarget = onPlane - camera.target;
        const float reach = arrowReach(camera, viewSize), planar = glm::length(fromTarget);
        const glm::vec3 toCamera = glm::normalize(camera.position - camera.target);
        fromTarget += toCamera * std::sqrt(std::max(reach * reach - planar * planar, 0.0f));
        if (glm::dot(fromTarget, fromTarget) > 1e-6f) {
            light.direction = -glm::normalize(fromTarget);
        }
    }
}

// Point lights as a marker, sphere lights as their outline at their size, tube lights as a
// capsule outline with a marker at each end and one in the middle, directional lights as an
// arrow from the centre of the view; all can be dragged (a tube's ends each on their own).
// `pressed`: the viewport's button was clicked this frame (it holds the mouse from then on, so
// ImGui reports the window as not hovered). Drawn clipped to the image. Returns true while a
// gizmo is being dragged.
bool drawLightGizmos(EditorState& state, ImVec2 origin, ImVec2 size, bool pressed) {
    int& dragged = state.draggedLight;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    const GizmoView view{origin, size, glm::vec2(size.x, size.y), state.scene.camera, draw};
    bool hoveredAny = false;
    for (int i = 0; i < int(state.scene.lights.size()); ++i) {
        // The selected light in yellow; one that solo leaves out of the picture greyed out.
        const ImU32 color = i == state.selectedLight ? IM_COL32(255, 210, 80, 255)
                            : soloedOut(state, i)    ? IM_COL32(110, 110, 110, 160)
                                                     : IM_COL32(230, 230, 230, 200);
        drawLightShape(view, state.scene.lights[size_t(i)], color);
        hoveredAny |= drawGrips(state, view, i, color, pressed);
    }
    draw->PopClipRect();
    if (dragged >= 0 && dragged < int(state.scene.lights.size()) && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        // The mouse is followed only inside the picture: a handle dragged past its edge stays
        // on it, where it can be grabbed again.
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const glm::vec2 mouseAt(mouse.x - origin.x, mouse.y - origin.y);
        const glm::vec2 margin(gizmoRadius() + 2.0f);
        const glm::vec2 local = glm::clamp(mouseAt, margin, glm::max(view.viewSize - margin, margin));
        dragLight(state.scene.lights[size_t(dragged)], state.draggedHandle, view.camera, view.viewSize, local);
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

// Which material each part of the view shows, named.
void drawSideLabels(const EditorState& state, ImVec2 origin, ImVec2 size) {
    const float margin = px(8);
    const float a = state.compareView == CompareView::Split ? size.x * std::clamp(state.splitPosition, 0.0f, 1.0f)
                                                            : std::floor(size.x / 2.0f);
    sideLabel('A', *state.compareA, origin.x + margin, origin.y + margin, a - 2.0f * margin, false);
    if (state.compareView == CompareView::Split) {
        sideLabel('B', labelledMaterial(state), origin.x + size.x - margin, origin.y + margin,
                  size.x - a - 2.0f * margin, true);
    } else {
        sideLabel('B', labelledMaterial(state), origin.x + a + margin, origin.y + margin, size.x - a - 2.0f * margin,
                  false);
    }
}

void image(unsigned texture, ImVec2 size, float u0 = 0.0f, float u1 = 1.0f) {
    // Renderer textures have GL's bottom-up rows: flip v.
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)), size, ImVec2(u0, 1.0f),
                 ImVec2(u1, 0.0f));
}

// The viewport's picture on screen: where it starts, its size, in whole pixels too.
struct ViewArea {
    ImVec2 origin, size;
    int width, height;
};

// View > PBR validation overlay over one picture on screen (at, size; u1: how much of it shows
// from the left), the picture only: a channel is what was asked to be seen. The edited side's
// tally goes to the status line.
void overlayFlags(const EditorState& state, EditorServices& services, const PreparedScene& scene, int width,
                  int height, EditorServices::Shown shown, ImVec2 at, ImVec2 size, float u1 = 1.0f) {
    if (!state.pbrOverlay || state.channel.channel >= 0) {
        return;
    }
    const EditorServices::PbrOverlay& overlay = services.pbrOverlay(scene, width, height, shown);
    ImGui::GetWindowDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(overlay.texture->id())),
                                         at, ImVec2(at.x + size.x, at.y + size.y), ImVec2(0.0f, 0.0f),
                                         ImVec2(u1, 1.0f));
    if (shown == EditorServices::Shown::Edited) {
        services.pbrTally = overlay.tally;
    }
}

// The picture: B, or A and B side by side, or A over B's left part up to the divider; with
// the PBR validation overlay over each when asked.
void drawPictures(EditorState& state, EditorServices& services, const Scene& b, const ViewArea& area) {
    using Shown = EditorServices::Shown;
    // While a widget is held (a slider drag), skip MSAA so the preview keeps up; the full
    // quality frame follows on release.
    const int samples = ImGui::IsAnyItemActive() ? 1 : 4;
    const int width = area.width, height = area.height;
    const PreparedScene& preparedB = preparedScene(state, b);
    if (state.compareA && state.compareView == CompareView::SideBySide) {
        const int half = std::max(width / 2, 8);
        const ImVec2 halfSize(float(half), area.size.y);
        const Scene a = withMaterial(state, *state.compareA);
        const PreparedScene& preparedA = preparedScene(state, a);
        image(services.viewportTexture(preparedA, half, height, state.renderPath, Shown::A, samples), halfSize);
        ImGui::SameLine(0.0f, 0.0f);
        image(services.viewportTexture(preparedB, half, height, state.renderPath, Shown::Edited, samples), halfSize);
        overlayFlags(state, services, preparedA, half, height, Shown::A, area.origin, halfSize);
        overlayFlags(state, services, preparedB, half, height, Shown::Edited,
                     ImVec2(area.origin.x + float(half), area.origin.y), halfSize);
        return;
    }
    image(services.viewportTexture(preparedB, width, height, state.renderPath, Shown::Edited, samples), area.size);
    overlayFlags(state, services, preparedB, width, height, Shown::Edited, area.origin, area.size);
    if (state.compareA && state.compareView == CompareView::Split) {
        // A left of the divider, B right, one camera: A's image drawn over B's left part.
        const Scene sceneA = withMaterial(state, *state.compareA);
        const PreparedScene& preparedA = preparedScene(state, sceneA);
        const unsigned a = services.viewportTexture(preparedA, width, height, state.renderPath, Shown::A, samples);
        const float split = std::clamp(state.splitPosition, 0.0f, 1.0f);
        const ImVec2 sizeA(area.size.x * split, area.size.y);
        ImGui::SetCursorScreenPos(area.origin);
        image(a, sizeA, 0.0f, split);
        overlayFlags(state, services, preparedA, width, height, Shown::A, area.origin, sizeA, split);
    }
}

// The split view's divider, drawn and dragged; true while the pointer is on it or drags it.
bool handleDivider(EditorState& state, const ViewArea& area, bool hovered) {
    if (!state.compareA || state.compareView != CompareView::Split) {
        return false;
    }
    const float x = area.origin.x + area.size.x * state.splitPosition;
    ImGui::GetWindowDrawList()->AddLine(ImVec2(x, area.origin.y), ImVec2(x, area.origin.y + area.size.y),
                                        IM_COL32(255, 255, 255, 220), 2.0f);
    bool& draggingDivider = state.draggingDivider;
    bool onDivider = std::abs(ImGui::GetIO().MousePos.x - x) < 6.0f && hovered;
    if (onDivider && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        draggingDivider = true;
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        draggingDivider = false;
    }
    if (draggingDivider) {
        state.splitPosition = std::clamp((ImGui::GetIO().MousePos.x - area.origin.x) / area.size.x, 0.02f, 0.98f);
        onDivider = true;
    }
    if (onDivider) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    }
    return onDivider;
}

// The edited part of a model of several parts, outlined over the picture as the camera sees
// it (with the gizmos: hidden with them, and not in Side by side, whose halves differ).
void drawPartOutline(EditorState& state, const ViewArea& area) {
    if (!state.model || modelMaterialCount(state) < 2 || !state.showGizmos ||
        state.compareView == CompareView::SideBySide) {
        return;
    }
    const glm::mat4 transform = viewProjection(state.scene.camera, area.size.x / area.size.y);
    auto screen = [&](const glm::vec4& clip) {
        return ImVec2(area.origin.x + (clip.x / clip.w + 1.0f) * 0.5f * area.size.x,
                      area.origin.y + (1.0f - clip.y / clip.w) * 0.5f * area.size.y);
    };
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(area.origin, ImVec2(area.origin.x + area.size.x, area.origin.y + area.size.y), true);
    for (const auto& [a, b] : partOutline(state)) {
        const glm::vec4 clipA = transform * glm::vec4(a, 1.0f), clipB = transform * glm::vec4(b, 1.0f);
        if (clipA.w > 1e-4f && clipB.w > 1e-4f) {   // both in front of the eye
            draw->AddLine(screen(clipA), screen(clipB), IM_COL32(255, 160, 40, 230), px(1.5f));
        }
    }
    draw->PopClipRect();
}

// A left click (a press and release that did not drag) on the picture picks the model's part under
// it, in the half it falls in when Side by side.
void pickOnClick(EditorState& state, const ViewArea& area) {
    const ImGuiIO& io = ImGui::GetIO();
    // While the read-out is on a click also pins a pixel; Ctrl+click only pins it.
    if (!state.model || !ImGui::IsMouseReleased(ImGuiMouseButton_Left) || io.KeyShift ||
        (io.KeyCtrl && state.pixelReadOut) ||
        io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] > px(3.0f) * px(3.0f)) {
        return;
    }
    float x = (io.MousePos.x - area.origin.x) / area.size.x, width = area.size.x;
    if (state.compareA && state.compareView == CompareView::SideBySide) {
        x = x < 0.5f ? 2.0f * x : 2.0f * x - 1.0f;
        width *= 0.5f;
    }
    const float y = (io.MousePos.y - area.origin.y) / area.size.y;
    pickPart(state, glm::vec2(2.0f * x - 1.0f, 1.0f - 2.0f * y), width / area.size.y);
}

// The pointer over the picture: the divider first, then a light's gizmo, else the camera; a
// click picks a part; F frames the mesh.
void handlePointer(EditorState& state, EditorServices& services, const ViewArea& area) {
    ImGui::SetCursorScreenPos(area.origin);
    const bool clicked = ImGui::InvisibleButton("viewport-input", area.size,
                                                ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle |
                                                    ImGuiButtonFlags_MouseButtonRight);
    recordItem("viewport");   // the whole picture, whichever parts of it A and B show
    const bool viewportActive = ImGui::IsItemActive();
    const bool viewportPressed = ImGui::IsItemActivated();
    const bool hovered = ImGui::IsItemHovered();

    const bool onDivider = handleDivider(state, area, hovered);
    const bool gizmo = state.showGizmos && state.compareView != CompareView::SideBySide &&
                       drawLightGizmos(state, area.origin, area.size, viewportPressed);
    if (viewportActive && !gizmo && !onDivider) {
        handleCameraInput(state, area.size);
    } else if (hovered && ImGui::GetIO().MouseWheel != 0.0f) {
        dollyCamera(state.scene.camera, std::pow(0.9f, ImGui::GetIO().MouseWheel));
    }
    if (clicked && !gizmo && !onDivider) {
        pickOnClick(state, area);
    }
    if (hovered && pressed(services.keyPresses, kKeyF) &&
        !ImGui::GetIO().WantTextInput) {
        frameMesh(state);
    }
}

// An environment file being prepared: the picture keeps the one it had until then.
void drawEnvironmentProgress(const EditorState& state, const ViewArea& area) {
    if (const std::shared_ptr<EnvironmentLoad>& load = state.environmentLoad) {
        char text[160];
        std::snprintf(text, sizeof text, "Preparing the environment %s: %.0f%%", environmentName(load->source()).c_str(),
                      100.0f * load->progress());
        ImGui::GetWindowDrawList()->AddText(
            ImVec2(area.origin.x + 8, area.origin.y + area.size.y - ImGui::GetTextLineHeight() - 8),
            IM_COL32(255, 230, 150, 255), text);
    }
}

// Which channel the viewport shows instead of the picture, at its top left: data, not light.
void drawChannelLabel(const EditorState& state, const ViewArea& area) {
    if (state.channel.channel < 0) {
        return;
    }
    const std::string text = "Channel: " + channelName(state.channel) + (state.channel.srgb ? " (sRGB)" : " (values)") +
                             "   View > Channel > Picture to go back";
    ImDrawList* draw = ImGui::GetWindowDrawList();
    // Under the comparison's side labels, which take the top corners.
    const bool labelled = state.compareA && state.compareView != CompareView::Single;
    const ImVec2 at(area.origin.x + px(8), area.origin.y + px(8) + (labelled ? ImGui::GetTextLineHeight() + px(10) : 0.0f));
    draw->AddRectFilled(ImVec2(at.x - px(4), at.y - px(3)),
                        ImVec2(at.x + ImGui::CalcTextSize(text.c_str()).x + px(4), at.y + ImGui::GetTextLineHeight() + px(3)),
                        IM_COL32(0, 0, 0, 170));
    draw->AddText(at, IM_COL32(255, 220, 120, 255), text.c_str());
    recordArea("channel label", at, ImVec2(at.x + ImGui::CalcTextSize(text.c_str()).x, at.y + ImGui::GetTextLineHeight()));
}

// Overlay (Advanced): cost of the last render and what was drawn.
void drawRenderOverlay(const EditorState& state, EditorServices& services, const Scene& b, const ViewArea& area) {
    int enabled = 0;
    for (const Light& light : b.lights) {
        enabled += light.enabled;
    }
    char overlay[160];
    std::snprintf(overlay, sizeof overlay, "CPU %.1f ms  GPU %.1f ms  lights %d  %s pass",
                  services.lastRenderMilliseconds(), services.lastGpuMilliseconds(), enabled,
                  std::string(renderPathName(state.renderPath)).c_str());
    const float line = ImGui::GetTextLineHeight();
    const ImVec2 origin = area.origin, size = area.size;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(ImVec2(origin.x + px(4), origin.y + size.y - line - px(8)),
                        ImVec2(origin.x + px(12) + ImGui::CalcTextSize(overlay).x, origin.y + size.y - px(4)),
                        IM_COL32(0, 0, 0, 150));
    draw->AddText(ImVec2(origin.x + px(8), origin.y + size.y - line - px(6)), IM_COL32(220, 220, 220, 255), overlay);
}
}  // namespace

void drawViewportPanel(EditorState& state, EditorServices& services) {
    drawToolbar(state);
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
    keepChannelShowable(state);
    services.channel = state.channel;
    const Scene b = renderedScene(state);
    services.pbrTally.reset();   // set again below while the overlay or the channel shows it
    drawPictures(state, services, b, area);
    if (state.channel.channel == shader::CHANNEL_PBR_VALIDATION) {
        services.pbrTally = services.channelPbrTally(EditorServices::Shown::Edited);
    }
    drawPartOutline(state, area);
    handlePointer(state, services, area);
    if (state.compareA && state.compareView != CompareView::Single) {
        drawSideLabels(state, area.origin, area.size);
    }
    drawEnvironmentProgress(state, area);
    drawChannelLabel(state, area);
    // The read-out tells the story of the picture under the mouse: B, or A and B.
    const PreparedScene preparedB = preparedScene(state, b);
    std::optional<Scene> sceneA;   // outlives preparedA, which refers to it
    std::optional<PreparedScene> preparedA;
    std::vector<ReadOutPicture> pictures;
    const ImVec2 end(area.origin.x + area.size.x, area.origin.y + area.size.y);
    if (state.pixelReadOut && state.compareA && state.compareView != CompareView::Single) {
        sceneA = withMaterial(state, *state.compareA);
        preparedA.emplace(preparedScene(state, *sceneA));
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
    drawPixelReadOut(state, services, pictures, ImGui::IsWindowHovered() && ImGui::IsMouseHoveringRect(area.origin, end));
    if (state.showAdvanced) {
        drawRenderOverlay(state, services, b, area);
    }
}

}  // namespace patina::editor
