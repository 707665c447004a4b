#include <memory>

#include "cli.h"
#include "image/image.h"
#include "inputs.h"
#include "shading/brdf_slice.h"

namespace patina::cli {

namespace {
// The slice's values (1/sr, -1 below the horizon) as a PFM, row 0 at the top as the PNG's.
HdrImage sliceValues(const BrdfSlice& slice) {
    HdrImage image{slice.size, slice.size, {}};
    image.rgb.reserve(slice.values.size() * 3);
    for (const glm::vec3& f : slice.values) {
        image.rgb.insert(image.rgb.end(), {f.r, f.g, f.b});
    }
    return image;
}

LdrImage sliceImage(const BrdfSlice& slice, float exposure, bool logScale) {
    LdrImage image{slice.size, slice.size, std::vector<uint8_t>(slice.values.size() * 4, 255)};
    for (size_t i = 0; i < slice.values.size(); ++i) {
        const glm::vec3 shown = sliceShown(slice.values[i], exposure, logScale);
        for (int c = 0; c < 3; ++c) {
            image.rgba[i * 4 + size_t(c)] = uint8_t(shown[c] * 255.0f + 0.5f);
        }
    }
    return image;
}
}  // namespace

Command addSliceCommand(CLI::App& app) {
    struct Options {
        SceneInputs inputs;
        float phiD = 90.0f, exposure = 0.0f;
        int size = 256;
        std::string lobe = "total", out, hdr;
        bool linear = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "slice", "Write BRDF Explorer's image slice (Burley 2012): f over theta_h (across) and theta_d (up), 0 to 90 "
                 "degrees, at one phi_d, as a PNG (log scale unless --linear) and optionally the values as PFM");
    options->inputs.addOptions(*command, false);
    command->add_option("--phi-d", options->phiD, "phi_d, degrees (90: both directions above the horizon everywhere)")
        ->check(CLI::Range(0.0f, 360.0f));
    command->add_option("--size", options->size, "Pixels a side")->check(CLI::Range(2, 4096));
    command->add_option("--lobe", options->lobe,
                        "total, diffuse or specular (reflected), or transmitted: a thin wall's BTDF "
                        "(KHR_materials_transmission) towards V mirrored below the surface, theta_h that of its "
                        "half vector")
        ->check(CLI::IsMember({"total", "diffuse", "specular", "transmitted"}));
    command->add_option("--exposure", options->exposure, "Stops the values are scaled by before they are shown")
        ->check(CLI::Range(-30.0f, 30.0f));
    command->add_flag("--linear", options->linear, "A linear scale (clamped at 1) instead of four decades of log");
    command->add_option("--out", options->out, "Output PNG")->required();
    command->add_option("--hdr", options->hdr, "Also the values (1/sr; -1 where L or V is below the horizon) as PFM");
    return [options] {
        const Scene scene = options->inputs.load();
        const SliceLobe lobe = options->lobe == "diffuse"       ? SliceLobe::Diffuse
                               : options->lobe == "specular"    ? SliceLobe::Specular
                               : options->lobe == "transmitted" ? SliceLobe::Transmitted
                                                                : SliceLobe::Total;
        const BrdfSlice slice = brdfSlice(scene.material, options->phiD, options->size, lobe);
        const std::vector<uint8_t> png = encodePng(sliceImage(slice, options->exposure, !options->linear));
        if (!options->hdr.empty()) {
            writeOutput(options->hdr, encodePfm(sliceValues(slice)));
        }
        writeOutput(options->out, png);
    };
}

}  // namespace patina::cli
