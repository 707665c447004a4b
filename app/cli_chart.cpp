// `patina chart KIND FOLDER`: a measurement's charts redrawn from the CSVs it wrote into FOLDER,
// through the same chart builders as a run, so a chart's look can change without timing again
// (timings on a shared machine do not repeat, and the docs quote them).
#include <filesystem>
#include <memory>

#include "bench/bench.h"
#include "bench/csv_read.h"
#include "bench/lighting_accuracy.h"
#include "bench/render_bench.h"
#include "bench/renderer_comparison.h"
#include "cli.h"
#include "files/file_bytes.h"
#include "files/input_error.h"

namespace patina::cli {

namespace {
CsvFile readCsv(const std::filesystem::path& path) {
    if (!std::filesystem::is_regular_file(path)) {
        throw InputError(path.string() + ": no such file (the measurement writes it)");
    }
    const std::vector<uint8_t> bytes = readFileBytes(path);
    return {std::string(bytes.begin(), bytes.end()), path.string()};
}
}  // namespace

Command addChartCommand(CLI::App& app) {
    struct Options {
        std::string kind, folder;
        bool quick = false;
        int samples = 0;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "chart", "Redraw a measurement's charts from the CSVs it wrote, measuring nothing: bench (bench.csv), "
                 "lighting (split_sum.csv and lighting_cost.csv), render (render_bench.csv; needs --msaa) or cycles "
                 "(cycles.csv, scripts/compare_cycles.sh's)");
    command->add_option("kind", options->kind, "bench, lighting, render or cycles")
        ->required()
        ->check(CLI::IsMember({"bench", "lighting", "render", "cycles"}));
    command->add_option("folder", options->folder, "The folder with the CSVs; the charts are written beside them")
        ->required();
    command->add_flag("--quick", options->quick, "lighting: the CSVs are from a --quick run (smaller frames timed)");
    command->add_option("--msaa", options->samples,
                        "render: the samples per pixel the run timed (render_bench.csv does not record them)")
        ->check(CLI::Range(1, 16));
    return [options] {
        const std::filesystem::path folder = outputFolder(options->folder);
        if (options->kind == "bench") {
            writeBenchChart(folder, parseBenchCsv(readCsv(folder / "bench.csv")));
        } else if (options->kind == "lighting") {
            writeLightingChart(folder, parseLightingAccuracy(readCsv(folder / "split_sum.csv"),
                                                             readCsv(folder / "lighting_cost.csv"), options->quick));
        } else if (options->kind == "cycles") {
            writeChart(folder / "cycles",
                       rendererComparisonChart(parseRendererComparison(readCsv(folder / "cycles.csv")), "reference"),
                       true);
        } else if (options->samples == 0) {
            throw InputError("chart render: give --msaa, the samples per pixel of the run (its title says them)");
        } else {
            writeRenderBenchCharts(folder, parseRenderBenchCsv(readCsv(folder / "render_bench.csv"), options->samples));
        }
    };
}

}  // namespace patina::cli
