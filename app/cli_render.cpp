#include <memory>

#include "cli.h"
#include "gl/headless_context.h"
#include "gl/renderer.h"
#include "image/image.h"
#include "inputs.h"
#include "gltf/scene_mesh.h"

namespace patina::cli {

Command addRenderCommand(CLI::App& app) {
    struct Options {
        SceneInputs inputs;
        int width = 800, height = 800, samples = 4;
        std::string passes = "single", out, hdr;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("render", "Render a scene to an sRGB PNG (headless)");
    options->inputs.addOptions(*command);
    command->add_option("--width", options->width, "Image width")->check(CLI::Range(1, 16384));
    command->add_option("--height", options->height, "Image height")->check(CLI::Range(1, 16384));
    command->add_option("--passes", options->passes, "single: all lights in one pass; multi: one pass per light; "
                        "specialised: one pass compiled for the scene's lights")
        ->check(CLI::IsMember({"single", "multi", "specialised"}));
    command->add_option("--msaa", options->samples, "Samples per pixel (1 = none)")->check(CLI::Range(1, 16));
    command->add_option("--out", options->out, "Output PNG")->required();
    command->add_option("--hdr", options->hdr, "Also write the linear image (PFM), before exposure and tone map");
    return [options] {
        Scene scene = options->inputs.load();
        resolveMesh(scene);
        HeadlessContext context;
        Renderer renderer;
        RenderSettings settings;
        settings.width = options->width;
        settings.height = options->height;
        settings.path = *renderPathFromName(options->passes);
        settings.samples = options->samples;
        // A one-off render keeps its peak memory down: strips of at most 16 MiB of
        // multisampled colour, and the linear image read back only when asked for.
        settings.maxTargetBytes = size_t(16) << 20;
        settings.readHdr = !options->hdr.empty();
        const RenderOutput output = renderer.render(scene, settings);
        // Encode both before writing either, so a failure leaves no output behind.
        const std::vector<uint8_t> png = encodePng(output.ldr);
        const std::vector<uint8_t> pfm = options->hdr.empty() ? std::vector<uint8_t>{} : encodePfm(output.hdr);
        if (!options->hdr.empty()) {
            writeOutput(options->hdr, pfm);
        }
        writeOutput(options->out, png);
    };
}

}  // namespace patina::cli
