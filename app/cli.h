#pragma once
#include <CLI/CLI.hpp>

namespace patina::cli {

// Each subcommand registers its options on `app` and returns the callback that runs it once
// parsing succeeded. Callbacks throw InputError for bad input (exit 3).
using Command = std::function<void()>;

Command addRenderCommand(CLI::App& app);
Command addProbeCommand(CLI::App& app);
Command addLobeCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addSheetCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addBenchRenderCommand(CLI::App& app);
Command addStabilityCommand(CLI::App& app);
Command addFurnaceCommand(CLI::App& app);
Command addLightingAccuracyCommand(CLI::App& app);
Command addExportCommand(CLI::App& app);

}  // namespace patina::cli
