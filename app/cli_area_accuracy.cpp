// `patina area-accuracy`: sphere and tube lights by each published shortcut against the exact
// integral (engine/accuracy/area_light_accuracy.h); docs/LIGHTING.md ("Area lights") shows its outputs.
#include <iostream>

#include "accuracy/area_light_accuracy.h"
#include "cli.h"
#include "image/image.h"
#include "inputs.h"

namespace patina::cli {

void writeAreaAccuracy(const std::filesystem::path& folder, bool quick) {
    const AreaAccuracyResult result = runAreaAccuracy(quick);
    writeOutputText((folder / "area_accuracy.csv").string(), areaAccuracyCsv(result));
    writeOutputText((folder / "area_cost.csv").string(), areaCostCsv(result));
    writeChart(folder / "area_accuracy", areaAccuracyChart(result), true);
    writeOutput((folder / "area_spheres.png").string(), encodePng(areaLightSpheres(quick)));
    std::cout << result.rows.size() << " area-light rows, " << result.referenceSamples
              << " Monte Carlo iterations a probe of the ground truth\n";
}

Command addAreaAccuracyCommand(CLI::App& app) {
    return addMeasurementCommand(
        app, "area-accuracy",
        "Sphere and tube lights against the ground truth: area_accuracy.csv, area_cost.csv, area_accuracy.svg/.png "
        "and area_spheres.png (lighting-accuracy writes them too)",
        writeAreaAccuracy);
}

}  // namespace patina::cli
