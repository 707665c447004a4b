#include <memory>

#include "cli.h"
#include "inputs.h"
#include "shading/lobe.h"

namespace patina::cli {

Command addLobeCommand(CLI::App& app) {
    struct Options {
        SceneInputs inputs;
        float thetaIn = 0.0f;
        int samples = 181;
        std::string out;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "lobe", "Write the BRDF in the plane of incidence (1/sr, no cosine) as CSV");
    options->inputs.addOptions(*command, false);
    command->add_option("--theta-in", options->thetaIn, "Angle of L from the normal, degrees")
        ->required()->check(CLI::Range(-90.0f, 90.0f));
    command->add_option("--samples", options->samples, "Angles from -90 to 90 degrees")
        ->check(CLI::Range(2, 1000000));
    command->add_option("--out", options->out, "Output CSV")->required();
    return [options] {
        const Scene scene = options->inputs.load();
        const std::string csv =
            formatLobeCsv(evaluateLobe(scene.material, options->thetaIn, options->samples));
        writeOutput(options->out, std::vector<uint8_t>(csv.begin(), csv.end()));
    };
}

}  // namespace patina::cli
