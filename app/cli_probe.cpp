#include <memory>

#include "cli.h"
#include "gl/gpu_probe.h"
#include "gl/headless_context.h"
#include "inputs.h"
#include "accuracy/probe_csv.h"
#include "reference/probe_reference.h"
#include "scene/probe.h"

namespace patina::cli {

Command addProbeCommand(CLI::App& app) {
    struct Options {
        SceneInputs inputs;
        std::string in, out, backend = "gpu";
        int samples = 4096;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "probe", "Shade given points (CSV px..vz) and write the linear radiance (CSV r,g,b)");
    options->inputs.addOptions(*command);
    command->add_option("--in", options->in, "Input CSV: px,py,pz,nx,ny,nz,vx,vy,vz")->required();
    command->add_option("--out", options->out, "Output CSV: r,g,b")->required();
    command->add_option("--backend", options->backend,
                        "gpu: the real shader; cpu: the same code as C++; reference: the ground truth by Monte "
                        "Carlo (environment, sphere and tube lights; the other lights exactly), with standard errors")
        ->check(CLI::IsMember({"cpu", "gpu", "reference"}));
    command->add_option("--samples", options->samples, "reference: iterations per row (3 directions each)")
        ->check(CLI::Range(1, 1 << 24));
    return [options] {
        const Scene scene = options->inputs.load();
        // The environment alone: a probe shades given points, never the scene's mesh.
        AssetCache assets;
        std::shared_ptr<const Environment> environment;
        if (const Light* light = enabledEnvironment(scene)) {
            std::vector<std::string> warnings;
            environment = assets.environment(light->source, warnings);
            printWarnings(warnings);
        }
        const std::vector<ProbeSample> samples =
            parseProbeCsv(readInputText(options->in), options->in);
        std::string csv;
        if (options->backend == "reference") {
            csv = formatReferenceCsv(
                probeReference(scene.material, scene.lights, samples, environment, options->samples));
        } else if (options->backend == "cpu") {
            csv = formatRadianceCsv(probeOnCpu(scene.material, scene.lights, samples, environment));
        } else {
            HeadlessContext context;
            GpuProbe probe;
            csv = formatRadianceCsv(probe.evaluate(scene.material, scene.lights, samples, environment));
        }
        writeOutput(options->out, std::vector<uint8_t>(csv.begin(), csv.end()));
    };
}

}  // namespace patina::cli
