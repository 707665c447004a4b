#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <optional>

#include <unistd.h>

#include "cli.h"
#include "gl/gpu_prefilter.h"
#include "gl/headless_context.h"
#include "gl/renderer.h"
#include "picture/display_image.h"
#include "image/image.h"
#include "picture/pbr_tally.h"
#include "inputs.h"
#include "picture_options.h"
#include "reference/channel_image.h"
#include "reference/reference_draws.h"
#include "reference/reference_render.h"

namespace patina::cli {

namespace {
// Ctrl+C during a ground-truth render: finish the pass under way and write what is done.
std::atomic<bool> interrupted{false};
extern "C" void stopAfterThisPass(int) {
    interrupted = true;
}

// The ground truth through pixel centres, pass by pass (reference/reference_render.h), with the
// progress on stderr; stoppable with Ctrl+C.
RenderOutput renderReferenceImage(const PreparedScene& prepared, int width, int height, int samples, bool visibility) {
    const Scene& scene = prepared.scene;
    // The floor the display puts under the model is drawn, and a scene staged with shadows
    // (a light casting them, a ground) counts what blocks the light.
    const std::optional<Mesh> ground = groundOf(prepared);
    const PixelSurfaces surfaces =
        rasterizeSurfaces(referenceDraws(prepared, ground), scene.camera, width, height, prepared.model.get());
    ReferenceRenderOptions options;
    options.samplesPerPixel = samples;
    options.visibility = visibility || stagedWithShadows(scene);
    options.samplesPerPass = std::min(samples, 16);
    const auto start = std::chrono::steady_clock::now();
    const bool terminal = isatty(STDERR_FILENO) != 0;
    interrupted = false;
    auto* previous = std::signal(SIGINT, stopAfterThisPass);
    const ReferenceImage image = renderReference(prepared, surfaces, options, [&](const ReferenceImage& partial) {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        // One line rewritten on a terminal, a line a pass in a log.
        std::fprintf(stderr, "%sreference: %d of %d samples per pixel, %.1f s%s%s", terminal ? "\r" : "",
                     partial.samplesPerPixel, samples, seconds, interrupted ? " (stopped: writing what is done)" : "",
                     terminal ? "" : "\n");
        return !interrupted;
    });
    std::signal(SIGINT, previous);
    if (terminal) {
        std::fprintf(stderr, "\n");
    }
    return {image.value, displayImage(image.value, scene.display, image.backdrop)};
}

// "pbr-validation: 812 of 31070 surface pixels flagged (2.6%): dielectric below 30 sRGB 812, ..."
void reportPbrTally(const PbrTally& tally, const PbrRanges& ranges) {
    std::printf("pbr-validation: %zu of %zu surface pixels flagged (%.1f%%): dielectric below %d sRGB %zu, above %d "
                "%zu; metal below %d %zu\n",
                tally.flagged(), tally.texels, tally.texels ? 100.0 * double(tally.flagged()) / double(tally.texels) : 0.0,
                ranges.dielectricMin, tally.dielectricDark, ranges.dielectricMax, tally.dielectricBright,
                ranges.metalMin, tally.metalDark);
}

// --channel: the GPU's channel render, or with --reference the CPU twin's (reference/
// channel_image.h); the PNG as data, the PFM untouched.
void renderChannel(const SceneInputs& inputs, const ChannelRequest& request, int width, int height, bool reference,
                   const std::string& out, const std::string& hdr) {
    std::optional<HeadlessContext> context;
    if (!reference) {
        context.emplace();
    }
    const LoadedScene loaded(inputs, context ? prefilterCubeOnGpu : prefilterCube);
    const PreparedScene& prepared = loaded.prepared;
    channelLights(loaded.scene.lights, request);   // a light the scene lacks: said before anything is drawn
    HdrImage image;
    if (reference) {
        image = channelImage(prepared, rasterizeSurfaces(prepared, width, height), request);
    } else {
        Renderer renderer;
        RenderSettings settings;
        settings.width = width;
        settings.height = height;
        settings.channel = request;
        settings.maxTargetBytes = kOneOffTargetBytes;
        image = renderer.render(prepared, settings).hdr;
    }
    const LdrImage shown = channelDisplayImage(image, request.channel, request.srgb);
    const std::vector<uint8_t> png = encodePng(shown);
    if (!hdr.empty()) {
        writeOutput(hdr, encodePfm(image));
    }
    writeOutput(out, png);
    if (request.channel == shader::CHANNEL_PBR_VALIDATION) {
        reportPbrTally(tallyPbrChannel(shown), request.strictPbr ? PbrRanges::strict() : PbrRanges{});
    }
}

struct RenderOptions {
    PictureOptions picture;
    std::string out, hdr;
    bool reference = false;
    int referenceSamples = 256;
    bool visibility = false;
    std::string channel;
    bool channelSrgb = false;
    bool pbrStrict = false;
};

void addRenderOptions(CLI::App& command, RenderOptions& options) {
    options.picture.addOptions(command);
    command.add_option("--out", options.out, "Output PNG")->required();
    command.add_option("--hdr", options.hdr, "Also write the linear image (PFM), before exposure and tone map");
    CLI::Option* reference = command.add_flag(
        "--reference", options.reference,
        "The ground truth instead: each pixel centre by Monte Carlo (the environment by MIS, the lights exactly), pass "
        "by pass; Ctrl+C writes what is done");
    command.add_option("--reference-samples", options.referenceSamples,
                       "--reference: estimator iterations per pixel (3 directions each)")
        ->check(CLI::Range(1, 1 << 20));
    command.add_flag("--visibility", options.visibility,
                     "--reference: with shadows and occlusion, every light and the environment blocked by the scene's "
                     "own surfaces (shadow rays through Embree; hemisphere lights are not shadowed), as it is without "
                     "asking where a light casts shadows or the display has a ground")
        ->needs(reference);
    command.add_option("--channel", options.channel,
                       "A debug channel instead of the radiance, as data (no exposure or tone map; docs/INSPECTOR.md): " +
                            channelNameList())
        ->check(CLI::Validator(
            [](std::string& name) {
                return channelFromName(name) ? std::string() : "unknown channel \"" + name + "\" (known: " + channelNameList() + ")";
            },
            "CHANNEL"));
    command.add_flag("--channel-srgb", options.channelSrgb,
                     "--channel: the PNG sRGB-encoded, for colour channels (default: the values themselves)");
    command.add_flag("--pbr-strict", options.pbrStrict,
                     "--channel pbr-validation: the strict ranges (dielectric 50-240 sRGB, metal from 180)");
}

// The PNG (and the PFM when asked for) of what `render` drew, both encoded before either is
// written, so that a failure leaves no output behind.
void writeRenderOutput(const RenderOptions& options, const RenderOutput& output) {
    const std::vector<uint8_t> png = encodePng(output.ldr);
    const std::vector<uint8_t> pfm = options.hdr.empty() ? std::vector<uint8_t>{} : encodePfm(output.hdr);
    if (!options.hdr.empty()) {
        writeOutput(options.hdr, pfm);
    }
    writeOutput(options.out, png);
}

void runRender(const RenderOptions& options) {
    if (!options.channel.empty()) {
        ChannelRequest request = *channelFromName(options.channel);   // the option's check passed it
        request.srgb = options.channelSrgb;
        request.strictPbr = options.pbrStrict;
        renderChannel(options.picture.inputs, request, options.picture.width, options.picture.height,
                      options.reference, options.out, options.hdr);
        return;
    }
    // The context first when the GPU renders: an environment the scene names is then
    // prefiltered on it too.
    std::optional<HeadlessContext> context;
    if (!options.reference) {
        context.emplace();
    }
    const LoadedScene loaded(options.picture.inputs, context ? prefilterCubeOnGpu : prefilterCube);
    const PreparedScene& prepared = loaded.prepared;
    writeRenderOutput(options, options.reference ? renderReferenceImage(prepared, options.picture.width,
                                                                        options.picture.height, options.referenceSamples,
                                                                        options.visibility)
                                                 : Renderer().render(prepared, options.picture.settings(!options.hdr.empty())));
}
}  // namespace

Command addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command = app.add_subcommand("render", "Render a scene to an sRGB PNG (headless)");
    addRenderOptions(*command, *options);
    return [options] { runRender(*options); };
}

}  // namespace patina::cli
