// `patina difference REF IMAGE...`: linear images of one view by different renderers (Patina's
// --hdr PFMs, its ground truth's, Blender's OpenEXRs) compared as a user sees them, through one
// exposure and tone curve (image/linear_difference.h): a CSV line per IMAGE on stdout, and with
// --sheet the images and where they differ. scripts/compare_cycles.sh drives it.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "bench/renderer_comparison.h"
#include "cli.h"
#include "environment/environment_files.h"
#include "files/file_bytes.h"
#include "files/input_error.h"
#include "picture/compositing.h"
#include "picture/display_image.h"
#include "picture/linear_difference.h"
#include "inputs.h"

namespace patina::cli {

namespace {

// A PFM (Patina's --hdr) or what an environment may be (OpenEXR, Radiance), told apart by content.
HdrImage readLinearImage(const std::string& path) {
    if (!std::filesystem::is_regular_file(path)) {
        throw InputError(path + ": no such file");
    }
    const std::vector<uint8_t> bytes = readFileBytes(path);
    if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] == 'F') {
        try {
            return decodePfm(bytes);
        } catch (const std::runtime_error& error) {
            throw InputError(path + ": " + error.what());
        }
    }
    return decodeEnvironmentImage(bytes, path);
}

// A cell of the CSV as written: not empty, no comma, quote or line break.
void checkCsvCell(const std::string& text, const std::string& what) {
    if (text.empty() || text.find_first_of(",\"\r\n") != std::string::npos) {
        throw InputError(what + " \"" + text + "\" cannot be a CSV cell: give one without commas, quotes or line breaks");
    }
}

struct Inputs {
    std::vector<HdrImage> images;   // shrunk; the first is the one the others are held to
    std::vector<uint8_t> mask;
};

Inputs readInputs(const std::vector<std::string>& paths, const std::string& coverage, int factor, int erode) {
    Inputs inputs;
    try {
        for (const std::string& path : paths) {
            inputs.images.push_back(downsampleBox(readLinearImage(path), factor));
        }
        inputs.mask = coverage.empty() ? std::vector<uint8_t>(inputs.images[0].rgb.size() / 3, 1)
                                       : coverageMask(readLinearImage(coverage), factor, erode);
    } catch (const std::invalid_argument& error) {
        throw InputError(error.what());
    }
    return inputs;
}

std::string fixed(double value, const char* format) {
    char text[48];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// Row 1: every image as displayed; row 2: the pixels compared, then each image's heat map
// captioned with its row's mean.
LdrImage differenceSheet(const Inputs& inputs, const std::vector<std::string>& names,
                         const std::vector<RendererDifference>& rows, const DisplaySettings& display, float gain) {
    std::vector<LdrImage> cells;
    std::vector<std::string> captions;
    for (size_t i = 0; i < inputs.images.size(); ++i) {
        cells.push_back(displayImage(inputs.images[i], display));
        captions.push_back(names[i]);
    }
    const HdrImage& reference = inputs.images[0];
    HdrImage compared{reference.width, reference.height, std::vector<float>(reference.rgb.size(), 0.0f)};
    cells.push_back(maskedHeatMap(compared, compared, inputs.mask, display, gain));
    captions.push_back("compared (black), left out (grey)");
    for (size_t i = 1; i < inputs.images.size(); ++i) {
        cells.push_back(maskedHeatMap(reference, inputs.images[i], inputs.mask, display, gain));
        captions.push_back(names[i] + ": mean " + fixed(rows[i - 1].meanAbsolute, "%.1f") + " (x" + fixed(gain, "%g") +
                           ")");
    }
    return contactSheet(cells, captions, int(inputs.images.size()));
}

}  // namespace

Command addDifferenceCommand(CLI::App& app) {
    struct Options {
        std::vector<std::string> images, names;
        std::string coverage, sheet, tonemap = "none", scene = "view";
        int downsample = 1, erode = 1;
        float exposure = 0.0f, gain = 4.0f;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "difference", "Compare linear images of one view as displayed: one exposure and tone map on each, then sRGB, "
                      "then the mean |difference| of each IMAGE to the first, in levels of 255, as CSV on stdout "
                      "(scripts/compare_cycles.sh's cycles.csv)");
    command->add_option("images", options->images, "The first is the one held to (PFM, OpenEXR or Radiance .hdr); "
                                                   "then one or more IMAGEs of the same size")
        ->required()
        ->expected(2, 64);
    command->add_option("--names", options->names, "A name for each image, for the CSV and the sheet (default: the "
                                                   "file names without folder and extension)");
    command->add_option("--coverage", options->coverage,
                        "A channel image, 0 where no item is (render --channel geometry-normal --reference --hdr): "
                        "only the pixels that show the model are compared (default: every pixel)");
    command->add_option("--erode", options->erode, "--coverage: also leave out pixels this close to its edge")
        ->check(CLI::Range(0, 64));
    command->add_option("--downsample", options->downsample,
                        "Shrink every image (and the coverage) by this factor first, each pixel the mean of its block")
        ->check(CLI::Range(1, 16));
    command->add_option("--exposure", options->exposure, "Stops, applied to every image")->check(CLI::Range(-20.0, 20.0));
    command->add_option("--tonemap", options->tonemap, "The view transform after exposure: " + tonemapNames() +
                                                            " (default: none)");
    command->add_option("--scene", options->scene, "The CSV's first column (default: view)");
    command->add_option("--sheet", options->sheet, "Also a PNG: the images as displayed, and where each differs "
                                                   "from the first");
    command->add_option("--heat-gain", options->gain, "--sheet: the heat maps show the difference times this")
        ->check(CLI::Range(0.1, 100.0));
    return [options] {
        std::vector<std::string> names = options->names;
        if (names.empty()) {
            for (const std::string& path : options->images) {
                names.push_back(std::filesystem::path(path).stem().string());
            }
        } else if (names.size() != options->images.size()) {
            throw InputError("--names gives " + std::to_string(names.size()) + " names for " +
                             std::to_string(options->images.size()) + " images");
        }
        for (const std::string& name : names) {
            checkCsvCell(name, "a name");
        }
        checkCsvCell(options->scene, "--scene");
        const auto tonemap = tonemapFromName(options->tonemap);
        if (!tonemap) {
            throw InputError("--tonemap: unknown tone map \"" + options->tonemap + "\" (known: " + tonemapNames() + ")");
        }
        DisplaySettings display;
        display.exposure = options->exposure;
        display.tonemap = *tonemap;
        const Inputs inputs = readInputs(options->images, options->coverage, options->downsample, options->erode);
        std::vector<RendererDifference> rows;
        try {
            for (size_t i = 1; i < inputs.images.size(); ++i) {
                const MaskedDifference difference =
                    maskedDifference(inputs.images[0], inputs.images[i], inputs.mask, display);
                rows.push_back({options->scene, names[i], names[0], difference.meanAbsolute, difference.meanSigned,
                                difference.pixels});
            }
        } catch (const std::invalid_argument& error) {
            throw InputError(error.what());
        }
        if (rows[0].pixels == 0) {
            throw InputError("no pixel is compared: the coverage shows no model away from its edges");
        }
        if (!options->sheet.empty()) {
            writeOutput(options->sheet, encodePng(differenceSheet(inputs, names, rows, display, options->gain)));
        }
        std::fputs(rendererComparisonCsv(rows).c_str(), stdout);
    };
}

}  // namespace patina::cli
