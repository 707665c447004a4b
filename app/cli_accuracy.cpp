// The speed/accuracy commands: bench, stability and furnace, and what they share with the other
// measurements (cli.h). Each writes into --out-dir (default: the current folder).
#include <filesystem>
#include <iostream>
#include <memory>

#include "bench/bench.h"
#include "cli.h"
#include "accuracy/furnace.h"
#include "gl/headless_context.h"
#include "image/image.h"
#include "io/input_error.h"
#include "inputs.h"
#include "accuracy/stability.h"

namespace patina::cli {

void writeChart(const std::filesystem::path& stem, const Chart& chart, bool svg) {
    if (svg) {
        writeOutputText(stem.string() + ".svg", chartToSvg(chart));
    }
    writeOutput(stem.string() + ".png", encodePng(chartToImage(chart)));
}

std::filesystem::path outputFolder(const std::string& folder) {
    const std::filesystem::path path = folder.empty() ? "." : folder;
    if (!std::filesystem::is_directory(path)) {
        throw InputError(path.string() + ": not a folder");
    }
    return path;
}

Command addMeasurementCommand(CLI::App& app, const char* name, const char* description, Measurement measure) {
    struct Options {
        std::string outDir;
        bool quick = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(name, description);
    command->add_option("--out-dir", options->outDir, "Folder for the outputs (default: current)");
    command->add_flag("--quick", options->quick, "A smaller, faster run (for CI)");
    return [options, measure] { measure(outputFolder(options->outDir), options->quick); };
}

Command addBenchCommand(CLI::App& app) {
    return addMeasurementCommand(
        app, "bench", "Cost against error of every BRDF model: bench.csv and speed_accuracy.svg/.png",
        [](const std::filesystem::path& folder, bool quick) {
            HeadlessContext context;
            BenchOptions options;
            options.quick = quick;
            const BenchResult result = runBench(options);
            writeOutputText((folder / "bench.csv").string(), benchCsv(result));
            writeChart(folder / "speed_accuracy", benchChart(result), true);
            std::cout << result.rows.size() << " models, " << result.samples << " samples, on " << result.renderer
                      << "\n";
        });
}

Command addStabilityCommand(CLI::App& app) {
    return addMeasurementCommand(
        app, "stability", "Where each BRDF model fails: stability.csv and a heat map per model",
        [](const std::filesystem::path& folder, bool quick) {
            HeadlessContext context;
            const std::vector<StabilityRow> rows = runStability(quick);
            writeOutputText((folder / "stability.csv").string(), stabilityCsv(rows));
            for (const BrdfModelInfo& model : brdfModels()) {
                writeOutput((folder / ("stability_" + std::string(model.name) + ".png")).string(),
                            encodePng(stabilityHeatMap(rows, std::string(model.name))));
            }
        });
}

Command addFurnaceCommand(CLI::App& app) {
    return addMeasurementCommand(
        app, "furnace", "White furnace: specular albedo with F = 1 of every model: furnace.csv and furnace.png",
        [](const std::filesystem::path& folder, bool quick) {
            const std::vector<FurnaceCurve> curves = whiteFurnace(quick ? 10 : 40, quick ? 1024 : 4096);
            writeOutputText((folder / "furnace.csv").string(), furnaceCsv(curves));
            writeChart(folder / "furnace", furnaceChart(curves), false);
        });
}

}  // namespace patina::cli
