#include <algorithm>
#include <cstdio>
#include <memory>

#include "cli.h"
#include "picture/compositing.h"
#include "inputs.h"
#include "material_renders.h"

namespace patina::cli {

Command addCompareCommand(CLI::App& app) {
    struct Options {
        ViewOptions view;
        std::string scenePath, a, b, out, part, mesh;
        int width = 512, height = 512;
        bool diff = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "compare", "Render two materials in one scene side by side, captioned, as a PNG");
    command->add_option("A", options->a, "Material JSON on the left")->required();
    command->add_option("B", options->b, "Material JSON on the right")->required();
    command->add_option("--scene", options->scenePath, "Scene JSON (default: the embedded scene)");
    command->add_option("--width", options->width, "Width of each panel")->check(CLI::Range(1, 4096));
    command->add_option("--height", options->height, "Height of each panel")->check(CLI::Range(1, 4096));
    command->add_option("--out", options->out, "Output PNG")->required();
    addMeshOption(*command, options->mesh);
    options->view.addOptions(*command);
    command->add_option("--part", options->part,
                        "With a glTF model: A and B on the parts of this material name only (default: every part)");
    command->add_flag("--diff", options->diff, "Add a third panel: the difference as a heat map");
    return [options] {
        SceneInputs inputs;
        inputs.scenePath = options->scenePath;
        inputs.mesh = options->mesh;
        inputs.view = options->view;
        const LoadedScene loaded(inputs);
        const PreparedScene& prepared = loaded.prepared;
        const std::vector<Material> materials = loadMaterials({options->a, options->b});
        std::vector<LdrImage> panels =
            renderMaterials(prepared, materials, {options->width, options->height, options->part});
        std::vector<std::string> captions{materialCaption(materials[0], options->width),
                                          materialCaption(materials[1], options->width)};
        if (options->diff) {
            const DifferenceStats stats = differenceStats(panels[0], panels[1]);
            char caption[96];
            std::snprintf(caption, sizeof caption, "difference  max %d  mean %.2f (of 255)",
                          stats.max, stats.mean);
            panels.push_back(differenceHeatMap(panels[0], panels[1]));
            captions.emplace_back(caption);
        }
        writeOutput(options->out, encodePng(contactSheet(panels, captions, int(panels.size()))));
    };
}

}  // namespace patina::cli
