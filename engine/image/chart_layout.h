#pragma once
// Where everything of a chart goes, in pixels (y down), measured before anything is drawn:
// the drawing (chart.cpp) only follows it, and tests read it without reading pixels.
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "image/chart.h"

namespace patina {

struct ChartBox {
    double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
    bool overlaps(const ChartBox& other) const;
};

// A text and the box it covers; a vertical one reads bottom to top.
struct ChartText {
    std::string text;
    ChartBox box;
    double pixels = 0.0;   // font size, per em
    bool vertical = false;
};

struct ChartLegendEntry {
    size_t series = 0;
    ChartBox sample;   // where its line and marker are shown
    ChartText label;
};

struct ChartPanelLayout {
    ChartBox plot;
    double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;   // the axes' ranges, log10 of a log axis
    bool logX = false, logY = false;
    std::vector<double> xTicks, yTicks;                 // grid lines, in axis units
    std::vector<ChartText> xTickLabels, yTickLabels;   // the ticks that keep a label
    ChartText title, xLabel, yLabel;
    std::vector<ChartLegendEntry> legend;

    // Pixel of a data point; a log axis's non-positive values fall far below or left.
    glm::dvec2 toPixel(glm::dvec2 point) const;
};

struct ChartLayout {
    int width = 0, height = 0;
    std::vector<ChartPanelLayout> panels;
};

ChartLayout chartLayout(const Chart& chart);

}  // namespace patina
