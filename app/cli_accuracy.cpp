// The speed/accuracy commands: bench, stability, furnace, lighting-accuracy and diffuse-accuracy,
// and what they share with the other measurements (cli.h). Each writes into --out-dir (default:
// the current folder).
#include <algorithm>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>

#include "bench/bench.h"
#include "bench/lighting_accuracy.h"
#include "accuracy/model_split_sum.h"
#include "assets/asset_cache.h"
#include "cli.h"
#include "accuracy/diffuse_accuracy.h"
#include "accuracy/furnace.h"
#include "environment/builtin_environments.h"
#include "gl/gpu_prefilter.h"
#include "gl/headless_context.h"
#include "image/image.h"
#include "files/input_error.h"
#include "inputs.h"
#include "accuracy/stability.h"

namespace patina::cli {

void writeChart(const std::filesystem::path& stem, const Chart& chart, bool vector) {
    if (vector) {
        writeOutputText(stem.string() + ".svg", chartToSvg(chart));
        writeOutputText(stem.string() + ".pdf", chartToPdf(chart));
    }
    writeOutput(stem.string() + ".png", encodePng(chartToImage(chart)));
}

// The folder named, made where missing (as turntable's --out is): a measurement that runs for
// minutes should not end on a folder that was not there.
std::filesystem::path outputFolder(const std::string& folder) {
    const std::filesystem::path path = folder.empty() ? "." : folder;
    std::error_code error;
    std::filesystem::create_directories(path, error);
    if (!std::filesystem::is_directory(path)) {
        throw InputError(path.string() + ": not a folder" + (error ? " (" + error.message() + ")" : ""));
    }
    return path;
}

void writeBenchChart(const std::filesystem::path& folder, const BenchResult& result) {
    writeChart(folder / "speed_accuracy", benchChart(result), true);
}

void writeLightingChart(const std::filesystem::path& folder, const LightingAccuracyResult& result) {
    writeChart(folder / "lighting_accuracy", lightingAccuracyChart(result), true);
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
            writeBenchChart(folder, result);
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
        app, "furnace",
        "White furnace: specular albedo with F = 1 of every model (furnace.csv, furnace.png), and a white "
        "dielectric, metal and thin-walled glass (reflected + transmitted) whole, split sum and ground truth, under "
        "epic, gltf and gltf-single (material_furnace.csv)",
        [](const std::filesystem::path& folder, bool quick) {
            const std::vector<FurnaceCurve> curves = whiteFurnace(quick ? 10 : 40, quick ? 1024 : 4096);
            writeOutputText((folder / "furnace.csv").string(), furnaceCsv(curves));
            writeChart(folder / "furnace", furnaceChart(curves), false);
            const std::vector<MaterialFurnaceRow> materials = materialFurnace(
                {BrdfModelId::Epic, BrdfModelId::Gltf, BrdfModelId::GltfSingle}, quick ? 4 : 10, quick ? 256 : 2048);
            writeOutputText((folder / "material_furnace.csv").string(), materialFurnaceCsv(materials));
        });
}

namespace {
// Blender's studio-light HDRIs (Debian's blender-data): one with a sun, one interior.
constexpr const char* kBlenderWorlds = "/usr/share/blender/datafiles/studiolights/world/";

std::vector<NamedEnvironment> lightingEnvironments(const std::vector<std::string>& files, PrefilterFunction prefilter) {
    std::vector<std::string> sources = files;
    if (sources.empty()) {
        sources = {builtinSource("studio")};
        for (const char* name : {"sunrise.exr", "interior.exr"}) {
            const std::filesystem::path path = std::filesystem::path(kBlenderWorlds) / name;
            if (std::filesystem::is_regular_file(path)) {
                sources.push_back(path.string());
            } else {
                std::cerr << "lighting-accuracy: " << path.string()
                          << " is not installed (apt-get install blender-data); measured without it\n";
            }
        }
    }
    std::vector<NamedEnvironment> environments;
    AssetCache assets;
    for (const std::string& source : sources) {
        std::vector<std::string> warnings;
        const std::string absolute =
            builtinName(source) ? source : std::filesystem::absolute(source).lexically_normal().string();
        std::shared_ptr<const Environment> environment = assets.environment(absolute, warnings, {}, {}, prefilter);
        printWarnings(warnings);
        environments.push_back({environmentName(source), std::move(environment)});
    }
    return environments;
}
// What diffuse-accuracy measures under by default: the built-in studio, every Blender HDRI
// installed, and a small sun 10^4 times its sky's radiance (sunEnvironment), made here.
std::vector<NamedEnvironment> diffuseEnvironments(const std::vector<std::string>& files, PrefilterFunction prefilter) {
    std::vector<std::string> sources = files;
    if (sources.empty()) {
        sources = {builtinSource("studio")};
        std::error_code error;
        for (const auto& entry : std::filesystem::directory_iterator(kBlenderWorlds, error)) {
            if (entry.path().extension() == ".exr") {
                sources.push_back(entry.path().string());
            }
        }
        std::sort(sources.begin() + 1, sources.end());
        if (sources.size() == 1) {
            std::cerr << "diffuse-accuracy: " << kBlenderWorlds
                      << " holds no HDRIs (apt-get install blender-data); measured without them\n";
        }
    }
    std::vector<NamedEnvironment> environments = lightingEnvironments(sources, prefilter);
    for (NamedEnvironment& environment : environments) {
        if (builtinName(environment.environment->source)) {
            environment.name = "built-in " + environment.name;   // beside Blender's studio.exr
        }
    }
    if (files.empty()) {
        environments.push_back({"sun", prepareEnvironment(sunEnvironment(1024), "generated:sun", {}, {}, prefilter)});
    }
    return environments;
}
}  // namespace

// A measurement under environments: --out-dir, --quick and --environment F (repeatable), whose
// default `defaults` names.
using EnvironmentMeasurement =
    std::function<void(const std::filesystem::path&, bool, const std::vector<std::string>&)>;
Command addEnvironmentMeasurementCommand(CLI::App& app, const char* name, const std::string& description,
                                         const std::string& defaults, EnvironmentMeasurement measure) {
    struct Options {
        std::string outDir;
        bool quick = false;
        std::vector<std::string> environments;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(name, description);
    command->add_option("--out-dir", options->outDir, "Folder for the outputs (default: current)");
    command->add_flag("--quick", options->quick, "A smaller, faster run (for CI)");
    command->add_option("--environment", options->environments,
                        "An .hdr or .exr to measure under (repeatable; default: " + defaults + ")");
    return [options, measure] { measure(outputFolder(options->outDir), options->quick, options->environments); };
}

Command addDiffuseAccuracyCommand(CLI::App& app) {
    return addEnvironmentMeasurementCommand(
        app, "diffuse-accuracy",
        "The environment's diffuse light against the ground truth: the irradiance against the exact cosine "
        "convolution (irradiance.csv), and a matte cube and sphere rendered against the reference render "
        "(matte.csv)",
        "builtin:studio, every Blender HDRI installed and a generated sun",
        [](const std::filesystem::path& folder, bool quick, const std::vector<std::string>& files) {
            HeadlessContext context;
            const std::vector<NamedEnvironment> environments = diffuseEnvironments(files, prefilterCubeOnGpu);   // the context is current
            std::vector<IrradianceErrorRow> irradiance;
            std::vector<MatteRow> matte;
            for (const NamedEnvironment& environment : environments) {
                const std::vector<IrradianceErrorRow> rows =
                    measureIrradiance(environment, quick ? 64 : 256, quick ? 256 : 4096);
                irradiance.insert(irradiance.end(), rows.begin(), rows.end());
                for (EnvironmentMethod method : {EnvironmentMethod::SplitSum, EnvironmentMethod::Dominant}) {
                    for (MatteShape shape : {MatteShape::Cube, MatteShape::Sphere}) {
                        MatteOptions options;
                        options.size = quick ? 32 : 64;
                        options.samples = quick ? 256 : 1024;
                        options.shading.method = method;
                        matte.push_back(measureMatte(environment, shape, options));
                    }
                }
                std::cerr << "diffuse-accuracy: " << environment.name << " measured\n";
            }
            writeOutputText((folder / "irradiance.csv").string(), irradianceCsv(irradiance));
            writeOutputText((folder / "matte.csv").string(), matteCsv(matte));
            std::cout << matteCsv(matte);
        });
}

Command addLightingAccuracyCommand(CLI::App& app) {
    return addEnvironmentMeasurementCommand(
        app, "lighting-accuracy",
        "The split sum and its variants against the ground truth under environments, with their frame cost: "
        "split_sum.csv, lighting_cost.csv, lighting_accuracy.svg/.png and a grid_<environment>.png each; "
        "whole materials by BRDF model (epic, gltf, gltf-single) against their ground truth: model_split_sum.csv; "
        "and sphere and tube lights as area-accuracy measures them",
        "builtin:studio and Blender's sunrise.exr and interior.exr when installed",
        [](const std::filesystem::path& folder, bool quick, const std::vector<std::string>& files) {
            const std::vector<NamedEnvironment> environments = lightingEnvironments(files, prefilterCube);
            HeadlessContext context;
            const LightingAccuracyResult result = runLightingAccuracy(environments, quick);
            writeOutputText((folder / "split_sum.csv").string(), splitSumCsv(result.accuracy.rows));
            writeOutputText((folder / "lighting_cost.csv").string(), lightingCostCsv(result));
            writeLightingChart(folder, result);
            for (const NamedEnvironment& environment : environments) {
                writeOutput((folder / ("grid_" + environment.name + ".png")).string(),
                            encodePng(roughnessMetallicGrid(environment, quick ? 48 : 128, quick ? 8 : 256)));
            }
            std::cout << lightingCostCsv(result);
            const std::vector<BrdfModelId> models = {BrdfModelId::Epic, BrdfModelId::Gltf, BrdfModelId::GltfSingle};
            writeOutputText((folder / "model_split_sum.csv").string(),
                            modelSplitSumCsv(measureModelSplitSum(environments, models, quick)));
            writeAreaAccuracy(folder, quick);
        });
}

}  // namespace patina::cli
