// `patina turntable`: one whole turn of the camera about the scene's target, as numbered PNGs
// or one animated PNG.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli.h"
#include "files/input_error.h"
#include "gl/gpu_prefilter.h"
#include "gl/headless_context.h"
#include "gl/renderer.h"
#include "image/animated_png.h"
#include "image/image.h"
#include "io/file_kinds.h"
#include "picture_options.h"
#include "scene/camera_control.h"

namespace patina::cli {

namespace {
// Half a degree a frame at most: the animated PNG holds every frame in memory until written.
constexpr int kMaxTurntableFrames = 720;

struct TurntableOptions {
    PictureOptions picture;
    int frames = 0;
    int fps = 30;
    std::string out;
};

// "frame_007.png": as many digits as the last frame's number needs, three at least, so that
// the names sort in the frames' order.
std::string frameName(int frame, int frames) {
    const int digits = std::max(3, int(std::to_string(frames - 1).size()));
    char name[32];
    std::snprintf(name, sizeof name, "frame_%0*d.png", digits, frame);
    return name;
}

// Before anything is drawn: the folder the frames go into, made where missing, or the folder
// the animated PNG goes into, which must be there. InputError for either that cannot be.
void checkOutput(const std::string& out, bool animated) {
    const std::filesystem::path path(out);
    std::error_code error;
    if (animated) {
        const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
        if (!std::filesystem::is_directory(folder, error)) {
            throw InputError("--out " + out + ": there is no folder " + folder.string() + " to write it in");
        }
        return;
    }
    if (std::filesystem::exists(path, error) && !std::filesystem::is_directory(path, error)) {
        throw InputError("--out " + out + ": a file, not a folder (end the name in .png for one animated PNG)");
    }
    std::filesystem::create_directories(path, error);
    if (error) {
        throw InputError("--out " + out + ": cannot make the folder: " + error.message());
    }
}

void runTurntable(const TurntableOptions& options) {
    const bool animated = lowerExtension(options.out) == ".png";
    checkOutput(options.out, animated);
    HeadlessContext context;   // first: an environment the scene names is prefiltered on it too
    LoadedScene loaded(options.picture.inputs, prefilterCubeOnGpu);
    Scene& scene = loaded.scene;   // its camera turns; `prepared` reads it
    const PreparedScene& prepared = loaded.prepared;
    const Camera start = scene.camera;
    Renderer renderer;
    const RenderSettings settings = options.picture.settings(false);
    std::vector<std::vector<uint8_t>> pngs;
    for (int frame = 0; frame < options.frames; ++frame) {
        scene.camera = turntableCamera(start, float(360.0 * frame / options.frames));
        std::vector<uint8_t> png = encodePng(renderer.render(prepared, settings).ldr);
        if (animated) {
            pngs.push_back(std::move(png));
        } else {
            writeOutput((std::filesystem::path(options.out) / frameName(frame, options.frames)).string(), png);
        }
    }
    if (animated) {
        writeOutput(options.out, encodeAnimatedPng(pngs, {1, uint16_t(options.fps)}));
    }
}
}  // namespace

Command addTurntableCommand(CLI::App& app) {
    auto options = std::make_shared<TurntableOptions>();
    CLI::App* command = app.add_subcommand(
        "turntable", "Render one whole turn of the camera about the scene's target (the vertical axis through it), "
                     "frame k of N at 360 k / N degrees: N PNGs in a folder, or one animated PNG");
    options->picture.addOptions(*command);
    command->add_option("--frames", options->frames, "Frames in the turn")
        ->required()
        ->check(CLI::Range(1, kMaxTurntableFrames));
    command->add_option("--fps", options->fps, "The animated PNG's frames a second")->check(CLI::Range(1, 120));
    command->add_option("--out", options->out,
                        "A folder (made if missing) for frame_000.png, frame_001.png, ...; or a .png file: one "
                        "animated PNG (APNG) of every frame, looped")
        ->required();
    return [options] { runTurntable(*options); };
}

}  // namespace patina::cli
