#include "panels/light_gizmos.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "state/editor_state.h"
#include "scene/camera_control.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
// A light's dot, at the UI's scale.
float gizmoRadius() {
    return px(7.0f);
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
bool drawGrips(const Document& document, Interaction& interaction, const GizmoView& view, int i, ImU32 color,
               bool pressed) {
    const Light& light = document.scene.lights[size_t(i)];
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
            interaction.draggedLight = i;
            interaction.draggedHandle = grip.handle;
            interaction.selectedLight = i;
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

}  // namespace

// Point lights as a marker, sphere lights as their outline at their size, tube lights as a
// capsule outline with a marker at each end and one in the middle, directional lights as an
// arrow from the centre of the view; all can be dragged (a tube's ends each on their own).
// `pressed`: the viewport's button was clicked this frame (it holds the mouse from then on, so
// ImGui reports the window as not hovered). Drawn clipped to the image. Returns true while a
// gizmo is being dragged.
bool drawLightGizmos(Document& document, Interaction& interaction, ImVec2 origin, ImVec2 size, bool pressed) {
    int& dragged = interaction.draggedLight;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    const GizmoView view{origin, size, glm::vec2(size.x, size.y), document.scene.camera, draw};
    bool hoveredAny = false;
    for (int i = 0; i < int(document.scene.lights.size()); ++i) {
        // The selected light in yellow; one that solo leaves out of the picture greyed out.
        const ImU32 color = i == interaction.selectedLight ? IM_COL32(255, 210, 80, 255)
                            : soloedOut(document, interaction, i)    ? IM_COL32(110, 110, 110, 160)
                                                     : IM_COL32(230, 230, 230, 200);
        drawLightShape(view, document.scene.lights[size_t(i)], color);
        hoveredAny |= drawGrips(document, interaction, view, i, color, pressed);
    }
    draw->PopClipRect();
    if (dragged >= 0 && dragged < int(document.scene.lights.size()) && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        // The mouse is followed only inside the picture: a handle dragged past its edge stays
        // on it, where it can be grabbed again.
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const glm::vec2 mouseAt(mouse.x - origin.x, mouse.y - origin.y);
        const glm::vec2 margin(gizmoRadius() + 2.0f);
        const glm::vec2 local = glm::clamp(mouseAt, margin, glm::max(view.viewSize - margin, margin));
        dragLight(document.scene.lights[size_t(dragged)], interaction.draggedHandle, view.camera, view.viewSize, local);
        return true;
    }
    dragged = -1;
    if (hoveredAny) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
    }
    return hoveredAny;
}

}  // namespace patina::editor
