#include "bench/renderer_comparison.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <utility>

#include "files/input_error.h"

namespace patina {

namespace {
const char* const kHeader = "scene,image,against,mean_abs_srgb,mean_signed_srgb,pixels";
}

std::string rendererComparisonCsv(const std::vector<RendererDifference>& rows) {
    std::string csv = std::string(kHeader) + "\n";
    for (const RendererDifference& row : rows) {
        char numbers[96];
        std::snprintf(numbers, sizeof numbers, ",%.3f,%.3f,%zu\n", row.meanAbsolute, row.meanSigned, row.pixels);
        csv += row.scene + "," + row.image + "," + row.against + numbers;
    }
    return csv;
}

std::vector<RendererDifference> parseRendererComparison(const CsvFile& file) {
    std::vector<RendererDifference> rows;
    for (const CsvLine& line : csvBody(file, kHeader)) {
        expectCells(line, 6, file.source);
        for (size_t column = 0; column < 3; ++column) {
            if (line.cells[column].empty()) {
                throw InputError(file.source + ":" + std::to_string(line.number) + ": column " +
                                 std::to_string(column + 1) + " is empty");
            }
        }
        const double pixels = csvNumber(line, 5, file.source);
        if (pixels < 0.0 || pixels != double(size_t(pixels))) {
            throw InputError(file.source + ":" + std::to_string(line.number) + ": column 6 ('" + line.cells[5] +
                             "') is not a pixel count");
        }
        rows.push_back({line.cells[0], line.cells[1], line.cells[2], csvNumber(line, 3, file.source),
                        csvNumber(line, 4, file.source), size_t(pixels)});
    }
    return rows;
}

namespace {

// Each name once, in the order of first appearance.
void addOnce(std::vector<std::string>& names, const std::string& name) {
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        names.push_back(name);
    }
}

ChartPanel comparisonPanel(const std::vector<RendererDifference>& rows, const std::string& truth,
                           const std::string& other, const std::vector<std::string>& images,
                           const std::vector<std::string>& scenes) {
    std::map<std::pair<std::string, std::string>, double> toTruth, toOther;   // (scene, image)
    for (const RendererDifference& row : rows) {
        if (row.against == truth) {
            toTruth[{row.scene, row.image}] = row.meanAbsolute;
        } else if (row.against == other) {
            toOther[{row.scene, row.image}] = row.meanAbsolute;
        }
    }
    ChartPanel panel;
    panel.title = "held to " + other;
    panel.xLabel = "mean |sRGB difference| to " + truth + " (levels of 255)";
    panel.yLabel = "mean |sRGB difference| to " + other;
    double largest = 0.0;
    for (size_t i = 0; i < images.size(); ++i) {
        ChartSeries series;
        series.label = images[i];
        series.style = i;
        series.line = false;
        series.markers = true;
        for (const std::string& scene : scenes) {
            const auto x = toTruth.find({scene, images[i]});
            const auto y = toOther.find({scene, images[i]});
            if (x != toTruth.end() && y != toOther.end()) {
                series.points.emplace_back(x->second, y->second);
                series.pointLabels.push_back(scene);
                largest = std::max({largest, x->second, y->second});
            }
        }
        if (!series.points.empty()) {
            panel.series.push_back(std::move(series));
        }
    }
    if (!panel.series.empty()) {
        ChartSeries diagonal;
        diagonal.label = "as far from both";
        diagonal.points = {{0.0, 0.0}, {largest, largest}};
        diagonal.style = images.size();
        diagonal.dashed = true;
        panel.series.push_back(std::move(diagonal));
    }
    return panel;
}

}  // namespace

Chart rendererComparisonChart(const std::vector<RendererDifference>& rows, const std::string& truth) {
    std::vector<std::string> scenes, others, images;
    for (const RendererDifference& row : rows) {
        addOnce(scenes, row.scene);
        if (row.against != truth) {
            addOnce(others, row.against);
        }
    }
    // The images held to the truth and to another, in the order the rows name them.
    for (const RendererDifference& row : rows) {
        if (row.against != truth) {
            continue;
        }
        const bool alsoToAnother = std::any_of(rows.begin(), rows.end(), [&](const RendererDifference& other) {
            return other.image == row.image && other.against != truth;
        });
        if (alsoToAnother) {
            addOnce(images, row.image);
        }
    }
    Chart chart;
    for (const std::string& other : others) {
        ChartPanel panel = comparisonPanel(rows, truth, other, images, scenes);
        if (!panel.series.empty()) {
            chart.panels.push_back(std::move(panel));
        }
    }
    if (chart.panels.empty()) {
        throw InputError("no image is held both to " + truth + " and to another: nothing to chart");
    }
    return chart;
}

}  // namespace patina
