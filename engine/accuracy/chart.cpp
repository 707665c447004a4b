#include "accuracy/chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace patina {

namespace {
constexpr int kMarginLeft = 70, kMarginRight = 150, kMarginTop = 48, kMarginBottom = 45;

// Data range of a panel, padded; in log10 space for log axes.
struct Axes {
    double x0, x1, y0, y1;
    bool logX, logY;
    int left, top, width, height;   // plot area in pixels

    double fx(double x) const { return logX ? std::log10(std::max(x, 1e-300)) : x; }
    double fy(double y) const { return logY ? std::log10(std::max(y, 1e-300)) : y; }
    glm::dvec2 toPixel(glm::dvec2 p) const {
        return {left + (fx(p.x) - x0) / (x1 - x0) * width, top + height - (fy(p.y) - y0) / (y1 - y0) * height};
    }
};

Axes axesFor(const ChartPanel& panel, int originX, int panelWidth, int panelHeight) {
    Axes axes{std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
              std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
              panel.logX, panel.logY, originX + kMarginLeft, kMarginTop,
              panelWidth - kMarginLeft - kMarginRight, panelHeight - kMarginTop - kMarginBottom};
    for (const ChartSeries& series : panel.series) {
        for (const glm::dvec2& p : series.points) {
            if ((panel.logX && p.x <= 0) || (panel.logY && p.y <= 0) || !std::isfinite(p.x) || !std::isfinite(p.y)) {
                continue;
            }
            axes.x0 = std::min(axes.x0, axes.fx(p.x));
            axes.x1 = std::max(axes.x1, axes.fx(p.x));
            axes.y0 = std::min(axes.y0, axes.fy(p.y));
            axes.y1 = std::max(axes.y1, axes.fy(p.y));
        }
    }
    if (axes.x0 > axes.x1) {
        axes.x0 = 0, axes.x1 = 1, axes.y0 = 0, axes.y1 = 1;
    }
    auto pad = [](double& lo, double& hi, bool log) {
        const double span = hi - lo;
        const double margin = span > 0 ? span * 0.08 : (log ? 0.5 : std::max(std::abs(lo) * 0.1, 0.5));
        lo -= margin;
        hi += margin;
    };
    pad(axes.x0, axes.x1, axes.logX);
    pad(axes.y0, axes.y1, axes.logY);
    return axes;
}

std::string tickText(double value, bool log) {
    char text[32];
    if (log) {
        const double v = std::pow(10.0, value);
        std::snprintf(text, sizeof text, v >= 0.01 && v < 10000 ? "%.3g" : "%.0e", v);
    } else {
        std::snprintf(text, sizeof text, "%.3g", value);
    }
    return text;
}

// Tick positions in axis space: decades for log axes (with 2 and 5 between them when the axis
// spans less than two decades), 5 steps otherwise.
std::vector<double> ticks(double lo, double hi, bool log) {
    std::vector<double> result;
    if (log) {
        const bool fine = hi - lo < 2.0;
        for (double d = std::floor(lo); d <= hi; d += 1.0) {
            for (double m : {1.0, 2.0, 5.0}) {
                const double t = d + std::log10(m);
                if (t >= lo && t <= hi && (fine || m == 1.0)) {
                    result.push_back(t);
                }
            }
        }
    } else {
        for (int i = 0; i <= 5; ++i) {
            result.push_back(lo + (hi - lo) * i / 5.0);
        }
    }
    return result;
}

std::string svgColour(Rgb8 c) {
    char text[16];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
    return text;
}

std::string escapeXml(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '&': out += "&amp;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

// --- raster drawing -----------------------------------------------------------------------
void plot(LdrImage& image, int x, int y, Rgb8 c) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) {
        return;
    }
    uint8_t* p = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
    p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 255;
}

void line(LdrImage& image, glm::dvec2 a, glm::dvec2 b, Rgb8 c, int thickness, bool dashed) {
    const double length = std::max(std::abs(b.x - a.x), std::abs(b.y - a.y));
    const int steps = std::max(1, int(std::ceil(length)));
    for (int i = 0; i <= steps; ++i) {
        if (dashed && (i / 6) % 2 == 1) {
            continue;
        }
        const glm::dvec2 p = a + (b - a) * (double(i) / steps);
        for (int dy = 0; dy < thickness; ++dy) {
            for (int dx = 0; dx < thickness; ++dx) {
                plot(image, int(std::lround(p.x)) + dx - thickness / 2, int(std::lround(p.y)) + dy - thickness / 2, c);
            }
        }
    }
}

void disc(LdrImage& image, glm::dvec2 centre, double radius, Rgb8 c) {
    for (int y = int(centre.y - radius); y <= int(centre.y + radius) + 1; ++y) {
        for (int x = int(centre.x - radius); x <= int(centre.x + radius) + 1; ++x) {
            if ((x - centre.x) * (x - centre.x) + (y - centre.y) * (y - centre.y) <= radius * radius) {
                plot(image, x, y, c);
            }
        }
    }
}

bool clipped(const Axes& axes, glm::dvec2 p) {
    return p.x < axes.left - 1 || p.x > axes.left + axes.width + 1 || p.y < axes.top - 1 ||
           p.y > axes.top + axes.height + 1;
}

constexpr Rgb8 kInk{30, 30, 30}, kGrid{225, 225, 225};
}  // namespace

Rgb8 chartColour(size_t index) {
    static const Rgb8 palette[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},
                                   {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127},
                                   {188, 189, 34},  {23, 190, 207}, {0, 0, 0},     {174, 199, 232}};
    return palette[index % (sizeof palette / sizeof palette[0])];
}

std::string chartToSvg(const Chart& chart) {
    const int width = chart.panelWidth * int(chart.panels.size()), height = chart.panelHeight;
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
                      "\" height=\"" + std::to_string(height) + "\" font-family=\"sans-serif\" font-size=\"11\">\n";
    svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    char buffer[512];
    for (size_t p = 0; p < chart.panels.size(); ++p) {
        const ChartPanel& panel = chart.panels[p];
        const Axes axes = axesFor(panel, int(p) * chart.panelWidth, chart.panelWidth, chart.panelHeight);
        for (double t : ticks(axes.x0, axes.x1, axes.logX)) {
            const double x = axes.left + (t - axes.x0) / (axes.x1 - axes.x0) * axes.width;
            std::snprintf(buffer, sizeof buffer,
                          "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#e1e1e1\"/>"
                          "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%s</text>\n",
                          x, axes.top, x, axes.top + axes.height, x, axes.top + axes.height + 14,
                          tickText(t, axes.logX).c_str());
            svg += buffer;
        }
        for (double t : ticks(axes.y0, axes.y1, axes.logY)) {
            const double y = axes.top + axes.height - (t - axes.y0) / (axes.y1 - axes.y0) * axes.height;
            std::snprintf(buffer, sizeof buffer,
                          "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#e1e1e1\"/>"
                          "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%s</text>\n",
                          axes.left, y, axes.left + axes.width, y, axes.left - 4, y + 4, tickText(t, axes.logY).c_str());
            svg += buffer;
        }
        std::snprintf(buffer, sizeof buffer,
                      "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"#1e1e1e\"/>\n"
                      "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\" font-size=\"13\">%s</text>\n"
                      "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">%s</text>\n"
                      "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\" transform=\"rotate(-90 %d %d)\">%s</text>\n",
                      axes.left, axes.top, axes.width, axes.height, axes.left + axes.width / 2, axes.top - 26,
                      escapeXml(panel.title).c_str(), axes.left + axes.width / 2, axes.top + axes.height + 34,
                      escapeXml(panel.xLabel).c_str(), axes.left - 50, axes.top + axes.height / 2, axes.left - 50,
                      axes.top + axes.height / 2, escapeXml(panel.yLabel).c_str());
        svg += buffer;
        for (size_t s = 0; s < panel.series.size(); ++s) {
            const ChartSeries& series = panel.series[s];
            const std::string colour = svgColour(series.colour);
            if (series.line && series.points.size() > 1) {
                svg += "<polyline fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\"" +
                       (series.dashed ? " stroke-dasharray=\"6 4\"" : "") + " points=\"";
                for (const glm::dvec2& point : series.points) {
                    const glm::dvec2 q = axes.toPixel(point);
                    std::snprintf(buffer, sizeof buffer, "%.1f,%.1f ", q.x, q.y);
                    svg += buffer;
                }
                svg += "\"/>\n";
            }
            for (size_t i = 0; i < series.points.size(); ++i) {
                const glm::dvec2 q = axes.toPixel(series.points[i]);
                if (series.markers) {
                    std::snprintf(buffer, sizeof buffer, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\"/>\n", q.x,
                                  q.y, colour.c_str());
                    svg += buffer;
                }
                if (i < series.pointLabels.size()) {
                    std::snprintf(buffer, sizeof buffer, "<text x=\"%.1f\" y=\"%.1f\">%s</text>\n", q.x + 6, q.y - 5,
                                  escapeXml(series.pointLabels[i]).c_str());
                    svg += buffer;
                }
            }
            std::snprintf(buffer, sizeof buffer,
                          "<rect x=\"%d\" y=\"%d\" width=\"12\" height=\"3\" fill=\"%s\"/>"
                          "<text x=\"%d\" y=\"%d\">%s</text>\n",
                          axes.left + axes.width + 10, axes.top + 10 + int(s) * 16, colour.c_str(),
                          axes.left + axes.width + 26, axes.top + 14 + int(s) * 16, escapeXml(series.label).c_str());
            svg += buffer;
        }
    }
    return svg + "</svg>\n";
}

LdrImage chartToImage(const Chart& chart) {
    LdrImage image{chart.panelWidth * int(chart.panels.size()), chart.panelHeight, {}};
    image.rgba.assign(size_t(image.width) * size_t(image.height) * 4, 255);
    for (size_t p = 0; p < chart.panels.size(); ++p) {
        const ChartPanel& panel = chart.panels[p];
        const Axes axes = axesFor(panel, int(p) * chart.panelWidth, chart.panelWidth, chart.panelHeight);
        for (double t : ticks(axes.x0, axes.x1, axes.logX)) {
            const double x = axes.left + (t - axes.x0) / (axes.x1 - axes.x0) * axes.width;
            line(image, {x, double(axes.top)}, {x, double(axes.top + axes.height)}, kGrid, 1, false);
            const std::string text = tickText(t, axes.logX);
            drawText(image, int(x) - textWidth(text, 1) / 2, axes.top + axes.height + 6, text, 1, kInk);
        }
        for (double t : ticks(axes.y0, axes.y1, axes.logY)) {
            const double y = axes.top + axes.height - (t - axes.y0) / (axes.y1 - axes.y0) * axes.height;
            line(image, {double(axes.left), y}, {double(axes.left + axes.width), y}, kGrid, 1, false);
            const std::string text = tickText(t, axes.logY);
            drawText(image, axes.left - 6 - textWidth(text, 1), int(y) - 4, text, 1, kInk);
        }
        const glm::dvec2 corners[4] = {{double(axes.left), double(axes.top)},
                                       {double(axes.left + axes.width), double(axes.top)},
                                       {double(axes.left + axes.width), double(axes.top + axes.height)},
                                       {double(axes.left), double(axes.top + axes.height)}};
        for (int i = 0; i < 4; ++i) {
            line(image, corners[i], corners[(i + 1) % 4], kInk, 1, false);
        }
        drawText(image, axes.left + axes.width / 2 - textWidth(panel.title, 2) / 2, 6, panel.title, 2, kInk);
        drawText(image, axes.left + axes.width / 2 - textWidth(panel.xLabel, 1) / 2, axes.top + axes.height + 24,
                 panel.xLabel, 1, kInk);
        drawText(image, int(p) * chart.panelWidth + 4, axes.top - 14, panel.yLabel, 1, kInk);
        for (size_t s = 0; s < panel.series.size(); ++s) {
            const ChartSeries& series = panel.series[s];
            for (size_t i = 0; series.line && i + 1 < series.points.size(); ++i) {
                const glm::dvec2 a = axes.toPixel(series.points[i]), b = axes.toPixel(series.points[i + 1]);
                if (!clipped(axes, a) && !clipped(axes, b)) {
                    line(image, a, b, series.colour, 2, series.dashed);
                }
            }
            for (size_t i = 0; i < series.points.size(); ++i) {
                const glm::dvec2 q = axes.toPixel(series.points[i]);
                if (clipped(axes, q)) {
                    continue;
                }
                if (series.markers) {
                    disc(image, q, 4.0, series.colour);
                }
                if (i < series.pointLabels.size()) {
                    drawText(image, int(q.x) + 6, int(q.y) - 12, series.pointLabels[i], 1, kInk);
                }
            }
            const int legendY = axes.top + 6 + int(s) * 16;
            line(image, {double(axes.left + axes.width + 10), double(legendY + 4)},
                 {double(axes.left + axes.width + 22), double(legendY + 4)}, series.colour, 3, false);
            drawText(image, axes.left + axes.width + 26, legendY, fitText(series.label, kMarginRight - 30, 1), 1, kInk);
        }
    }
    return image;
}

}  // namespace patina
