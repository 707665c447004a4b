// `patina bench-render`: the renderer's frame cost per path against light count, resolution
// and triangles; batch rendering against separate processes; peak memory of a render.
// Writes render_bench.csv, render_targets.csv, render_lights.png and render_scale.png.
#include <filesystem>
#include <iostream>
#include <thread>
#include <memory>

#include "child_process.h"
#include "cli.h"
#include "gl/headless_context.h"
#include "image/image.h"
#include "files/input_error.h"
#include "inputs.h"
#include "bench/render_bench.h"
#include "io/scene_file.h"
#include "io/temporary_folder.h"
#include "bench/timing.h"

#ifndef PATINA_PRESETS_DIR
#define PATINA_PRESETS_DIR "presets"
#endif

namespace patina::cli {

namespace {
struct BatchResult {
    int images = 0, size = 0;
    double sheetSeconds = 0.0, separateSeconds = 0.0;
};

std::vector<std::string> presetFiles(size_t count) {
    std::vector<std::string> files;
    for (const std::filesystem::path& file : materialFilesIn(PATINA_PRESETS_DIR)) {
        files.push_back(file.string());
    }
    if (files.size() < count) {
        throw InputError(std::string(PATINA_PRESETS_DIR) + ": " + std::to_string(files.size()) +
                         " presets, the batch needs " + std::to_string(count));
    }
    files.resize(count);
    return files;
}

// One `patina sheet` of the presets against one `patina render` process per preset, both
// counted from process start, rounds interleaved.
BatchResult measureBatch(bool quick, const std::filesystem::path& scratch) {
    BatchResult batch;
    batch.images = quick ? 6 : 24;
    batch.size = quick ? 128 : 512;
    const std::vector<std::string> presets = presetFiles(size_t(batch.images));
    const std::string size = std::to_string(batch.size);
    std::vector<std::string> sheet = presets;
    sheet.insert(sheet.begin(), "sheet");
    for (const char* option : {"--size", size.c_str(), "--columns", "6", "--out"}) {
        sheet.emplace_back(option);
    }
    sheet.push_back((scratch / "sheet.png").string());
    std::vector<double> sheetSeconds, separateSeconds;
    for (int round = 0; round < (quick ? 1 : 3); ++round) {
        sheetSeconds.push_back(runSelf(sheet).seconds);
        double total = 0.0;
        for (const std::string& preset : presets) {
            total += runSelf({"render", "--material", preset, "--width", size, "--height", size, "--out",
                              (scratch / "one.png").string()})
                         .seconds;
        }
        separateSeconds.push_back(total);
    }
    batch.sheetSeconds = median(sheetSeconds);
    batch.separateSeconds = median(separateSeconds);
    return batch;
}

double renderPeakRssMb(const std::filesystem::path& scratch) {
    std::vector<double> peaks;
    for (int run = 0; run < 3; ++run) {
        peaks.push_back(runSelf({"render", "--out", (scratch / "default.png").string()}).peakRssMb);
    }
    return median(peaks);
}

}  // namespace

void writeRenderBenchCharts(const std::filesystem::path& folder, const RenderBenchResult& result) {
    writeChart(folder / "render_lights", renderBenchLightChart(result), false);
    writeChart(folder / "render_scale", renderBenchScaleChart(result), false);
}

Command addBenchRenderCommand(CLI::App& app) {
    struct Options {
        std::string outDir = ".";
        bool quick = false;
        int runs = 7, samples = 4;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "bench-render", "Frame cost of the multi, single and specialised paths against lights, resolution and "
                        "triangles; batch speed; render memory");
    command->add_option("--out-dir", options->outDir, "Folder for the outputs (default: current)");
    command->add_flag("--quick", options->quick, "Small frames and few runs (for CI)");
    command->add_option("--runs", options->runs, "Timed runs per measurement (median)")->check(CLI::Range(1, 101));
    command->add_option("--msaa", options->samples, "Samples per pixel of the frames timed (1 = none)")
        ->check(CLI::Range(1, 16));
    return [options] {
        const std::filesystem::path folder = outputFolder(options->outDir);
        // Child processes first, while this one is small: a child's peak RSS includes what
        // its parent had resident when it forked (child_process.h). Missing presets fail here,
        // before the long part.
        BatchResult batch;
        double rssMb = 0.0;
        {
            const TemporaryFolder scratch("patina-bench-render");
            batch = measureBatch(options->quick, scratch.path());
            rssMb = renderPeakRssMb(scratch.path());
        }
        RenderBenchOptions bench;
        bench.quick = options->quick;
        bench.runs = options->quick ? std::min(options->runs, 3) : options->runs;
        bench.samples = options->samples;
        RenderBenchResult result;
        {
            HeadlessContext context;
            result = runRenderBench(bench);
        }

        std::vector<TargetCheck> targets = renderBenchTargets(result);
        const std::string count = std::to_string(batch.images);
        targets.push_back({"one sheet of " + count + " / " + count + " separate renders (time)",
                           batch.sheetSeconds / batch.separateSeconds, 0.2,
                           batch.sheetSeconds / batch.separateSeconds <= 0.2});
        targets.push_back({"peak RSS of patina render, default scene (MB)", rssMb, 150.0, rssMb <= 150.0});

        writeOutputText((folder / "render_bench.csv").string(), renderBenchCsv(result));
        writeOutputText((folder / "render_targets.csv").string(), targetsCsv(targets));
        writeRenderBenchCharts(folder, result);

        std::cout << "on " << result.renderer << ", " << result.width << "x" << result.height << ", "
                  << result.samples << "x MSAA, medians of " << bench.runs << " runs; specialised takes up to "
                  << result.flatLightSlots << " lights as flat inputs where they pay\n";
        for (const TargetCheck& t : targets) {
            std::cout << (t.met ? "  met   " : "  MISSED ") << t.name << ": " << t.value << " (bound " << t.bound
                      << ")\n";
        }
        std::cout << "  batch: " << double(batch.images) / batch.sheetSeconds << " images/s in one sheet ("
                  << batch.size << "x" << batch.size << "), " << double(batch.images) / batch.separateSeconds
                  << " images/s as separate renders\n";
        std::cout << "  glTF: " << result.gltfTriangles << " triangles (" << result.gltfBytes / 1e6
                  << " MB GLB) imported in " << result.gltfLoadSeconds << " s; its hidden faces found in "
                  << result.hiddenFacesSeconds << " s (" << (result.gltfClosed ? "closed" : "not closed") << ")\n";
        for (const TexturedLoadRow& load : result.texturedLoads) {
            std::cout << "  textured model, " << load.maps << " PNG map(s) of " << load.side << "x" << load.side
                      << " (" << load.pngBytes / 1e6 << " MB): " << load.coldSeconds << " s cold, "
                      << load.cachedSeconds << " s from the cache (decoded on up to "
                      << std::thread::hardware_concurrency() << " cores)\n";
        }
        std::cout << "  environment " << result.prefilterSource << " (cube faces of " << result.prefilterFaceSize
                  << "): ready in " << result.prefilterColdSeconds << " s with an empty cache, "
                  << result.prefilterWarmSeconds << " s from the disk cache\n";
    };
}

}  // namespace patina::cli
