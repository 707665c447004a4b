#pragma once
// What the commands that draw the scene's picture on the GPU (render, turntable) share: the
// scene and the view (SceneInputs with --mesh, --part and ViewOptions), the image's size and
// how the renderer draws it.
#include <string>

#include <CLI/CLI.hpp>

#include "gl/renderer.h"
#include "inputs.h"

namespace patina::cli {

struct PictureOptions {
    SceneInputs inputs;
    int width = 800, height = 800, samples = 4;
    std::string passes = "single";
    std::string environmentMethod = "split-sum";
    int environmentSamples = 16;

    // --scene, --material, --part, --mesh, --model, the view options, --width, --height,
    // --passes, --msaa, --environment-method and --environment-samples.
    void addOptions(CLI::App& command);
    // The renderer's settings for one picture of that size: a one-off render's (strips of at
    // most kOneOffTargetBytes), the linear image kept only with `readHdr`.
    RenderSettings settings(bool readHdr) const;
};

}  // namespace patina::cli
