#include "accuracy/furnace.h"

#include <cmath>
#include <cstdio>

#include <glm/trigonometric.hpp>

#include "accuracy/albedo_curve.h"
#include "common/luminance.h"
#include "common/parallel_for.h"
#include "shading/energy_table.h"

namespace patina {

std::vector<FurnaceCurve> whiteFurnace(int steps, int samples) {
    std::vector<FurnaceCurve> curves;
    for (const BrdfModelInfo& model : brdfModels()) {
        for (double mu : {1.0, 0.25}) {
            FurnaceCurve curve{std::string(model.name), mu, {}, {}};
            for (int i = 0; i <= steps; ++i) {
                const double r = double(i) / steps;
                double albedo = directionalAlbedo(model.id, mu, r, samples);
                if (model.multipleScattering()) {
                    // F = 1: the compensation factor is 1 + (1 / E_table - 1).
                    albedo /= tabulatedAlbedo(model.id, float(mu), float(r));
                }
                curve.roughness.push_back(r);
                curve.albedo.push_back(albedo);
            }
            curves.push_back(curve);
        }
    }
    return curves;
}

std::string furnaceCsv(const std::vector<FurnaceCurve>& curves) {
    std::string csv = "model,mu,roughness,albedo\n";
    char line[160];
    for (const FurnaceCurve& curve : curves) {
        for (size_t i = 0; i < curve.roughness.size(); ++i) {
            std::snprintf(line, sizeof line, "%s,%.3g,%.4g,%.6f\n", curve.model.c_str(), curve.mu, curve.roughness[i],
                          curve.albedo[i]);
            csv += line;
        }
    }
    return csv;
}

Chart furnaceChart(const std::vector<FurnaceCurve>& curves) {
    Chart chart;
    chart.panelWidth = 760;
    for (double mu : {1.0, 0.25}) {
        ChartPanel panel{mu == 1.0 ? "White furnace, mu = 1" : "White furnace, mu = 0.25", "roughness",
                         "specular albedo E with F = 1", false, false, {}};
        std::vector<const FurnaceCurve*> drawn;
        for (const FurnaceCurve& curve : curves) {
            if (curve.mu != mu) {
                continue;
            }
            // Models with the same specular lobe share one line, named after all of them.
            bool merged = false;
            for (size_t i = 0; i < drawn.size() && !merged; ++i) {
                if (drawn[i]->albedo == curve.albedo) {
                    panel.series[i].label += ", " + curve.model;
                    merged = true;
                }
            }
            if (merged) {
                continue;
            }
            ChartSeries series{curve.model, {}, drawn.size(), true, false, false, {}, {}};
            for (size_t i = 0; i < curve.roughness.size(); ++i) {
                series.points.emplace_back(curve.roughness[i], curve.albedo[i]);
            }
            panel.series.push_back(series);
            drawn.push_back(&curve);
        }
        chart.panels.push_back(panel);
    }
    return chart;
}

namespace {
// materialFurnace's materials, all white: a dielectric, a metal and a thin-walled glass.
constexpr const char* kFurnaceMaterials[] = {"white dielectric", "white metal", "white glass"};
}  // namespace

std::vector<MaterialFurnaceRow> materialFurnace(const std::vector<BrdfModelId>& models, int steps, int samples) {
    std::vector<MaterialFurnaceRow> rows;
    for (BrdfModelId model : models) {
        for (const char* name : kFurnaceMaterials) {
            for (double mu : {1.0, 0.25}) {
                for (int i = 0; i <= steps; ++i) {
                    rows.push_back({std::string(brdfModel(model).name), name, mu, double(i) / steps});
                }
            }
        }
    }
    parallelFor(rows.size(), [&](size_t i) {
        MaterialFurnaceRow& row = rows[i];
        MaterialParameters white;
        white.model = *brdfModelFromName(row.model);
        white.baseColor = glm::vec3(1.0f);
        white.metallic = row.material == "white metal" ? 1.0f : 0.0f;
        white.transmission = row.material == "white glass" ? 1.0f : 0.0f;
        white.roughness = float(row.roughness);
        const AlbedoPoint p = albedoAt(white, glm::degrees(float(std::acos(row.mu))), samples, 0xD1B54A32D192ED03ull * (i + 1));
        row.splitSum = luminance(p.product);
        row.truth = luminance(p.truth);
        row.truthStandardError = luminance(p.standardError);
        row.splitSumTransmitted = luminance(p.productTransmitted);
        row.truthTransmitted = luminance(p.truthTransmitted);
    });
    return rows;
}

std::string materialFurnaceCsv(const std::vector<MaterialFurnaceRow>& rows) {
    std::string csv = "model,material,mu,roughness,split_sum,truth,truth_se,split_sum_transmitted,truth_transmitted\n";
    char line[240];
    for (const MaterialFurnaceRow& r : rows) {
        std::snprintf(line, sizeof line, "%s,%s,%.3g,%.4g,%.6f,%.6f,%.6f,%.6f,%.6f\n", r.model.c_str(),
                      r.material.c_str(), r.mu, r.roughness, r.splitSum, r.truth, r.truthStandardError,
                      r.splitSumTransmitted, r.truthTransmitted);
        csv += line;
    }
    return csv;
}

}  // namespace patina
