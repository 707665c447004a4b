#include "accuracy/stability.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "accuracy/accuracy.h"
#include "picture/compositing.h"
#include "accuracy/edge_cases.h"
#include "gl/gpu_probe.h"

namespace patina {

const std::vector<double> kStabilityRoughness = {0.0, 1e-6, 1e-4, 1e-3, 0.01, 0.02, 0.045, 0.089, 0.1,
                                                 0.2, 0.3,  0.4,  0.5,  0.6,  0.7,  0.8,   0.9,   1.0};
const std::vector<double> kStabilityCosines = {0.0, 1e-7, 1e-5, 1e-3, 0.01, 0.05, 0.1, 0.2,
                                               0.3, 0.4,  0.5,  0.6,  0.7,  0.8,  0.9, 1.0};

const char* precisionName(Precision precision) {
    switch (precision) {
    case Precision::Fp64: return "fp64";
    case Precision::Fp32Cpu: return "fp32-cpu";
    case Precision::Fp16Cpu: return "fp16-cpu";
    case Precision::Fp32Gpu: return "fp32-gpu";
    }
    return "?";
}

namespace {
constexpr double kFp16Max = 65504.0;
const double kAzimuths[] = {std::numbers::pi, std::numbers::pi / 2};   // pi: V in the mirror plane (the specular peak)
const float kMetallic[] = {0.0f, 1.0f};

// The configuration in the frame of a light along +z (so the GPU probe's one directional light
// serves every sample): N at acos(NoL) from L, V at acos(NoV) from N.
AccuracySample configuration(double roughness, float metallic, double NoV, double NoL, double phi) {
    Material material;
    material.baseColor = {0.8f, 0.5f, 0.25f};
    material.roughness = float(roughness);
    material.metallic = metallic;
    const glm::dvec3 L(0, 0, 1);
    const double sinL = std::sqrt(std::max(0.0, 1.0 - NoL * NoL)), sinV = std::sqrt(std::max(0.0, 1.0 - NoV * NoV));
    const glm::dvec3 N(sinL, 0.0, NoL);
    const glm::dvec3 t = sinL > 1e-12 ? glm::normalize(L - NoL * N) : glm::dvec3(1, 0, 0);
    const glm::dvec3 b = glm::cross(N, t);
    const glm::dvec3 V = sinV * std::cos(phi) * t + sinV * std::sin(phi) * b + NoV * N;
    return {material, N, V, L};
}

void count(StabilityCounts& counts, double value) {
    ++counts.values;
    counts.nan += std::isnan(value);
    counts.inf += std::isinf(value);
    counts.negative += value < 0.0;
    counts.overRange += std::isfinite(value) && value > kFp16Max;
}

struct Cell {
    double worst = -std::numeric_limits<double>::infinity();   // log10 relative error
    bool broken = false;                                        // NaN or Inf seen
};

void compare(StabilityCounts& counts, Cell& cell, glm::dvec3 value, glm::dvec3 fp64) {
    for (int c = 0; c < 3; ++c) {
        count(counts, value[c]);
        if (!std::isfinite(value[c])) {
            cell.broken = true;
        } else if (std::isfinite(fp64[c]) && std::abs(fp64[c]) > 1e-4) {
            const double relative = std::abs(value[c] - fp64[c]) / std::abs(fp64[c]);
            counts.maxRelativeError = std::max(counts.maxRelativeError, relative);
            cell.worst = std::max(cell.worst, std::log10(std::max(relative, 1e-12)));
        }
    }
}

void countSpecialCases(StabilityCounts& counts, const std::vector<glm::vec3>& values) {
    for (const glm::vec3& v : values) {
        for (int c = 0; c < 3; ++c) {
            count(counts, v[c]);
        }
    }
}
}  // namespace

std::vector<StabilityRow> runStability(bool quick) {
    const std::vector<double> roughness =
        quick ? std::vector<double>{0.0, 1e-4, 0.045, 0.5, 1.0} : kStabilityRoughness;
    const std::vector<double> cosines = quick ? std::vector<double>{0.0, 1e-7, 0.01, 0.5, 1.0} : kStabilityCosines;
    const size_t cells = roughness.size() * cosines.size();
    GpuProbe probe;
    std::vector<StabilityRow> rows;
    for (const BrdfModelInfo& model : brdfModels()) {
        StabilityRow fp64{std::string(model.name), Precision::Fp64, {}, {}, {}};
        StabilityRow cpu{fp64.model, Precision::Fp32Cpu, {}, {}, {}};
        StabilityRow half{fp64.model, Precision::Fp16Cpu, {}, {}, {}};
        StabilityRow gpu{fp64.model, Precision::Fp32Gpu, {}, {}, {}};
        std::vector<Cell> fp64Cells(cells), cpuCells(cells), halfCells(cells), gpuCells(cells);
        for (size_t ri = 0; ri < roughness.size(); ++ri) {
            for (float metallic : kMetallic) {
                std::vector<AccuracySample> batch;
                std::vector<size_t> cellOf;
                for (size_t vi = 0; vi < cosines.size(); ++vi) {
                    for (double NoL : cosines) {
                        for (double phi : kAzimuths) {
                            batch.push_back(configuration(roughness[ri], metallic, cosines[vi], NoL, phi));
                            cellOf.push_back(ri * cosines.size() + vi);
                        }
                    }
                }
                Material material = batch.front().material;
                material.model = model.id;
                std::vector<ProbeSample> samples;
                for (const AccuracySample& s : batch) {
                    samples.push_back({glm::vec3(0.0f), glm::vec3(s.N), glm::vec3(s.V)});
                }
                const std::vector<glm::vec3> gpuValues = probe.evaluate(material, {accuracyLight()}, samples);
                for (size_t i = 0; i < batch.size(); ++i) {
                    const glm::dvec3 exact = reflectedF64(model.id, batch[i]);
                    compare(fp64.grid, fp64Cells[cellOf[i]], exact, exact);
                    compare(cpu.grid, cpuCells[cellOf[i]], reflectedF32(model.id, batch[i]), exact);
                    compare(half.grid, halfCells[cellOf[i]],
                            reflectedF16(model.id, batch[i].material, batch[i].N, batch[i].V, batch[i].L), exact);
                    compare(gpu.grid, gpuCells[cellOf[i]], glm::dvec3(gpuValues[i]), exact);
                }
            }
        }
        for (const EdgeCase& edge : edgeCases()) {
            Material material = edge.material;
            material.model = model.id;
            countSpecialCases(cpu.specialCases, probeOnCpu(material, edge.lights, edge.samples));
            countSpecialCases(gpu.specialCases, probe.evaluate(material, edge.lights, edge.samples));
        }
        for (auto [row, cellValues] :
             {std::pair{&fp64, &fp64Cells}, {&cpu, &cpuCells}, {&half, &halfCells}, {&gpu, &gpuCells}}) {
            row->roughnessSteps = int(roughness.size());
            for (const Cell& cell : *cellValues) {
                row->heat.push_back(cell.broken ? std::numeric_limits<double>::quiet_NaN() : cell.worst);
            }
            rows.push_back(*row);
        }
    }
    return rows;
}

std::string stabilityCsv(const std::vector<StabilityRow>& rows) {
    std::string csv = "model,precision,values,nan,inf,negative,over_range,max_rel_error_vs_fp64,"
                      "special_values,special_nan,special_inf,special_negative\n";
    char line[512];
    for (const StabilityRow& r : rows) {
        std::snprintf(line, sizeof line, "%s,%s,%zu,%zu,%zu,%zu,%zu,%.4g,%zu,%zu,%zu,%zu\n", r.model.c_str(),
                      precisionName(r.precision), r.grid.values, r.grid.nan, r.grid.inf, r.grid.negative,
                      r.grid.overRange, r.grid.maxRelativeError, r.specialCases.values, r.specialCases.nan,
                      r.specialCases.inf, r.specialCases.negative);
        csv += line;
    }
    return csv;
}

LdrImage stabilityHeatMap(const std::vector<StabilityRow>& rows, const std::string& model) {
    constexpr int kCell = 20, kLeft = 60, kTop = 40, kGap = 30;
    std::vector<const StabilityRow*> panels;
    for (const StabilityRow& row : rows) {
        if (row.model == model) {
            panels.push_back(&row);
        }
    }
    const size_t cells = panels.empty() ? 0 : panels.front()->heat.size();
    const int columns = panels.empty() ? 0 : panels.front()->roughnessSteps;
    const int lines = columns ? int(cells) / columns : 0;
    const int panelWidth = kLeft + columns * kCell + kGap;
    LdrImage image{std::max(1, panelWidth * int(panels.size())), kTop + lines * kCell + 70, {}};
    image.rgba.assign(size_t(image.width) * size_t(image.height) * 4, 255);
    const Rgb8 ink{30, 30, 30}, broken{255, 0, 255};
    for (size_t p = 0; p < panels.size(); ++p) {
        const int x0 = int(p) * panelWidth + kLeft;
        drawText(image, x0, 8, model + "  " + precisionName(panels[p]->precision), 1, ink);
        drawText(image, x0, 22, "x: roughness  y: NoV  colour: log10 rel. error", 1, ink);
        for (int i = 0; i < int(cells); ++i) {
            const int cx = i / lines, cy = i % lines;   // cells are roughness-major
            const double value = panels[p]->heat[size_t(i)];
            Rgb8 colour;
            if (std::isnan(value)) {
                colour = broken;
            } else {
                // -8 (or exact) -> black ... 0 and above -> pale yellow.
                const double t = std::clamp((std::max(value, -8.0) + 8.0) / 8.0, 0.0, 1.0);
                colour = heatColour(int(t * 255.0));
            }
            for (int y = 0; y < kCell - 1; ++y) {
                for (int x = 0; x < kCell - 1; ++x) {
                    const int px = x0 + cx * kCell + x, py = kTop + (lines - 1 - cy) * kCell + y;
                    uint8_t* pixel = &image.rgba[(size_t(py) * size_t(image.width) + size_t(px)) * 4];
                    pixel[0] = colour.r, pixel[1] = colour.g, pixel[2] = colour.b;
                }
            }
        }
        drawText(image, x0, kTop + lines * kCell + 6, "r: 0 ... 1 (left to right)", 1, ink);
        drawText(image, x0, kTop + lines * kCell + 20, "NoV: 0 (bottom) ... 1 (top)", 1, ink);
        drawText(image, x0, kTop + lines * kCell + 34, "magenta: NaN or Inf", 1, broken);
    }
    return image;
}

}  // namespace patina
