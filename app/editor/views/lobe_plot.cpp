#include "views/lobe_plot.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "common/luminance.h"
#include "shading/lobe.h"

namespace patina::editor {

namespace {
constexpr uint32_t rgba(uint32_t r, uint32_t g, uint32_t b, uint32_t a) {
    return r | (g << 8) | (b << 16) | (a << 24);   // IM_COL32's layout
}

// Whether the three channels of every sample are one (a grey material): their curves coincide.
bool grey(const std::vector<LobeSample>& samples) {
    return std::all_of(samples.begin(), samples.end(), [](const LobeSample& s) {
        const glm::vec3 total = s.total();
        const float tolerance = 1e-5f * std::max(total.r, 1e-6f);
        return std::abs(total.g - total.r) <= tolerance && std::abs(total.b - total.r) <= tolerance &&
               std::abs(s.specular.g - s.specular.r) <= tolerance && std::abs(s.specular.b - s.specular.r) <= tolerance;
    });
}

// A transmitting material's lobe below the surface (LobeSample::transmitted, thin-walled
// KHR_materials_transmission): drawn above the horizon at the mirrored angle, in its own colour
// and named so; none for a material without a transmission.
void addTransmittedCurve(LobePlot& plot, const std::vector<LobeSample>& samples, float cosine, const std::string& b) {
    if (std::all_of(samples.begin(), samples.end(), [](const LobeSample& s) { return s.transmitted == glm::vec3(0.0f); })) {
        return;
    }
    const uint32_t color = rgba(120, 230, 140, 255);
    LobeCurve curve{{}, color, 1.5f, b + "transmitted, below (mirrored up, luminance)", color};
    for (const LobeSample& sample : samples) {
        curve.values.push_back(luminance(sample.transmitted) * cosine);
    }
    plot.curves.push_back(std::move(curve));
}
}  // namespace

LobePlot lobePlot(const Document& document, const Interaction& interaction) {
    const LobeSettings& lobe = interaction.lobe;
    const float cosine = lobe.multiplyByCosine ? std::cos(glm::radians(lobe.thetaInDegrees)) : 1.0f;
    LobePlot plot;
    auto add = [&](const std::vector<LobeSample>& samples, auto pick, uint32_t color, float thickness,
                   std::string legend) {
        LobeCurve curve{{}, color, thickness, std::move(legend), color};
        for (const LobeSample& sample : samples) {
            curve.values.push_back(pick(sample) * cosine);
        }
        plot.curves.push_back(std::move(curve));
    };
    auto total = [](const LobeSample& s) { return luminance(s.total()); };
    if (interaction.compareA) {
        add(evaluateLobe(*interaction.compareA, lobe.thetaInDegrees, kLobeSamples), total, rgba(160, 160, 160, 160),
            3.0f, "A total");
    }
    // The same material under the reference model, for what a model chosen instead of the
    // default gets wrong; under the default it is a research question the Accuracy tab answers.
    const Material edited = editedMaterial(document, interaction);
    const BrdfModelId model = edited.model;
    if (model != MaterialParameters{}.model && model != BrdfModelId::Reference) {
        Material reference = edited;
        reference.model = BrdfModelId::Reference;
        add(evaluateLobe(reference, lobe.thetaInDegrees, kLobeSamples), total, rgba(0, 220, 220, 200), 1.0f,
            "reference model");
    }
    const std::vector<LobeSample> samples = evaluateLobe(edited, lobe.thetaInDegrees, kLobeSamples);
    const std::string b = interaction.compareA ? "B " : "";   // "B" says which only beside an A
    if (lobe.luminance) {
        add(samples, [](const LobeSample& s) { return luminance(s.diffuse); }, rgba(110, 170, 255, 255), 1.0f,
            b + "diffuse");
        add(samples, [](const LobeSample& s) { return luminance(s.specular); }, rgba(255, 150, 90, 255), 1.0f,
            b + "specular");
        add(samples, total, rgba(255, 255, 255, 255), 2.0f, b + "total");
    } else if (grey(samples)) {
        // R, G and B are one curve: drawn once, in white, as what it is.
        add(samples, [](const LobeSample& s) { return s.total().r; }, rgba(255, 255, 255, 255), 2.0f,
            b + "total (thick)");
        add(samples, [](const LobeSample& s) { return s.specular.r; }, rgba(255, 255, 255, 160), 1.0f,
            b + "specular (thin)");
    } else {
        const uint32_t channel[3] = {rgba(255, 80, 80, 255), rgba(80, 255, 80, 255), rgba(90, 140, 255, 255)};
        // Each legend entry names three curves, one a channel: its line is neutral, not the red one's.
        const uint32_t neutral = rgba(220, 220, 220, 255);
        for (int c = 0; c < 3; ++c) {
            add(samples, [c](const LobeSample& s) { return s.total()[c]; }, channel[c], 2.0f,
                c == 0 ? b + "total, R G B (thick)" : "");
            plot.curves.back().legendColor = neutral;
            add(samples, [c](const LobeSample& s) { return s.specular[c]; }, channel[c] & 0x80FFFFFFu, 1.0f,
                c == 0 ? b + "specular (thin)" : "");
            plot.curves.back().legendColor = neutral;
        }
    }
    addTransmittedCurve(plot, samples, cosine, b);
    plot.maxValue = 1e-6f;
    for (const LobeCurve& curve : plot.curves) {
        for (float value : curve.values) {
            plot.maxValue = std::max(plot.maxValue, value);
        }
    }
    return plot;
}

std::vector<Lobe3d> lobes3d(const Document& document, const Interaction& interaction) {
    const LobeSettings& lobe = interaction.lobe;
    const float cosine = lobe.multiplyByCosine ? std::cos(glm::radians(lobe.thetaInDegrees)) : 1.0f;
    const float thetaIn = glm::radians(lobe.thetaInDegrees);
    const glm::vec3 L(std::sin(thetaIn), 0.0f, std::cos(thetaIn));
    std::vector<Material> materials{editedMaterial(document, interaction)};
    if (interaction.compareA) {
        materials.push_back(*interaction.compareA);
    }
    std::vector<Lobe3d> lobes;
    // Each lobe's values, the reflected's then (with a transmission) the transmitted's.
    std::vector<std::vector<float>> values, transmittedValues;
    float maxValue = 1e-6f, peak = 0.0f;
    for (const Material& material : materials) {
        const LobeValue mirrored = lobeValue(material, L, glm::vec3(-L.x, -L.y, L.z));
        peak = std::max({peak, luminance(mirrored.total()) * cosine, luminance(mirrored.transmitted) * cosine});
        Lobe3d& lobe3d = lobes.emplace_back();
        std::vector<float>& v = values.emplace_back();
        std::vector<float>& t = transmittedValues.emplace_back();
        const bool transmits = material.transmission > 0.0f;
        for (int ring = 0; ring < kLobeRings; ++ring) {
            const float theta = glm::radians(90.0f * float(ring) / float(kLobeRings - 1));
            for (int meridian = 0; meridian < kLobeMeridians; ++meridian) {
                const float phi = glm::radians(360.0f * float(meridian) / float(kLobeMeridians));
                const glm::vec3 V(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
                const LobeValue f = lobeValue(material, L, V);
                v.push_back(luminance(f.total()) * cosine);
                lobe3d.points.push_back(V);
                maxValue = std::max(maxValue, v.back());
                if (transmits) {   // towards V mirrored below the surface (lobe.h)
                    t.push_back(luminance(f.transmitted) * cosine);
                    lobe3d.transmitted.push_back(glm::vec3(V.x, V.y, -V.z));
                    maxValue = std::max(maxValue, t.back());
                }
            }
        }
    }
    for (size_t i = 0; i < lobes.size(); ++i) {
        lobes[i].maxValue = maxValue;
        lobes[i].peak = peak;
        for (size_t p = 0; p < lobes[i].points.size(); ++p) {
            lobes[i].points[p] *= lobeRadius(values[i][p], maxValue, lobe.logScale);
        }
        for (size_t p = 0; p < lobes[i].transmitted.size(); ++p) {
            lobes[i].transmitted[p] *= lobeRadius(transmittedValues[i][p], maxValue, lobe.logScale);
        }
    }
    return lobes;
}

float lobeRadius(float value, float maxValue, bool logScale) {
    const float linear = value / maxValue;
    const float fraction = logScale ? (std::log10(std::max(linear, 1e-12f)) + 3.0f) / 3.0f : linear;
    return std::clamp(fraction, 0.0f, 1.0f);
}

}  // namespace patina::editor
