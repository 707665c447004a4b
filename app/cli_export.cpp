#include <memory>

#include "cli.h"
#include "gltf/export.h"
#include "gltf/import.h"
#include "io/input_error.h"
#include "inputs.h"

namespace patina::cli {

Command addExportCommand(CLI::App& app) {
    struct Options {
        SceneInputs inputs;
        std::string mesh = "sphere", out;
        bool binFile = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("export", "Write a mesh with a material as glTF 2.0 (.gltf or .glb)");
    options->inputs.addOptions(*command, false);
    command->add_option("--mesh", options->mesh, "sphere, torus, or a .gltf/.glb file to take the triangles from");
    command->add_option("--out", options->out, "Output .gltf or .glb")
        ->required()
        ->check(CLI::Validator(
            [](const std::string& path) {
                return gltfExtension(path).empty() ? std::string("must end in .gltf or .glb") : std::string();
            },
            "F.gltf|F.glb"));
    command->add_flag("--bin", options->binFile, "With .gltf: the buffer in F.bin beside it, not a data: URI");
    return [options] {
        const Material material = options->inputs.load().material;
        const auto kind = meshKindFromName(options->mesh);
        const Mesh mesh = kind ? makeMesh(*kind) : importGltf(options->mesh).mesh;
        try {
            exportGltf(options->out, mesh, material, options->binFile ? GltfBuffer::BinFile : GltfBuffer::Embedded);
        } catch (const InputError&) {
            throw;
        } catch (const std::runtime_error& error) {
            throw InputError(error.what());   // an unwritable path, as for every command
        }
    };
}

}  // namespace patina::cli
