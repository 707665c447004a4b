#include <cstdio>
#include <memory>

#include "accuracy/albedo_curve.h"
#include "cli.h"
#include "inputs.h"

namespace patina::cli {

namespace {
// The transmitted columns (KHR_materials_transmission, 0 without) are the part of split_sum and
// truth that comes through the wall; the rest of each is the reflected albedo.
std::string albedoCsv(const std::vector<AlbedoPoint>& curve) {
    std::string csv = "theta_v_deg,split_sum_r,split_sum_g,split_sum_b,truth_r,truth_g,truth_b,truth_se_r,truth_se_g,"
                      "truth_se_b,transmitted_split_sum_r,transmitted_split_sum_g,transmitted_split_sum_b,"
                      "transmitted_truth_r,transmitted_truth_g,transmitted_truth_b\n";
    char row[512];
    for (const AlbedoPoint& p : curve) {
        std::snprintf(row, sizeof row, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                      double(p.thetaVDegrees), double(p.product.r), double(p.product.g), double(p.product.b),
                      double(p.truth.r), double(p.truth.g), double(p.truth.b), double(p.standardError.r),
                      double(p.standardError.g), double(p.standardError.b), double(p.productTransmitted.r),
                      double(p.productTransmitted.g), double(p.productTransmitted.b), double(p.truthTransmitted.r),
                      double(p.truthTransmitted.g), double(p.truthTransmitted.b));
        csv += row;
    }
    return csv;
}
}  // namespace

Command addAlbedoCommand(CLI::App& app) {
    struct Options {
        SceneInputs inputs;
        int points = 19, samples = 1024;
        std::string out, chart;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "albedo", "Write the material's directional albedo against theta_v under a white furnace as CSV: the split "
                  "sum's (what the renderer computes) beside the ground truth's estimate and its standard error");
    options->inputs.addOptions(*command, false);
    command->add_option("--points", options->points, "Angles from 0 to 88.5 degrees")->check(CLI::Range(2, 1000));
    command->add_option("--samples", options->samples, "Ground-truth MIS iterations per angle (3 directions each)")
        ->check(CLI::Range(1, 1 << 20));
    command->add_option("--out", options->out, "Output CSV")->required();
    command->add_option("--chart", options->chart,
                        "Also a chart of the luminance with the truth's error bars: STEM.png, STEM.svg and STEM.pdf");
    return [options] {
        const Scene scene = options->inputs.load();
        const std::vector<AlbedoPoint> curve = albedoCurve(scene.material, options->points, options->samples);
        const std::string csv = albedoCsv(curve);
        writeOutput(options->out, std::vector<uint8_t>(csv.begin(), csv.end()));
        if (!options->chart.empty()) {
            writeChart(options->chart, albedoChart({{scene.material.name, curve}}), true);
        }
    };
}

}  // namespace patina::cli
