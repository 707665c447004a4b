// Charts (engine/image/chart.h): one drawing onto PNG, SVG and PDF, read from the layout
// where that is enough (text boxes) and from the PNG's pixels where it is not (error bars).
#include <cmath>
#include <cstdlib>
#include <regex>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "image/chart.h"
#include "image/chart_layout.h"

namespace patina {
namespace {

// A chart whose ticks crowd: a narrow log panel over 18 decades and a linear one of wide numbers.
Chart crowded() {
    Chart chart;
    chart.panelWidth = 220;
    chart.panelHeight = 200;
    ChartPanel log{"log", "a quantity over many decades", "another, also over many", true, true, {}};
    ChartSeries points{"points", {{1e-9, 1e-9}, {1e9, 1e9}}, 0, true, true, false, {}, {}};
    log.series.push_back(points);
    ChartPanel linear{"linear", "big numbers", "small ones", false, false, {}};
    ChartSeries wide{"wide", {{123456.0, 0.000123}, {1234567.0, 0.000987}}, 1, true, true, false, {}, {}};
    linear.series.push_back(wide);
    chart.panels = {log, linear};
    return chart;
}

std::vector<const ChartText*> texts(const ChartPanelLayout& panel) {
    std::vector<const ChartText*> all{&panel.title, &panel.xLabel, &panel.yLabel};
    for (const auto* labels : {&panel.xTickLabels, &panel.yTickLabels}) {
        for (const ChartText& label : *labels) {
            all.push_back(&label);
        }
    }
    for (const ChartLegendEntry& entry : panel.legend) {
        all.push_back(&entry.label);
    }
    return all;
}

bool inside(const ChartBox& box, const ChartLayout& layout) {
    return box.x >= 0 && box.y >= 0 && box.x + box.width <= layout.width && box.y + box.height <= layout.height;
}

TEST(Chart, NoTwoTextsOverlapAndTickLabelsAreThinnedToFit) {
    const ChartLayout layout = chartLayout(crowded());
    ASSERT_EQ(layout.panels.size(), 2u);
    for (const ChartPanelLayout& panel : layout.panels) {
        EXPECT_GE(panel.xTickLabels.size(), 2u);
        EXPECT_GE(panel.yTickLabels.size(), 2u);
        const std::vector<const ChartText*> all = texts(panel);
        for (size_t i = 0; i < all.size(); ++i) {
            EXPECT_TRUE(inside(all[i]->box, layout)) << all[i]->text;
            EXPECT_FALSE(all[i]->box.overlaps(panel.plot)) << all[i]->text << " on the plot";
            for (size_t j = i + 1; j < all.size(); ++j) {
                EXPECT_FALSE(all[i]->box.overlaps(all[j]->box)) << all[i]->text << " / " << all[j]->text;
            }
        }
    }
    // Thinned, not dropped: 19 decades do not fit 220 pixels, so some labels went.
    EXPECT_LT(layout.panels[0].xTickLabels.size(), layout.panels[0].xTicks.size());
    // The panels stand apart.
    EXPECT_LE(layout.panels[0].plot.x + layout.panels[0].plot.width, layout.panels[1].yLabel.box.x);
}

TEST(Chart, TheLegendNamesEverySeriesInFullAndGrowsTheCanvas) {
    Chart chart;
    chart.panelWidth = 300;
    ChartPanel panel{"t", "x", "y", false, false, {}};
    const std::string longest = "split sum, dominant direction, with the horizon fade and the specular occlusion of "
                                "the glTF's own map, at every roughness";
    for (size_t s = 0; s < 6; ++s) {
        const std::string label = s == 2 ? longest : "series " + std::to_string(s);
        panel.series.push_back({label, {{0.0, double(s)}, {1.0, double(s) + 1}}, s, true, true, false, {}, {}});
    }
    chart.panels = {panel};
    const ChartLayout layout = chartLayout(chart);
    const ChartPanelLayout& drawn = layout.panels[0];
    ASSERT_EQ(drawn.legend.size(), 6u);
    for (size_t s = 0; s < 6; ++s) {
        EXPECT_EQ(drawn.legend[s].series, s);
        EXPECT_EQ(drawn.legend[s].label.text, panel.series[s].label);
        EXPECT_TRUE(inside(drawn.legend[s].label.box, layout)) << s;
        EXPECT_FALSE(drawn.legend[s].sample.overlaps(drawn.legend[s].label.box));
    }
    EXPECT_GT(layout.width, chart.panelWidth) << "widened for the longest name";
    EXPECT_GT(layout.height, chart.panelHeight) << "the legend is under the plot";
    const LdrImage image = chartToImage(chart);
    EXPECT_EQ(image.width, layout.width);
    EXPECT_EQ(image.height, layout.height);
}

TEST(Chart, EightSeriesGetDistinctColoursAndMarkers) {
    std::set<std::tuple<int, int, int>> colours;
    std::set<ChartMarker> markers;
    for (size_t style = 0; style < 8; ++style) {
        const Rgb8 c = chartColour(style);
        colours.insert({c.r, c.g, c.b});
        markers.insert(chartMarker(style));
    }
    EXPECT_EQ(colours.size(), 8u);
    EXPECT_EQ(markers.size(), 8u);
    for (size_t style = 8; style < 10; ++style) {
        const Rgb8 c = chartColour(style);
        colours.insert({c.r, c.g, c.b});
    }
    EXPECT_EQ(colours.size(), 10u);
    // Each colour a chart's marker shows is the series', on the image too.
    Chart chart;
    ChartPanel panel{"", "", "", false, false, {}};
    for (size_t s = 0; s < 8; ++s) {
        panel.series.push_back({std::to_string(s), {{double(s), double(s)}}, s, false, true, false, {}, {}});
    }
    chart.panels = {panel};
    const LdrImage image = chartToImage(chart);
    for (size_t s = 0; s < 8; ++s) {
        const Rgb8 c = chartColour(s);
        int found = 0;
        for (size_t i = 0; i < image.rgba.size(); i += 4) {
            found += std::abs(image.rgba[i] - c.r) + std::abs(image.rgba[i + 1] - c.g) +
                         std::abs(image.rgba[i + 2] - c.b) < 30;
        }
        EXPECT_GT(found, 10) << s;
    }
}

// Pixels near the series' colour in the column around x, from y0 to y1.
int colouredRows(const LdrImage& image, Rgb8 colour, int x, int y0, int y1) {
    int rows = 0;
    for (int y = std::max(y0, 0); y <= std::min(y1, image.height - 1); ++y) {
        bool any = false;
        for (int dx = -1; dx <= 1; ++dx) {
            const uint8_t* p = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x + dx)) * 4];
            any = any || (std::abs(p[0] - colour.r) + std::abs(p[1] - colour.g) + std::abs(p[2] - colour.b) < 60);
        }
        rows += any;
    }
    return rows;
}

TEST(Chart, ErrorBarsSpanTheStandardErrorEachWay) {
    for (const bool log : {false, true}) {
        Chart chart;
        ChartPanel panel{"", "", "", false, log, {}};
        panel.series.push_back({"one point", {{0.5, 1.0}}, 0, false, true, false, {}, {0.5}});
        panel.series.push_back({"a second", {{0.2, 1.0}, {0.8, 1.0}}, 1, false, true, false, {}, {}});
        chart.panels = {panel};
        const ChartPanelLayout layout = chartLayout(chart).panels[0];
        const LdrImage image = chartToImage(chart);
        const Rgb8 colour = chartColour(0);
        const glm::dvec2 point = layout.toPixel({0.5, 1.0});
        const int top = int(std::lround(layout.toPixel({0.5, 1.5}).y));
        const int bottom = int(std::lround(layout.toPixel({0.5, 0.5}).y));
        const int x = int(std::lround(point.x));
        // The whole bar, from 2 pixels inside each end, and nothing past the caps.
        EXPECT_EQ(colouredRows(image, colour, x, top + 2, bottom - 2), bottom - top - 3) << log;
        EXPECT_EQ(colouredRows(image, colour, x, top - 12, top - 3), 0) << log;
        EXPECT_EQ(colouredRows(image, colour, x, bottom + 3, bottom + 12), 0) << log;
        // The caps: the colour beside the bar's ends, not beside the point's middle.
        EXPECT_GT(colouredRows(image, colour, x + 3, top - 1, top + 1), 0) << log;
        EXPECT_EQ(colouredRows(image, colour, x + 3, (top + int(point.y)) / 2 - 2, (top + int(point.y)) / 2 + 2), 0);
        // The second series has no errors: no bar above its points.
        const glm::dvec2 other = layout.toPixel({0.2, 1.0});
        EXPECT_EQ(colouredRows(image, chartColour(1), int(std::lround(other.x)), top, int(other.y) - 8), 0) << log;
    }
    // On a log axis a bar below zero runs to the bottom of the plot.
    Chart chart;
    ChartPanel panel{"", "", "", false, true, {}};
    panel.series.push_back({"", {{0.5, 1.0}, {0.6, 0.01}}, 0, false, false, false, {}, {2.0, 0.0}});
    chart.panels = {panel};
    const ChartPanelLayout layout = chartLayout(chart).panels[0];
    const LdrImage image = chartToImage(chart);
    const glm::dvec2 point = layout.toPixel({0.5, 1.0});
    const int plotBottom = int(layout.plot.y + layout.plot.height);
    EXPECT_GE(colouredRows(image, chartColour(0), int(std::lround(point.x)), int(point.y), plotBottom - 2),
              plotBottom - 2 - int(point.y));
}

// Well-formed enough for a reader: every tag closed in order, one root <svg>.
bool wellFormedSvg(const std::string& svg) {
    static const std::regex tag(R"(<(/?)([A-Za-z][\w:-]*)[^>]*?(/?)>)");
    std::vector<std::string> open;
    int roots = 0;
    const std::string body = svg.substr(svg.find("<svg"));
    for (auto it = std::sregex_iterator(body.begin(), body.end(), tag); it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        if (m[1] == "/") {
            if (open.empty() || open.back() != m[2]) {
                return false;
            }
            open.pop_back();
        } else if (m[3] != "/") {
            roots += open.empty();
            open.push_back(m[2]);
        }
    }
    return open.empty() && roots == 1;
}

TEST(Chart, SvgAndPdfAreTheSameDrawing) {
    const Chart chart = crowded();
    const ChartLayout layout = chartLayout(chart);
    const std::string svg = chartToSvg(chart), pdf = chartToPdf(chart);
    ASSERT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_TRUE(wellFormedSvg(svg));
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("width=\"" + std::to_string(layout.width) + "px\""), std::string::npos);
    EXPECT_NE(svg.find("height=\"" + std::to_string(layout.height) + "px\""), std::string::npos);
    ASSERT_EQ(pdf.rfind("%PDF-", 0), 0u);
    EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
    EXPECT_NE(pdf.find("/MediaBox [ 0 0 " + std::to_string(layout.width) + " " + std::to_string(layout.height) + " ]"),
              std::string::npos);
    EXPECT_NE(pdf.find("DejaVuSans"), std::string::npos) << "the font embedded";
    EXPECT_FALSE(wellFormedSvg("<svg><g></svg></g>"));
}

// A marker-only series' legend marker stays in its sample (a polygon's path once began at the
// end of the text drawn before it, and filled a wedge from there).
TEST(Chart, ALegendMarkerStaysInItsSample) {
    Chart chart;
    ChartPanel panel{"", "", "", false, false, {}};
    panel.series.push_back({"a first series with a long name", {{0.0, 0.0}}, 0, false, true, false, {}, {}});
    panel.series.push_back({"triangles", {{1.0, 1.0}}, 2, false, true, false, {}, {}});
    chart.panels = {panel};
    ASSERT_EQ(chartMarker(2), ChartMarker::Triangle);
    const ChartPanelLayout layout = chartLayout(chart).panels[0];
    ASSERT_EQ(layout.legend.size(), 2u);
    const ChartBox& sample = layout.legend[1].sample;
    const LdrImage image = chartToImage(chart);
    const Rgb8 c = chartColour(2);
    int outside = 0;
    for (int y = int(layout.plot.y + layout.plot.height) + 2; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const uint8_t* p = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
            const bool coloured = std::abs(p[0] - c.r) + std::abs(p[1] - c.g) + std::abs(p[2] - c.b) < 60;
            const bool inSample = x >= sample.x - 2 && x <= sample.x + sample.width + 2 && y >= sample.y - 2 &&
                                  y <= sample.y + sample.height + 2;
            outside += coloured && !inSample;
        }
    }
    EXPECT_EQ(outside, 0);
}

// Rows of the plot (inside its frame) that hold dark grey, the point labels' colour, and how
// many such pixels there are.
std::pair<int, int> labelInk(const LdrImage& image, const ChartBox& plot) {
    int rows = 0, pixels = 0;
    for (int y = int(plot.y) + 3; y < int(plot.y + plot.height) - 3; ++y) {
        int inRow = 0;
        for (int x = int(plot.x) + 3; x < int(plot.x + plot.width) - 3; ++x) {
            const uint8_t* p = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
            inRow += p[0] == p[1] && p[1] == p[2] && p[0] < 150;
        }
        rows += inRow > 0;
        pixels += inRow;
    }
    return {rows, pixels};
}

// Labels of points at the plot's right edge show whole (they were cut off by the plot's edge),
// and two of one spot are drawn one above the other, not over each other.
TEST(Chart, PointLabelsStayInThePlotAndApart) {
    auto chartOf = [](double x, std::vector<std::string> labels) {
        Chart chart;
        ChartPanel panel{"", "", "", false, false, {}};
        panel.series.push_back({"range", {{0.0, 0.0}, {1.0, 1.0}}, 1, false, false, false, {}, {}});
        ChartSeries spot{"spot", std::vector<glm::dvec2>(labels.size(), glm::dvec2(x, 0.5)), 0, false, true, false,
                         labels, {}};
        panel.series.push_back(spot);
        chart.panels = {panel};
        return chart;
    };
    auto ink = [](const Chart& chart) { return labelInk(chartToImage(chart), chartLayout(chart).panels[0].plot); };
    const std::string label = "a label longer than any margin right of its point";
    const auto [middleRows, middlePixels] = ink(chartOf(0.5, {label}));
    const auto [edgeRows, edgePixels] = ink(chartOf(1.0, {label}));
    EXPECT_GT(middlePixels, 50);
    EXPECT_NEAR(edgePixels, middlePixels, 0.1 * middlePixels);
    EXPECT_GE(ink(chartOf(1.0, {label, label})).first, 2 * edgeRows - 1);
}

}  // namespace
}  // namespace patina
