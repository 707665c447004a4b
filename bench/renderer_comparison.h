#pragma once
// scripts/compare_cycles.sh's numbers: Patina's models, its ground truth and Blender's Cycles on
// the same views, each pair's mean |sRGB difference| as `patina difference` measures it, in
// cycles.csv; and the chart `patina chart cycles` draws from them (docs/LIGHTING.md, "Side by
// side with Cycles").
#include <cstddef>
#include <string>
#include <vector>

#include "image/chart.h"
#include "bench/csv_read.h"

namespace patina {

// One line of cycles.csv: `image` held to `against` on `scene`'s view.
struct RendererDifference {
    std::string scene, image, against;
    double meanAbsolute = 0.0;   // levels of 255
    double meanSigned = 0.0;     // positive: `image` is brighter
    size_t pixels = 0;           // compared
};

// The CSV `patina difference` prints and compare_cycles.sh gathers into cycles.csv: the header
// scene,image,against,mean_abs_srgb,mean_signed_srgb,pixels, then a line a row, the differences
// to 3 decimals.
std::string rendererComparisonCsv(const std::vector<RendererDifference>& rows);
// Its lines back; throws InputError naming the file and the line.
std::vector<RendererDifference> parseRendererComparison(const CsvFile& file);

// A panel for each image other than `truth` that images are held to (Cycles as rendered, and
// Cycles with the model hidden from its secondary rays), in the order the rows first name them:
// each image held both to `truth` and to that one is a series, with a point per scene at
// (its difference to the truth, its difference to the panel's), labelled with the scene; and
// the diagonal, where an image is as far from both. Throws InputError when no image is held to
// both.
Chart rendererComparisonChart(const std::vector<RendererDifference>& rows, const std::string& truth);

}  // namespace patina
