#include "panels/lobe_views.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/glm.hpp>

#include "common/luminance.h"
#include "views/lobe_plot.h"
#include "shading/brdf_slice.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
constexpr int kSliceSize = 48;   // cells a side: a rectangle each, so no texture to keep
const ImU32 kLabel = IM_COL32(170, 170, 180, 255);

ImU32 colourOf(glm::vec3 shown) {
    return IM_COL32(int(shown.r * 255.0f + 0.5f), int(shown.g * 255.0f + 0.5f), int(shown.b * 255.0f + 0.5f), 255);
}

// One slice at `at`, `side` pixels square, its caption above, axes labelled; the hovered cell's
// angles and f in a tooltip.
void drawSlice(const BrdfSlice& slice, const LobeSettings& lobe, ImVec2 at, float side, const char* caption) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float cell = side / float(slice.size), line = ImGui::GetTextLineHeight();
    draw->AddText(ImVec2(at.x, at.y - line - px(2)), kLabel, caption);
    for (int y = 0; y < slice.size; ++y) {
        for (int x = 0; x < slice.size; ++x) {
            const glm::vec3 f = slice.at(x, y);
            const ImU32 colour = f.x < 0.0f ? IM_COL32(30, 30, 40, 255)
                                            : colourOf(sliceShown(f, lobe.sliceExposure, lobe.sliceLog));
            const ImVec2 min(at.x + float(x) * cell, at.y + float(y) * cell);
            draw->AddRectFilled(min, ImVec2(min.x + cell + 0.5f, min.y + cell + 0.5f), colour);
        }
    }
    draw->AddText(ImVec2(at.x, at.y + side + px(1)), kLabel, "0");
    const char* across = "theta_h ->";
    draw->AddText(ImVec2(at.x + (side - ImGui::CalcTextSize(across).x) * 0.5f, at.y + side + px(1)), kLabel, across);
    draw->AddText(ImVec2(at.x + side - ImGui::CalcTextSize("90").x, at.y + side + px(1)), kLabel, "90");
    draw->AddText(ImVec2(at.x - ImGui::CalcTextSize("90").x - px(3), at.y), kLabel, "90");
    draw->AddText(ImVec2(at.x - ImGui::CalcTextSize("td").x - px(3), at.y + side * 0.5f - line * 0.5f), kLabel, "td");
    if (ImGui::IsMouseHoveringRect(at, ImVec2(at.x + side, at.y + side))) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const int x = std::clamp(int((mouse.x - at.x) / cell), 0, slice.size - 1);
        const int y = std::clamp(int((mouse.y - at.y) / cell), 0, slice.size - 1);
        const glm::vec2 angles = sliceAngles(x, y, slice.size);
        const glm::vec3 f = slice.at(x, y);
        if (f.x < 0.0f) {
            ImGui::SetTooltip("theta_h %.1f  theta_d %.1f deg\nL or V below the horizon", double(angles.x),
                              double(angles.y));
        } else {
            ImGui::SetTooltip("theta_h %.1f  theta_d %.1f deg\nf = (%.4g, %.4g, %.4g) /sr", double(angles.x),
                              double(angles.y), double(f.r), double(f.g), double(f.b));
        }
    }
}

}  // namespace

namespace {
// The edited material's slice caption: what the axes are, and for a thin wall's transmission
// (KHR_materials_transmission) that its lobe below the surface is a slice of its own.
std::string sliceCaption(const Material& material, SliceLobe which, bool compared) {
    std::string caption = compared ? "B" : "theta_h across, theta_d up (degrees)";
    if (which == SliceLobe::Transmitted) {
        caption += material.transmission > 0.0f ? "; transmitted: H of L and V mirrored below"
                                                : "; no transmission";
    } else if (material.transmission > 0.0f) {
        caption += compared ? "" : "; set Lobe to transmitted to see the light through the wall";
    }
    return caption;
}
}  // namespace

void drawSliceView(const Document& document, const Interaction& interaction, ImVec2 size) {
    const LobeSettings& lobe = interaction.lobe;
    const SliceLobe which = SliceLobe(std::clamp(lobe.sliceLobe, 0, 3));
    const float line = ImGui::GetTextLineHeight();
    const int count = interaction.compareA ? 2 : 1;
    const float margin = ImGui::CalcTextSize("90").x + px(8);
    const float side = std::max(std::min((size.x - margin * float(count)) / float(count) - px(8), size.y - 2.0f * line - px(8)),
                                px(32));
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(20, 20, 24, 255));
    ImVec2 at(origin.x + margin, origin.y + line + px(4));
    if (interaction.compareA) {
        drawSlice(brdfSlice(*interaction.compareA, lobe.phiDDegrees, kSliceSize, which), lobe, at, side, "A");
        at.x += side + margin + px(8);
    }
    const Material edited = editedMaterial(document, interaction);
    drawSlice(brdfSlice(edited, lobe.phiDDegrees, kSliceSize, which), lobe, at, side,
              sliceCaption(edited, which, bool(interaction.compareA)).c_str());
    ImGui::Dummy(size);
    recordItem("slice");   // no tooltip of its own: the hovered cell's values are the tooltip
}

namespace {
struct AlbedoShown {
    const std::vector<AlbedoPoint>* curve;
    ImU32 colour;
    const char* name;
};

bool transmits(const std::vector<AlbedoPoint>& curve) {
    return std::any_of(curve.begin(), curve.end(),
                       [](const AlbedoPoint& p) { return p.productTransmitted != glm::vec3(0.0f); });
}

// A transmitting material's transmitted albedo (KHR_materials_transmission, the part of the
// split sum through the wall) as a thin line under its curve; nothing without a transmission.
template <typename ToScreen>
void drawTransmittedAlbedo(ImDrawList* draw, const AlbedoShown& s, ToScreen toScreen) {
    if (!transmits(*s.curve)) {
        return;
    }
    for (const AlbedoPoint& p : *s.curve) {
        draw->PathLineTo(toScreen(p.thetaVDegrees, luminance(p.productTransmitted)));
    }
    draw->PathStroke(s.colour & 0xA0FFFFFFu, 0, 1.0f);
}

// The legend's rows above the plot from `at`: each curve's colour and what it draws.
void drawAlbedoLegend(ImDrawList* draw, const std::vector<AlbedoShown>& shown, ImVec2 at, float line) {
    for (const AlbedoShown& s : shown) {
        char text[160];
        std::snprintf(text, sizeof text, "%s%ssplit sum (line)%s, single-scattering truth +- 1 s.e. (circles)", s.name,
                      *s.name ? ": " : "", transmits(*s.curve) ? ", transmitted share (thin)" : "");
        draw->AddLine(ImVec2(at.x, at.y + line * 0.5f), ImVec2(at.x + px(16), at.y + line * 0.5f), s.colour, 2.0f);
        draw->AddText(ImVec2(at.x + px(20), at.y), kLabel, text);
        at.y += line;
    }
}
}  // namespace

void drawAlbedoView(const Document& document, const Interaction& interaction, EditorServices& services, ImVec2 size) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float line = ImGui::GetTextLineHeight();
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(20, 20, 24, 255));
    using Shown = AlbedoShown;
    std::vector<Shown> shown;
    if (interaction.compareA) {
        shown.push_back({&services.albedo(*interaction.compareA), IM_COL32(170, 170, 170, 255), "A"});
    }
    shown.push_back({&services.albedo(editedMaterial(document, interaction)), IM_COL32(255, 170, 80, 255),
                     interaction.compareA ? "B" : ""});
    // Luminance; a bar is the luminance of the channels' standard errors, which bounds its own.
    float top = 1.0f;
    for (const Shown& s : shown) {
        for (const AlbedoPoint& p : *s.curve) {
            top = std::max({top, luminance(p.product), luminance(p.truth) + luminance(p.standardError)});
        }
    }
    top *= 1.05f;
    // The legend in its own rows above the plot, so it never covers a curve.
    const float legendHeight = float(shown.size()) * line + px(4);
    const ImVec2 plotMin(origin.x + ImGui::CalcTextSize("0.00").x + px(10), origin.y + legendHeight + line * 0.5f + px(4));
    const ImVec2 plotMax(origin.x + size.x - px(8), origin.y + size.y - line - px(8));
    auto toScreen = [&](float thetaV, float value) {
        return ImVec2(plotMin.x + (plotMax.x - plotMin.x) * thetaV / 90.0f,
                      plotMax.y - (plotMax.y - plotMin.y) * value / top);
    };
    for (float tick : {0.0f, 0.5f, 1.0f}) {
        const ImVec2 at = toScreen(0.0f, tick);
        draw->AddLine(at, ImVec2(plotMax.x, at.y), IM_COL32(60, 60, 70, 255));
        char text[16];
        std::snprintf(text, sizeof text, "%.2f", double(tick));
        draw->AddText(ImVec2(origin.x + px(4), at.y - line * 0.5f), kLabel, text);
    }
    draw->AddText(ImVec2(plotMin.x, plotMax.y + px(4)), kLabel, "0");
    const char* axis = "theta_v (degrees)";
    draw->AddText(ImVec2((plotMin.x + plotMax.x - ImGui::CalcTextSize(axis).x) * 0.5f, plotMax.y + px(4)), kLabel, axis);
    draw->AddText(ImVec2(plotMax.x - ImGui::CalcTextSize("90").x, plotMax.y + px(4)), kLabel, "90");
    for (const Shown& s : shown) {
        for (const AlbedoPoint& p : *s.curve) {
            draw->PathLineTo(toScreen(p.thetaVDegrees, luminance(p.product)));
        }
        draw->PathStroke(s.colour, 0, 2.0f);
        drawTransmittedAlbedo(draw, s, toScreen);
        for (const AlbedoPoint& p : *s.curve) {
            const float value = luminance(p.truth), error = luminance(p.standardError);
            const ImVec2 low = toScreen(p.thetaVDegrees, value - error), high = toScreen(p.thetaVDegrees, value + error);
            draw->AddLine(low, high, IM_COL32(255, 255, 255, 220), 1.0f);
            draw->AddLine(ImVec2(low.x - px(3), low.y), ImVec2(low.x + px(3), low.y), IM_COL32(255, 255, 255, 220));
            draw->AddLine(ImVec2(high.x - px(3), high.y), ImVec2(high.x + px(3), high.y), IM_COL32(255, 255, 255, 220));
            draw->AddCircle(toScreen(p.thetaVDegrees, value), px(3), s.colour, 8, 1.5f);
        }
    }
    drawAlbedoLegend(draw, shown, ImVec2(plotMin.x, origin.y + px(4)), line);
    ImGui::Dummy(size);
    recordItem("albedo", "Directional albedo (luminance) against theta_v under a white furnace: the split sum's tables "
                         "(with their multiple scattering) against the ground truth's Monte Carlo estimate of the "
                         "single-scattering BRDF; the gap grows with roughness and a stretched lobe");
    if (ImGui::IsItemHovered()) {
        const std::vector<AlbedoPoint>& curve = *shown.back().curve;
        const float thetaV = std::clamp((ImGui::GetIO().MousePos.x - plotMin.x) / (plotMax.x - plotMin.x), 0.0f, 1.0f) * 90.0f;
        const AlbedoPoint& p = *std::min_element(curve.begin(), curve.end(), [&](const AlbedoPoint& a, const AlbedoPoint& b) {
            return std::abs(a.thetaVDegrees - thetaV) < std::abs(b.thetaVDegrees - thetaV);
        });
        ImGui::SetTooltip("theta_v %.1f deg\nsplit sum %.4f\nground truth %.4f +- %.4f\ntransmitted: split sum %.4f, "
                          "ground truth %.4f",
                          double(p.thetaVDegrees), double(luminance(p.product)), double(luminance(p.truth)),
                          double(luminance(p.standardError)), double(luminance(p.productTransmitted)),
                          double(luminance(p.truthTransmitted)));
    }
}

namespace {
const ImU32 kTransmittedColour = IM_COL32(120, 230, 140, 220);   // the polar plot's transmitted green

// One lobe's grid (Lobe3d's ring-major points) as rings and every other meridian.
template <typename Project>
void drawLobeMesh(ImDrawList* draw, const std::vector<glm::vec3>& points, ImU32 colour, Project project) {
    auto at = [&](int ring, int meridian) {
        return project(points[size_t(ring * kLobeMeridians + meridian % kLobeMeridians)]);
    };
    for (int ring = 1; ring < kLobeRings; ++ring) {
        for (int m = 0; m <= kLobeMeridians; ++m) {
            draw->PathLineTo(at(ring, m));
        }
        draw->PathStroke(colour, 0, 1.0f);
    }
    for (int m = 0; m < kLobeMeridians; m += 2) {
        for (int ring = 0; ring < kLobeRings; ++ring) {
            draw->PathLineTo(at(ring, m));
        }
        draw->PathStroke(colour, 0, 1.0f);
    }
}

// The line above the 3D view: which colour is which, and the scale.
void drawLobe3dLegend(ImDrawList* draw, ImVec2 at, const std::vector<Lobe3d>& lobes, const Interaction& interaction) {
    const bool transmits = std::any_of(lobes.begin(), lobes.end(), [](const Lobe3d& l) { return !l.transmitted.empty(); });
    char text[256];
    std::snprintf(text, sizeof text, "%s%s%.3g /sr at the largest%s", interaction.compareA ? "B orange, A grey; " : "",
                  transmits ? "green: transmitted, below the surface; " : "", double(lobes.front().maxValue),
                  interaction.lobe.logScale ? " (log, 3 decades)" : "");
    draw->AddText(at, kLabel, text);
    // A smooth lobe's peak falls between the grid's directions: said on a line of its own, so the
    // scale is not read as the peak.
    if (lobes.front().peak > 2.0f * lobes.front().maxValue) {
        std::snprintf(text, sizeof text, "the mirror peak, %.3g /sr, lies between the drawn directions",
                      double(lobes.front().peak));
        draw->AddText(ImVec2(at.x, at.y + ImGui::GetTextLineHeight()), kLabel, text);
    }
}
}  // namespace

void drawLobe3dView(const Document& document, Interaction& interaction, ImVec2 size) {
    LobeSettings& lobe = interaction.lobe;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("lobe3d", size);
    recordItem("lobe 3d", "The lobe over every outgoing direction for theta_in, and a transmitting material's lobe "
                          "through the wall below the surface (green); drag to turn it");
    if (ImGui::IsItemActive()) {
        const ImVec2 delta = ImGui::GetIO().MouseDelta;
        lobe.yawDegrees = std::fmod(lobe.yawDegrees + delta.x * 0.5f, 360.0f);
        lobe.pitchDegrees = std::clamp(lobe.pitchDegrees + delta.y * 0.5f, -10.0f, 89.0f);
    }
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(20, 20, 24, 255));
    draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    const std::vector<Lobe3d> lobes = lobes3d(document, interaction);
    const bool transmits = std::any_of(lobes.begin(), lobes.end(), [](const Lobe3d& l) { return !l.transmitted.empty(); });
    const float yaw = glm::radians(lobe.yawDegrees), pitch = glm::radians(lobe.pitchDegrees);
    // Fit the unit hemisphere seen at this pitch: up to cos + |sin| above the centre (the
    // normal's tip leaning back), |sin| below it (the horizon's near edge), or the whole unit
    // sphere's 1 with a lobe below the surface; a text line on top.
    const float line = ImGui::GetTextLineHeight();
    const float above = std::cos(pitch) + std::abs(std::sin(pitch));
    const float below = transmits ? 1.0f : std::abs(std::sin(pitch));
    const float scale = std::max(std::min(size.x * 0.45f, (size.y - line - px(12)) / (above + below)), px(8));
    const ImVec2 centre(origin.x + size.x * 0.5f, origin.y + line + px(6) + scale * above);
    // Orthographic, turned by yaw about the normal and tilted by pitch towards the viewer.
    auto project = [&](glm::vec3 p) {
        const float x = p.x * std::cos(yaw) - p.y * std::sin(yaw), depth = p.x * std::sin(yaw) + p.y * std::cos(yaw);
        return ImVec2(centre.x + scale * x, centre.y - scale * (p.z * std::cos(pitch) + depth * std::sin(pitch)));
    };
    for (int i = 0; i <= 48; ++i) {   // the horizon
        const float a = glm::radians(7.5f * float(i));
        draw->PathLineTo(project(glm::vec3(std::cos(a), std::sin(a), 0.0f)));
    }
    draw->PathStroke(IM_COL32(70, 70, 80, 255), 0, 1.0f);
    draw->AddLine(project(glm::vec3(0.0f)), project(glm::vec3(0.0f, 0.0f, 1.0f)), IM_COL32(120, 120, 130, 255));
    const float thetaIn = glm::radians(lobe.thetaInDegrees);
    draw->AddLine(project(glm::vec3(0.0f)), project(glm::vec3(std::sin(thetaIn), 0.0f, std::cos(thetaIn))),
                  IM_COL32(255, 220, 90, 255), 1.5f);
    for (size_t l = lobes.size(); l-- > 0;) {   // B last, on top
        const ImU32 colour = l == 0 ? IM_COL32(255, 170, 80, 220) : IM_COL32(170, 170, 170, 150);
        drawLobeMesh(draw, lobes[l].points, colour, project);
        if (!lobes[l].transmitted.empty()) {
            drawLobeMesh(draw, lobes[l].transmitted, l == 0 ? kTransmittedColour : colour, project);
        }
    }
    drawLobe3dLegend(draw, ImVec2(origin.x + px(6), origin.y + px(4)), lobes, interaction);
    draw->PopClipRect();
}

}  // namespace patina::editor
