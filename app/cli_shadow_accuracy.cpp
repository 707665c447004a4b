// `patina shadow-accuracy`: the shadow-mapped render against the ground truth with visibility,
// by light size, map resolution and bias (engine/accuracy/shadow_accuracy.h); docs/LIGHTING.md
// section 6 shows its outputs.
#include <iostream>

#include "accuracy/shadow_accuracy.h"
#include "cli.h"
#include "gl/headless_context.h"
#include "inputs.h"

namespace patina::cli {

Command addShadowAccuracyCommand(CLI::App& app) {
    return addMeasurementCommand(
        app, "shadow-accuracy",
        "Shadow maps against the ground truth with visibility, by light size, map resolution and bias: "
        "shadow_accuracy.csv and shadow_accuracy.svg/.pdf/.png",
        [](const std::filesystem::path& folder, bool quick) {
            HeadlessContext context;
            const ShadowAccuracyResult result = measureShadowAccuracy(shadowAccuracyOptions(quick));
            writeOutputText((folder / "shadow_accuracy.csv").string(), shadowAccuracyCsv(result));
            writeChart(folder / "shadow_accuracy", shadowAccuracyChart(result), true);
            std::cout << result.rows.size() << " rows, " << result.width << "x" << result.height << ", "
                      << result.referenceSamples << " ground-truth iterations a pixel for a sphere light; a floor pixel "
                      << result.pixelFootprint << " world units wide at the shadow\n";
        });
}

}  // namespace patina::cli
