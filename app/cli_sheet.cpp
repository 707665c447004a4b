#include <future>
#include <memory>
#include <optional>
#include <stdexcept>

#include "cli.h"
#include "picture/compositing.h"
#include "files/input_error.h"
#include "inputs.h"
#include "material_renders.h"
#include "image/png_stream.h"

namespace patina::cli {

Command addSheetCommand(CLI::App& app) {
    struct Options {
        ViewOptions view;
        std::string scenePath, out, part, mesh;
        std::vector<std::string> materials;
        int columns = 4, size = 256;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "sheet", "Render materials in one scene as a captioned contact sheet PNG");
    command->add_option("materials", options->materials, "Material JSON files")->required();
    command->add_option("--out", options->out, "Output PNG")->required();
    command->add_option("--columns", options->columns, "Cells per row")->check(CLI::Range(1, 256));
    command->add_option("--size", options->size, "Width and height of each cell")
        ->check(CLI::Range(1, 4096));
    command->add_option("--scene", options->scenePath, "Scene JSON (default: the embedded scene)");
    addMeshOption(*command, options->mesh);
    options->view.addOptions(*command);
    command->add_option("--part", options->part,
                        "With a glTF model: each material on the parts of this material name only (default: every part)");
    return [options] {
        SceneInputs inputs;
        inputs.scenePath = options->scenePath;
        inputs.mesh = options->mesh;
        inputs.view = options->view;
        const LoadedScene loaded(inputs);
        const PreparedScene& prepared = loaded.prepared;
        const std::vector<Material> materials = loadMaterials(options->materials);
        std::vector<std::string> names;
        for (const Material& material : materials) {
            names.push_back(material.name);
        }
        try {   // refuse an oversized sheet before rendering anything
            sheetLayout(options->size, options->size, int(names.size()), options->columns);
        } catch (const std::invalid_argument& error) {
            throw InputError(std::string("the sheet is too large: ") + error.what() +
                             "; use a smaller --size or other --columns");
        }
        // Filling the sheet's pixels is mostly the kernel's first touch of each page (24 cells
        // at 512: 26 MB, 25-40 ms); a worker does it while this thread starts the GL context
        // and compiles the first shader.
        std::future<std::unique_ptr<SheetBuilder>> filling = std::async(std::launch::async, [&] {
            return std::make_unique<SheetBuilder>(options->size, options->size, names, options->columns);
        });
        std::unique_ptr<SheetBuilder> sheet;
        // Each finished row of cells is deflated while the next renders: a sheet's renders
        // leave part of the second core idle.
        std::optional<PngStream> png;
        auto take = [&] {
            if (!sheet) {
                sheet = filling.get();
                png.emplace(sheet->image());
            }
        };
        renderMaterials(prepared, materials, {options->size, options->size, options->part}, [&](LdrImage&& cell) {
            take();
            sheet->add(cell);
            png->rowsReady(sheet->finishedRows());
        });
        take();
        writeOutput(options->out, png->finish());
    };
}

}  // namespace patina::cli
