#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <numbers>

#include <glm/glm.hpp>
#include <imgui.h>

#include "common/luminance.h"
#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "views/lobe_plot.h"
#include "panels/lobe_views.h"
#include "panels/panels.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
// theta_in from the first enabled directional light, seen from the camera: the angle between
// L and the normal that faces the viewer.
std::optional<float> followedThetaIn(const Document& document) {
    for (const Light& light : document.scene.lights) {
        if (light.type == LightType::Directional && light.enabled) {
            const glm::vec3 toCamera = glm::normalize(document.scene.camera.position - document.scene.camera.target);
            const glm::vec3 L = -glm::normalize(light.direction);
            return glm::degrees(std::acos(glm::clamp(glm::dot(L, toCamera), -1.0f, 1.0f)));
        }
    }
    return std::nullopt;
}

// Polar plot in the plane of incidence: angle theta_out from the normal (up), radius = value;
// the angles and the outer ring's value labelled, a legend in the top left corner.
void drawPolar(const LobePlot& plot, const LobeSettings& lobe, ImVec2 size) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float line = ImGui::GetTextLineHeight();
    const ImVec2 centre(origin.x + size.x * 0.5f, origin.y + size.y - line - px(6));
    const float margin = ImGui::CalcTextSize("+90").x + px(8);   // the angle labels beside the ends
    const float radius = std::max(std::min(size.x * 0.5f - margin, size.y - line - px(12)), px(10));
    const ImU32 label = IM_COL32(170, 170, 180, 255);
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(20, 20, 24, 255));
    draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    for (float ring : {0.25f, 0.5f, 0.75f, 1.0f}) {
        draw->PathArcTo(centre, radius * ring, -std::numbers::pi_v<float>, 0.0f, 48);
        draw->PathStroke(IM_COL32(70, 70, 80, 255), 0, 1.0f);
    }
    draw->AddLine(ImVec2(centre.x - radius, centre.y), ImVec2(centre.x + radius, centre.y), IM_COL32(120, 120, 130, 255));
    // Axis labels: theta_out at the ends and the normal, the outer ring's value.
    auto text = [&](ImVec2 at, const char* what) { draw->AddText(at, label, what); };
    text(ImVec2(centre.x - radius - ImGui::CalcTextSize("-90").x - px(4), centre.y - line * 0.5f), "-90");
    text(ImVec2(centre.x + radius + px(4), centre.y - line * 0.5f), "+90");
    text(ImVec2(centre.x - ImGui::CalcTextSize("theta_out").x * 0.5f, centre.y + px(2)), "theta_out");
    char outer[64];
    std::snprintf(outer, sizeof outer, lobe.logScale ? "%.3g /sr (log, 3 decades)" : "%.3g /sr", double(plot.maxValue));
    // By the outer ring's 45 degrees, moved left as far as a long value needs to stay inside.
    const float outerX = std::min(centre.x + radius * 0.71f + px(2), origin.x + size.x - ImGui::CalcTextSize(outer).x - px(4));
    const ImVec2 outerAt(outerX, centre.y - radius * 0.71f - line);
    text(outerAt, outer);
    recordArea("lobe:outer value", outerAt, ImVec2(outerAt.x + ImGui::CalcTextSize(outer).x, outerAt.y + line),
               "The outer ring's value: the largest value plotted, in 1/sr");
    const float inRadians = glm::radians(lobe.thetaInDegrees);
    draw->AddLine(centre, ImVec2(centre.x + radius * std::sin(inRadians), centre.y - radius * std::cos(inRadians)),
                  IM_COL32(255, 220, 90, 255), 1.5f);
    for (const LobeCurve& curve : plot.curves) {
        for (size_t i = 0; i < curve.values.size(); ++i) {
            const float theta = glm::radians(-90.0f + 180.0f * float(i) / float(curve.values.size() - 1));
            const float r = radius * lobeRadius(curve.values[i], plot.maxValue, lobe.logScale);
            draw->PathLineTo(ImVec2(centre.x + r * std::sin(theta), centre.y - r * std::cos(theta)));
        }
        draw->PathStroke(curve.color, 0, curve.thickness);
    }
    // The legend: a short line in each curve's colour and what it is.
    ImVec2 at(origin.x + px(6), origin.y + px(4));
    auto entry = [&](ImU32 color, float thickness, const char* what) {
        draw->AddLine(ImVec2(at.x, at.y + line * 0.5f), ImVec2(at.x + px(16), at.y + line * 0.5f), color,
                      std::max(thickness, 1.5f));
        draw->AddText(ImVec2(at.x + px(20), at.y), label, what);
        at.y += line;
    };
    entry(IM_COL32(255, 220, 90, 255), 1.5f, "light (theta_in)");
    for (const LobeCurve& curve : plot.curves) {
        if (!curve.legend.empty()) {
            entry(curve.legendColor, curve.thickness, curve.legend.c_str());
        }
    }
    draw->PopClipRect();
    ImGui::Dummy(size);
}
}  // namespace

namespace {
// Which of the panel's views shows: the polar plot or one of BRDF Explorer's.
void drawViewChoice(LobeSettings& lobe) {
    const std::pair<LobeView, const char*> views[] = {
        {LobeView::Polar, "Polar"}, {LobeView::Slice, "Slice"}, {LobeView::Albedo, "Albedo"}, {LobeView::Lobe3d, "3D"}};
    const char* tips[] = {"The BRDF in the plane of incidence, and D, G, F",
                          "BRDF Explorer's image slice: theta_h across, theta_d up, at phi_d (Burley 2012)",
                          "Directional albedo against theta_v: the split sum against the ground truth",
                          "The lobe over every outgoing direction; drag to turn it"};
    for (size_t i = 0; i < std::size(views); ++i) {
        if (i > 0) {
            ImGui::SameLine();
        }
        if (ImGui::RadioButton(views[i].second, lobe.view == views[i].first)) {
            lobe.view = views[i].first;
        }
        recordItem(std::string("lobe view:") + views[i].second, tips[i]);
    }
}

// The slice's settings: phi_d, exposure, log scale, which lobe.
void drawSliceControls(LobeSettings& lobe) {
    ImGui::SetNextItemWidth(px(130));
    ImGui::SliderFloat("phi_d", &lobe.phiDDegrees, 0.0f, 180.0f, "%.0f deg");
    recordItem("phi_d", "The difference angle's azimuth about H; 90 keeps both directions above the horizon");
    sameLineIfFits(labelledWidth(px(110), "Exposure"));
    ImGui::SetNextItemWidth(px(110));
    ImGui::SliderFloat("Exposure", &lobe.sliceExposure, -8.0f, 8.0f, "%+.1f EV");
    recordItem("slice exposure", "Scale the values by 2^EV before they are shown");
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Log"));
    ImGui::Checkbox("Log##slice", &lobe.sliceLog);
    recordItem("slice log", "Log scale: four decades, 0.01 to 100 1/sr");
    sameLineIfFits(labelledWidth(px(110), "Lobe"));
    ImGui::SetNextItemWidth(px(110));
    ImGui::Combo("Lobe", &lobe.sliceLobe, "total\0diffuse\0specular\0transmitted\0");
    recordItem("slice lobe", "Which part of f the slice shows: the reflected light's, or a thin wall's transmitted "
                             "lobe below the surface (KHR_materials_transmission), theta_h that of the mirrored "
                             "direction's half vector");
}
}  // namespace

void drawLobePanel(const Document& document, Interaction& interaction, EditorServices& services) {
    LobeSettings& lobe = interaction.lobe;
    drawViewChoice(lobe);
    if (lobe.view == LobeView::Slice) {
        drawSliceControls(lobe);
        drawSliceView(document, interaction, ImGui::GetContentRegionAvail());
        return;
    }
    if (lobe.view == LobeView::Albedo) {
        drawAlbedoView(document, interaction, services, ImGui::GetContentRegionAvail());
        return;
    }
    const ImGuiStyle& style = ImGui::GetStyle();
    auto checkboxWidth = [&](const char* label) { return labelledWidth(ImGui::GetFrameHeight(), label); };
    ImGui::Checkbox("Follow first directional light", &lobe.followFirstDirectional);
    recordItem("Follow light", "theta_in from the first directional light, as seen from the camera");
    const std::optional<float> followed = lobe.followFirstDirectional ? followedThetaIn(document) : std::nullopt;
    if (followed) {
        lobe.thetaInDegrees = std::min(*followed, 89.9f);
    }
    sameLineIfFits(labelledWidth(px(160), "theta_in"));
    ImGui::BeginDisabled(followed.has_value());
    ImGui::SetNextItemWidth(px(160));
    ImGui::SliderFloat("theta_in", &lobe.thetaInDegrees, 0.0f, 89.9f, "%.1f deg");
    recordItem("theta_in", "The angle the light comes in at, from the normal");
    ImGui::EndDisabled();
    if (lobe.view == LobeView::Polar) {   // the 3D lobe is luminance
        sameLineIfFits(checkboxWidth("Luminance"));
        ImGui::Checkbox("Luminance", &lobe.luminance);
        recordItem("Luminance", "Diffuse, specular and total as luminance, instead of per colour channel");
    }
    sameLineIfFits(checkboxWidth("Log"));
    ImGui::Checkbox("Log", &lobe.logScale);
    recordItem("Log", "Log scale: three decades below the peak, to see the tails");
    sameLineIfFits(checkboxWidth("x cos"));
    ImGui::Checkbox("x cos", &lobe.multiplyByCosine);
    recordItem("x cos", "Multiply by cos(theta_in): the light the surface actually reflects");

    if (lobe.view == LobeView::Lobe3d) {
        drawLobe3dView(document, interaction, ImGui::GetContentRegionAvail());
        return;
    }
    const LobePlot plot = lobePlot(document, interaction);
    const float termsWidth = px(220);
    const ImVec2 available = ImGui::GetContentRegionAvail();
    drawPolar(plot, lobe, ImVec2(std::max(available.x - termsWidth - style.ItemSpacing.x, px(80)),
                                 std::max(available.y, px(60))));
    recordItem("lobe");
    ImGui::SameLine();

    // The three specular terms against theta_out, from the shared code.
    ImGui::BeginGroup();
    const Material edited = editedMaterial(document, interaction);
    const shader::SurfaceMaterial m = surfaceMaterialInLobeFrame(edited);
    const float inRadians = glm::radians(lobe.thetaInDegrees);
    const glm::vec3 N(0, 0, 1), L(std::sin(inRadians), 0, std::cos(inRadians));
    float d[kLobeSamples], g[kLobeSamples], f[kLobeSamples];
    for (int i = 0; i < kLobeSamples; ++i) {
        const float out = glm::radians(-90.0f + 180.0f * float(i) / float(kLobeSamples - 1));
        const glm::vec3 V(std::sin(out), 0, std::cos(out));
        const shader::SpecularTerms t = specularTerms(edited.model, m, N, V, L);
        const float NoV = std::max(glm::dot(N, V), shader::MIN_N_DOT_V), NoL = std::max(glm::dot(N, L), 0.0f);
        d[i] = t.D;
        g[i] = t.Vis * 4.0f * NoL * NoV;   // G = V * 4 NoL NoV
        f[i] = luminance(t.F);
    }
    const float plotHeight = std::max((available.y - 3 * ImGui::GetTextLineHeightWithSpacing()) / 3.0f, px(20));
    ImGui::PlotLines("##D", d, kLobeSamples, 0, "D", 0.0f, FLT_MAX, ImVec2(termsWidth, plotHeight));
    recordItem("D plot", "D, the distribution of microfacet normals, against theta_out from -90 to 90");
    ImGui::PlotLines("##G", g, kLobeSamples, 0, "G", 0.0f, 1.0f, ImVec2(termsWidth, plotHeight));
    recordItem("G plot", "G, the microfacets' shadowing and masking (0 to 1), against theta_out");
    ImGui::PlotLines("##F", f, kLobeSamples, 0, "F", 0.0f, 1.0f, ImVec2(termsWidth, plotHeight));
    recordItem("F plot", "F, the Fresnel reflectance (0 to 1, luminance), against theta_out");
    ImGui::EndGroup();
}

}  // namespace patina::editor
