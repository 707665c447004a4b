#pragma once
// The curves of the lobe panel's polar plot, as numbers: which curves, their legend (naming
// only what is drawn), and the scale that fits all of them (B, A when set, and the reference
// model's when another model than the default is chosen), so no curve runs off the plot.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "state/document.h"
#include "state/interaction.h"

namespace patina::editor {

struct LobeCurve {
    std::vector<float> values;   // one per theta_out from -90 to 90 degrees, cosine applied
    uint32_t color;              // ImGui's packed RGBA (IM_COL32)
    float thickness;
    std::string legend;          // its legend entry; empty: covered by an earlier entry
    uint32_t legendColor;        // the legend entry's line: the curve's, or neutral for one naming several
};

struct LobePlot {
    std::vector<LobeCurve> curves;   // drawn in order: the last on top
    float maxValue = 0.0f;           // the largest value of any curve: the plot's outer ring
};

constexpr int kLobeSamples = 181;

LobePlot lobePlot(const Document& document, const Interaction& interaction);

// A value's distance from the centre as a fraction of the plot's radius: linear, or in log
// scale 3 decades below the maximum to the maximum.
float lobeRadius(float value, float maxValue, bool logScale);

// The 3D lobe's surface for theta_in (Lobe3d): luminance of f (times cos theta_in with "x cos")
// over outgoing directions, kLobeRings rings of theta_out from 0 to 90 degrees by kLobeMeridians
// of phi_out; the points' distance from the centre is lobeRadius of the value. A transmitting
// material (KHR_materials_transmission, thin-walled) has its transmitted lobe too, below the
// surface on the same grid mirrored (lobe.h's LobeValue::transmitted), on the same scale.
constexpr int kLobeRings = 16, kLobeMeridians = 36;
struct Lobe3d {
    std::vector<glm::vec3> points;        // ring-major, (ring, meridian); unit-sphere directions times their radius
    std::vector<glm::vec3> transmitted;   // the same grid below the surface (z <= 0); empty without a transmission
    float maxValue = 0.0f;
    // The largest value at the mirror direction (and straight through, with a transmission) of
    // either lobe: a smooth lobe's peak, which falls between the grid's directions.
    float peak = 0.0f;
};
// The lobes of B and, when set, A, scaled together (one maxValue for both).
std::vector<Lobe3d> lobes3d(const Document& document, const Interaction& interaction);

}  // namespace patina::editor
