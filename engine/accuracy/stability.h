#pragma once
// `patina stability`: where each model fails. A grid of roughness x NoV x NoL (the failure points
// of docs/SHADING.md S2 included) evaluated in fp64, fp32 and emulated fp16 on the CPU and fp32 on the
// GPU, plus the special cases of edge_cases.h. Needs a current GL context.
#include <string>
#include <vector>

#include "shading/brdf_models.h"
#include "image/chart.h"

namespace patina {

extern const std::vector<double> kStabilityRoughness;   // 0, 1e-6, ..., 0.089, 0.1 .. 1
extern const std::vector<double> kStabilityCosines;     // NoV and NoL: 0, 1e-7, ..., 1

enum class Precision { Fp64, Fp32Cpu, Fp16Cpu, Fp32Gpu };
const char* precisionName(Precision precision);

struct StabilityCounts {
    size_t values = 0, nan = 0, inf = 0, negative = 0;
    size_t overRange = 0;        // above 65504, the largest fp16 value
    double maxRelativeError = 0.0;   // against fp64, where fp64 is finite and above 1e-4
};

struct StabilityRow {
    std::string model;
    Precision precision;
    StabilityCounts grid;          // the roughness x NoV x NoL grid
    StabilityCounts specialCases;  // edge_cases.h through the full light path (fp32 rows only)
    // log10 relative error per (roughness, NoV), worst over NoL and azimuth; NaN where a value
    // was NaN or Inf.
    std::vector<double> heat;
    int roughnessSteps = 0;   // heat is roughnessSteps columns of NoV values
};

std::vector<StabilityRow> runStability(bool quick);
std::string stabilityCsv(const std::vector<StabilityRow>& rows);
// roughness x NoV heat map of one model, one panel per precision.
LdrImage stabilityHeatMap(const std::vector<StabilityRow>& rows, const std::string& model);

}  // namespace patina
