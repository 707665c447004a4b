#pragma once
// Scatter and line charts as an engineer puts them in a paper, drawn through Cairo by one
// function onto a PNG's image, an SVG or a PDF (chart.cpp), from a layout that measures
// every text first (chart_layout.h): tick labels thinned until none overlap, each series named
// in full in a legend under the plot, which grows the canvas instead of cutting a name.
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "image/caption.h"
#include "image/image.h"

namespace patina {

enum class ChartMarker { Circle, Square, Triangle, Diamond, InvertedTriangle, Cross, Plus, Star };

struct ChartSeries {
    std::string label;
    std::vector<glm::dvec2> points;   // data coordinates
    size_t style = 0;                 // its colour and marker: chartColour(style), chartMarker(style)
    bool line = true;
    bool markers = false;
    bool dashed = false;
    std::vector<std::string> pointLabels;   // one per point, or empty
    std::vector<double> errors;             // the standard error of each point's y, or empty
};

struct ChartPanel {
    std::string title, xLabel, yLabel;
    bool logX = false, logY = false;
    std::vector<ChartSeries> series;
};

struct Chart {
    std::vector<ChartPanel> panels;   // side by side
    int panelWidth = 640, panelHeight = 480;   // without the legend; wider where a text needs it
};

LdrImage chartToImage(const Chart& chart);
std::string chartToSvg(const Chart& chart);
std::string chartToPdf(const Chart& chart);

// Ten colours apart for the colour-blind too, and eight marker shapes: a style's pair repeats
// only after 40 series.
Rgb8 chartColour(size_t style);
ChartMarker chartMarker(size_t style);

}  // namespace patina
