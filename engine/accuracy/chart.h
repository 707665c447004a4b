#pragma once
// Small scatter/line charts drawn two ways from one description: SVG text and a raster image
// (for PNG), so bench, stability and furnace charts need no plotting package.
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "image/caption.h"
#include "image/image.h"

namespace patina {

struct ChartSeries {
    std::string label;
    std::vector<glm::dvec2> points;   // data coordinates
    Rgb8 colour;
    bool line = true;
    bool markers = false;
    bool dashed = false;
    std::vector<std::string> pointLabels;   // one per point, or empty
};

struct ChartPanel {
    std::string title, xLabel, yLabel;
    bool logX = false, logY = false;
    std::vector<ChartSeries> series;
};

struct Chart {
    std::vector<ChartPanel> panels;   // side by side
    int panelWidth = 640, panelHeight = 480;
};

std::string chartToSvg(const Chart& chart);
LdrImage chartToImage(const Chart& chart);

// A colour per index that stays apart from its neighbours.
Rgb8 chartColour(size_t index);

}  // namespace patina
