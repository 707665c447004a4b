// patina: the editor (no subcommand) and the command line. Exit codes: 0 success, 2 usage error, 3 bad input (a file or value
// that cannot be used; the message names it), 1 anything else (e.g. no OpenGL).
#include <filesystem>
#include <iostream>

#include "cli.h"
#include "window/editor_app.h"
#include "files/input_error.h"

int main(int argc, char** argv) {
    CLI::App app{"Patina: a live editor for physically based materials (Karis 2013 shading)"};
    app.require_subcommand(0, 1);
    patina::editor::EditorOptions editor;   // its start time: now, for --stats
    app.add_option("file", editor.files, "Without a subcommand: open the editor on this material or scene (.json), "
                                         "Patina screenshot (.png), glTF model (.gltf, .glb) or environment image "
                                         "(.hdr, .exr)");
    app.add_flag("--stats", editor.stats, "Editor: log time to first frame, frame times while dragging and peak "
                                          "memory to stderr");
    std::vector<std::pair<CLI::App*, patina::cli::Command>> commands;
    for (auto add : {patina::cli::addRenderCommand, patina::cli::addTurntableCommand, patina::cli::addProbeCommand,
                     patina::cli::addLobeCommand, patina::cli::addSliceCommand,
                     patina::cli::addAlbedoCommand, patina::cli::addCompareCommand,
                     patina::cli::addSheetCommand, patina::cli::addBenchCommand,
                     patina::cli::addBenchRenderCommand,
                     patina::cli::addStabilityCommand, patina::cli::addFurnaceCommand,
                     patina::cli::addLightingAccuracyCommand, patina::cli::addDiffuseAccuracyCommand,
                     patina::cli::addAreaAccuracyCommand, patina::cli::addShadowAccuracyCommand,
                     patina::cli::addExportCommand, patina::cli::addValidateCommand,
                     patina::cli::addInspectCommand, patina::cli::addChartCommand,
                     patina::cli::addDifferenceCommand}) {
        patina::cli::Command run = add(app);
        commands.emplace_back(app.get_subcommands({}).back(), std::move(run));
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? 0 : 2;
    }
    if (app.get_subcommands().empty()) {
        // A missing file does not keep the editor shut: it opens and says so there (and here,
        // for a terminal without a window). A bare word that is no file is a subcommand
        // mistyped, and refused.
        for (const std::string& file : editor.files) {
            std::error_code error;
            if (std::filesystem::exists(file, error)) {
                continue;
            }
            if (!std::filesystem::path(file).has_extension()) {
                std::cerr << "error: " << file << ": neither a subcommand nor a file (see patina --help)\n";
                return 3;
            }
            std::cerr << "warning: " << file << ": no such file; the editor opens without it\n";
        }
        return patina::editor::runEditor(editor);
    }
    try {
        for (auto& [subcommand, run] : commands) {
            if (subcommand->parsed()) {
                run();
            }
        }
    } catch (const patina::InputError& error) {
        std::cerr << "error: " << error.what() << "\n";
        return 3;
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
