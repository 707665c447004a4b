#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <imgui.h>

#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "shading/lobe.h"
#include "panels.h"
#include "widgets.h"

namespace patina::editor {

namespace {
constexpr int kSamples = 181;

// Rec. 709 luminance of linear RGB.
float luminance(glm::vec3 c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

// theta_in from the first enabled directional light, seen from the camera: the angle between
// L and the normal that faces the viewer.
std::optional<float> followedThetaIn(const EditorState& state) {
    for (const Light& light : state.scene.lights) {
        if (light.type == LightType::Directional && light.enabled) {
            const glm::vec3 toCamera = glm::normalize(state.scene.camera.position - state.scene.camera.target);
            const glm::vec3 L = -glm::normalize(light.direction);
            return glm::degrees(std::acos(glm::clamp(glm::dot(L, toCamera), -1.0f, 1.0f)));
        }
    }
    return std::nullopt;
}

struct Curve {
    std::vector<float> values;   // one per lobe sample, already scaled for the plot
    ImU32 color;
    float thickness;
};

// Polar plot in the plane of incidence: angle theta_out from the normal (up), radius = value.
void drawPolar(const std::vector<Curve>& curves, float maxValue, float thetaIn, ImVec2 size) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 centre(origin.x + size.x * 0.5f, origin.y + size.y - 8.0f);
    const float radius = std::min(size.x * 0.5f, size.y) - 12.0f;
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(20, 20, 24, 255));
    for (float ring : {0.25f, 0.5f, 0.75f, 1.0f}) {
        draw->PathArcTo(centre, radius * ring, -3.14159265f, 0.0f, 48);
        draw->PathStroke(IM_COL32(70, 70, 80, 255), 0, 1.0f);
    }
    draw->AddLine(ImVec2(centre.x - radius, centre.y), ImVec2(centre.x + radius, centre.y), IM_COL32(120, 120, 130, 255));
    const float inRadians = glm::radians(thetaIn);
    draw->AddLine(centre, ImVec2(centre.x + radius * std::sin(inRadians), centre.y - radius * std::cos(inRadians)),
                  IM_COL32(255, 220, 90, 255), 1.5f);
    for (const Curve& curve : curves) {
        for (size_t i = 0; i < curve.values.size(); ++i) {
            const float theta = glm::radians(-90.0f + 180.0f * float(i) / float(curve.values.size() - 1));
            const float r = radius * std::clamp(curve.values[i] / maxValue, 0.0f, 1.0f);
            draw->PathLineTo(ImVec2(centre.x + r * std::sin(theta), centre.y - r * std::cos(theta)));
        }
        draw->PathStroke(curve.color, 0, curve.thickness);
    }
    ImGui::Dummy(size);
}
}  // namespace

void drawLobePanel(EditorState& state) {
    LobeSettings& lobe = state.lobe;
    ImGui::Checkbox("Follow first directional light", &lobe.followFirstDirectional);
    const std::optional<float> followed = lobe.followFirstDirectional ? followedThetaIn(state) : std::nullopt;
    if (followed) {
        lobe.thetaInDegrees = std::min(*followed, 89.9f);
    }
    ImGui::SameLine();
    ImGui::BeginDisabled(followed.has_value());
    ImGui::SetNextItemWidth(160);
    ImGui::SliderFloat("theta_in", &lobe.thetaInDegrees, 0.0f, 89.9f, "%.1f deg");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::Checkbox("Luminance", &lobe.luminance);
    ImGui::SameLine();
    ImGui::Checkbox("Log", &lobe.logScale);
    ImGui::SameLine();
    ImGui::Checkbox("x cos", &lobe.multiplyByCosine);

    const std::vector<LobeSample> samples = evaluateLobe(state.scene.material, lobe.thetaInDegrees, kSamples);
    const std::vector<LobeSample> aSamples =
        state.compareA ? evaluateLobe(*state.compareA, lobe.thetaInDegrees, kSamples) : std::vector<LobeSample>{};
    const float cosIn = std::cos(glm::radians(lobe.thetaInDegrees));
    // Log scale maps [1e-3 max, max] onto the radius: 3 decades.
    auto scaled = [&](float value, float maxValue) {
        value *= lobe.multiplyByCosine ? cosIn : 1.0f;
        return lobe.logScale ? std::max(0.0f, std::log10(std::max(value, 1e-12f) / maxValue) + 3.0f) / 3.0f * maxValue
                             : value;
    };
    float maxValue = 1e-6f;
    for (const LobeSample& s : samples) {
        const glm::vec3 t = s.total() * (lobe.multiplyByCosine ? cosIn : 1.0f);
        maxValue = std::max({maxValue, t.r, t.g, t.b});
    }
    auto curve = [&](const std::vector<LobeSample>& from, auto pick, ImU32 color, float thickness) {
        Curve c{{}, color, thickness};
        for (const LobeSample& s : from) {
            c.values.push_back(scaled(pick(s), maxValue));
        }
        return c;
    };
    std::vector<Curve> curves;
    if (!aSamples.empty()) {
        curves.push_back(curve(aSamples, [](const LobeSample& s) { return luminance(s.total()); },
                               IM_COL32(160, 160, 160, 160), 3.0f));
    }
    // The same material under the reference model, for what the current model gets wrong.
    if (state.scene.material.model != BrdfModelId::Reference) {
        Material reference = state.scene.material;
        reference.model = BrdfModelId::Reference;
        curves.push_back(curve(evaluateLobe(reference, lobe.thetaInDegrees, kSamples),
                               [](const LobeSample& s) { return luminance(s.total()); }, IM_COL32(0, 220, 220, 200),
                               1.0f));
    }
    if (lobe.luminance) {
        curves.push_back(curve(samples, [](const LobeSample& s) { return luminance(s.diffuse); }, IM_COL32(110, 170, 255, 255), 1.0f));
        curves.push_back(curve(samples, [](const LobeSample& s) { return luminance(s.specular); }, IM_COL32(255, 150, 90, 255), 1.0f));
        curves.push_back(curve(samples, [](const LobeSample& s) { return luminance(s.total()); }, IM_COL32(255, 255, 255, 255), 2.0f));
    } else {
        const ImU32 channel[3] = {IM_COL32(255, 80, 80, 255), IM_COL32(80, 255, 80, 255), IM_COL32(90, 140, 255, 255)};
        for (int c = 0; c < 3; ++c) {
            curves.push_back(curve(samples, [c](const LobeSample& s) { return s.total()[c]; }, channel[c], 2.0f));
            curves.push_back(curve(samples, [c](const LobeSample& s) { return s.specular[c]; }, channel[c] & 0x80FFFFFF, 1.0f));
        }
    }
    const float termsWidth = 220.0f;
    const ImVec2 available = ImGui::GetContentRegionAvail();
    drawPolar(curves, maxValue, lobe.thetaInDegrees,
              ImVec2(std::max(available.x - termsWidth - 8.0f, 80.0f), std::max(available.y, 60.0f)));
    recordItem("lobe");
    ImGui::SameLine();

    // The three specular terms against theta_out, from the shared code.
    ImGui::BeginGroup();
    const shader::SurfaceMaterial m = surfaceMaterial(state.scene.material);
    const float inRadians = glm::radians(lobe.thetaInDegrees);
    const glm::vec3 N(0, 0, 1), L(std::sin(inRadians), 0, std::cos(inRadians));
    float d[kSamples], g[kSamples], f[kSamples];
    for (int i = 0; i < kSamples; ++i) {
        const float out = glm::radians(-90.0f + 180.0f * float(i) / float(kSamples - 1));
        const glm::vec3 V(std::sin(out), 0, std::cos(out));
        const shader::SpecularTerms t = specularTerms(state.scene.material.model, m, N, V, L);
        const float NoV = std::max(glm::dot(N, V), shader::MIN_N_DOT_V), NoL = std::max(glm::dot(N, L), 0.0f);
        d[i] = t.D;
        g[i] = t.Vis * 4.0f * NoL * NoV;   // G = V * 4 NoL NoV
        f[i] = luminance(t.F);
    }
    const float plotHeight = std::max((available.y - 3 * ImGui::GetTextLineHeightWithSpacing()) / 3.0f, 20.0f);
    ImGui::PlotLines("##D", d, kSamples, 0, "D", 0.0f, FLT_MAX, ImVec2(termsWidth, plotHeight));
    ImGui::PlotLines("##G", g, kSamples, 0, "G", 0.0f, 1.0f, ImVec2(termsWidth, plotHeight));
    ImGui::PlotLines("##F", f, kSamples, 0, "F", 0.0f, 1.0f, ImVec2(termsWidth, plotHeight));
    ImGui::EndGroup();
}

}  // namespace patina::editor
