#include <memory>

#include "cli.h"
#include "gltf/export.h"
#include "io/file_kinds.h"
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
        // The triangles as every command loads them: a built-in's, or the glTF file's.
        Scene source;
        if (const auto kind = meshKindFromName(options->mesh)) {
            source.mesh = *kind;
        } else {
            source.meshFile = options->mesh;
        }
        AssetCache assets;
        const std::shared_ptr<const Mesh> mesh = assets.mesh(source);
        try {
            exportGltf(options->out, *mesh, material, options->binFile ? GltfBuffer::BinFile : GltfBuffer::Embedded);
        } catch (const InputError&) {
            throw;
        } catch (const std::runtime_error& error) {
            throw InputError(error.what());   // an unwritable path, as for every command
        }
    };
}

}  // namespace patina::cli
