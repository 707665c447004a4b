#pragma once
#include <filesystem>

#include <CLI/CLI.hpp>

#include "image/chart.h"

namespace patina {
struct BenchResult;
struct LightingAccuracyResult;
struct RenderBenchResult;
}  // namespace patina

namespace patina::cli {

// Each subcommand registers its options on `app` and returns the callback that runs it once
// parsing succeeded. Callbacks throw InputError for bad input (exit 3).
using Command = std::function<void()>;

Command addRenderCommand(CLI::App& app);
// `patina turntable`: a whole turn of the camera as PNGs or an animated PNG.
Command addTurntableCommand(CLI::App& app);
Command addProbeCommand(CLI::App& app);
Command addLobeCommand(CLI::App& app);
Command addSliceCommand(CLI::App& app);
Command addAlbedoCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addSheetCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addBenchRenderCommand(CLI::App& app);
Command addStabilityCommand(CLI::App& app);
Command addFurnaceCommand(CLI::App& app);
Command addLightingAccuracyCommand(CLI::App& app);
Command addDiffuseAccuracyCommand(CLI::App& app);
Command addExportCommand(CLI::App& app);
Command addAreaAccuracyCommand(CLI::App& app);
// `patina shadow-accuracy`: shadow maps against the ground truth with visibility.
Command addShadowAccuracyCommand(CLI::App& app);
// `patina inspect`: one pixel's story as JSON.
Command addInspectCommand(CLI::App& app);
// `patina chart`: a measurement's charts redrawn from the CSVs it wrote, measuring nothing.
Command addChartCommand(CLI::App& app);
// `patina difference`: linear images of one view compared as displayed, as CSV.
Command addDifferenceCommand(CLI::App& app);
// `patina validate`: exit 1 when a material is out of range (the lines say which).
Command addValidateCommand(CLI::App& app);

// The measurement commands (cli_accuracy.cpp) share their options, --out-dir (an existing
// folder, default: the current one) and --quick, and their charts' files.
using Measurement = std::function<void(const std::filesystem::path& folder, bool quick)>;
Command addMeasurementCommand(CLI::App& app, const char* name, const char* description, Measurement measure);
// STEM.png, and with `vector` STEM.svg and STEM.pdf: the same drawing on each surface.
void writeChart(const std::filesystem::path& stem, const Chart& chart, bool vector);
// `folder` as given (empty: the current one), made with its parents where missing; InputError when
// it is a file or cannot be made.
std::filesystem::path outputFolder(const std::string& folder);
// Each measurement's charts into `folder` under the names its command gives them, from a run
// or from its CSVs (`patina chart`): one definition for both.
void writeBenchChart(const std::filesystem::path& folder, const BenchResult& result);
void writeLightingChart(const std::filesystem::path& folder, const LightingAccuracyResult& result);
void writeRenderBenchCharts(const std::filesystem::path& folder, const RenderBenchResult& result);
// area-accuracy's outputs into `folder` (lighting-accuracy writes them beside its own).
void writeAreaAccuracy(const std::filesystem::path& folder, bool quick);

}  // namespace patina::cli
