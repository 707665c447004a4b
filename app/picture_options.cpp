#include "picture_options.h"

namespace patina::cli {

void PictureOptions::addOptions(CLI::App& command) {
    inputs.addOptions(command, true, true);
    inputs.view.addOptions(command);
    command.add_option("--width", width, "Image width")->check(CLI::Range(1, 16384));
    command.add_option("--height", height, "Image height")->check(CLI::Range(1, 16384));
    command.add_option("--passes", passes, "single: all lights in one pass; multi: one pass per light; "
                       "specialised: one pass compiled for the scene's lights")
        ->check(CLI::IsMember({"single", "multi", "specialised"}));
    command.add_option("--msaa", samples, "Samples per pixel (1 = none)")->check(CLI::Range(1, 16));
    command.add_option("--environment-method", environmentMethod,
                       "How an environment lights the mesh: split-sum (Karis 2013, the default), dominant (the split "
                       "sum along the dominant direction) or stochastic (filtered importance samples; docs/LIGHTING.md)")
        ->check(CLI::IsMember({"split-sum", "dominant", "stochastic"}));
    command.add_option("--environment-samples", environmentSamples,
                       "--environment-method stochastic: samples per pixel")
        ->check(CLI::Range(1, 256));
}

RenderSettings PictureOptions::settings(bool readHdr) const {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.path = *renderPathFromName(passes);   // the option's check passed it
    settings.samples = samples;
    settings.environment = {*environmentMethodFromName(environmentMethod), environmentSamples};
    // A one-off render keeps its peak memory down: strips of at most 16 MiB of
    // multisampled colour, and the linear image read back only when asked for.
    settings.maxTargetBytes = kOneOffTargetBytes;
    settings.readHdr = readHdr;
    return settings;
}

}  // namespace patina::cli
