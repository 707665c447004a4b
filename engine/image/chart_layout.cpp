#include "image/chart_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "image/text.h"

namespace patina {

namespace {

constexpr double kTitlePixels = 14.0, kLabelPixels = 12.0, kTickPixels = 11.0;
constexpr double kPad = 10.0;          // around the panel's edges
constexpr double kGap = 6.0;           // the least room between two texts
constexpr double kTickLength = 4.0;    // a tick mark, outside the plot
constexpr double kSampleWidth = 30.0;  // a legend's line and marker
constexpr double kMinPlot = 120.0;

double axisValue(double value, bool log) {
    return log ? std::log10(std::max(value, 1e-300)) : value;
}

ChartText measured(std::string text, double pixels) {
    const FontLine line = fontLine(pixels);
    const double width = textAdvance(text, pixels);
    return {std::move(text), {0.0, 0.0, width, line.ascent + line.descent}, pixels, false};
}

double lineHeight(double pixels) {
    const FontLine line = fontLine(pixels);
    return line.ascent + line.descent;
}

struct Range {
    double lo = std::numeric_limits<double>::max(), hi = -std::numeric_limits<double>::max();
    void add(double v) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
};

// The axes' ranges over every point and error bar, padded; 0..1 when nothing can be shown.
void findRanges(const ChartPanel& panel, ChartPanelLayout& layout) {
    Range x, y;
    for (const ChartSeries& series : panel.series) {
        for (size_t i = 0; i < series.points.size(); ++i) {
            const glm::dvec2 p = series.points[i];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || (panel.logX && p.x <= 0) || (panel.logY && p.y <= 0)) {
                continue;
            }
            x.add(axisValue(p.x, panel.logX));
            y.add(axisValue(p.y, panel.logY));
            const double error = i < series.errors.size() && std::isfinite(series.errors[i]) ? series.errors[i] : 0.0;
            y.add(axisValue(p.y + error, panel.logY));
            if (!panel.logY || p.y - error > 0) {   // a log axis's bar is cut at the bottom instead
                y.add(axisValue(p.y - error, panel.logY));
            }
        }
    }
    if (x.lo > x.hi) {
        x = {0.0, 1.0}, y = {0.0, 1.0};
    }
    auto pad = [](Range& r, bool log) {
        const double span = r.hi - r.lo;
        const double margin = span > 0 ? span * 0.06 : (log ? 0.5 : std::max(std::abs(r.lo) * 0.1, 0.5));
        r.lo -= margin, r.hi += margin;
    };
    pad(x, panel.logX);
    pad(y, panel.logY);
    layout.x0 = x.lo, layout.x1 = x.hi, layout.y0 = y.lo, layout.y1 = y.hi;
}

// 1, 2 or 5 times a power of ten, near span / 6.
double niceStep(double span) {
    const double raw = span / 6.0;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / magnitude;
    return (f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0) * magnitude;
}

std::vector<double> linearTicks(double lo, double hi) {
    std::vector<double> ticks;
    const double step = niceStep(hi - lo);
    for (double k = std::ceil(lo / step); k * step <= hi + step * 1e-9; k += 1.0) {
        ticks.push_back(std::abs(k) < 0.5 ? 0.0 : k * step);
    }
    return ticks;
}

// Decades, with 2 and 5 between them when the axis spans less than two; where that gives
// fewer than two, evenly stepped values.
std::vector<double> logTicks(double lo, double hi) {
    std::vector<double> ticks;
    const bool fine = hi - lo < 2.0;
    for (double d = std::floor(lo); d <= hi; d += 1.0) {
        for (double m : {1.0, 2.0, 5.0}) {
            const double t = d + std::log10(m);
            if (t >= lo && t <= hi && (fine || m == 1.0)) {
                ticks.push_back(t);
            }
        }
    }
    if (ticks.size() < 2) {
        ticks.clear();
        for (double v : linearTicks(std::pow(10.0, lo), std::pow(10.0, hi))) {
            if (v > 0) {
                ticks.push_back(std::log10(v));
            }
        }
    }
    return ticks;
}

std::string tickText(double tick, bool log, double step) {
    char text[32];
    if (log) {
        const double v = std::pow(10.0, tick);
        const int exponent = int(std::floor(tick + 1e-9));
        const double mantissa = v / std::pow(10.0, exponent);
        if (v >= 1e-3 && v < 1e5) {
            std::snprintf(text, sizeof text, "%.4g", v);
        } else if (std::abs(mantissa - 1.0) < 1e-6) {
            std::snprintf(text, sizeof text, "1e%d", exponent);
        } else {
            std::snprintf(text, sizeof text, "%.2ge%d", mantissa, exponent);
        }
    } else if (std::abs(tick) >= 1e6 || step < 1e-4) {
        std::snprintf(text, sizeof text, "%.3g", tick);
    } else {
        const int decimals = std::max(0, -int(std::floor(std::log10(step) + 1e-9)));
        std::snprintf(text, sizeof text, "%.*f", decimals, tick);
    }
    return text;
}

std::vector<ChartText> tickLabels(const std::vector<double>& ticks, bool log) {
    const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
    std::vector<ChartText> labels;
    for (double t : ticks) {
        labels.push_back(measured(tickText(t, log, step), kTickPixels));
    }
    return labels;
}

ChartBox grown(ChartBox box, double by) {
    return {box.x - by, box.y - by, box.width + 2 * by, box.height + 2 * by};
}

// Every stride-th label, the smallest stride that leaves kGap between neighbours.
std::vector<ChartText> thinned(const std::vector<ChartText>& labels) {
    for (size_t stride = 1; stride < labels.size(); ++stride) {
        std::vector<ChartText> kept;
        for (size_t i = 0; i < labels.size(); i += stride) {
            kept.push_back(labels[i]);
        }
        bool apart = true;
        for (size_t k = 0; k + 1 < kept.size(); ++k) {
            apart = apart && !grown(kept[k].box, kGap / 2).overlaps(grown(kept[k + 1].box, kGap / 2));
        }
        if (apart) {
            return kept;
        }
    }
    return labels.empty() ? labels : std::vector<ChartText>{labels.front()};
}

// A log axis's labels: all of them if they fit, else its decades alone, thinned.
std::vector<ChartText> keptLabels(const std::vector<ChartText>& labels, const std::vector<double>& ticks, bool log) {
    std::vector<ChartText> kept = thinned(labels);
    if (!log || kept.size() == labels.size()) {
        return kept;
    }
    std::vector<ChartText> decades;
    for (size_t i = 0; i < ticks.size(); ++i) {
        if (std::abs(ticks[i] - std::round(ticks[i])) < 1e-9) {
            decades.push_back(labels[i]);
        }
    }
    return decades.size() >= 2 ? thinned(decades) : kept;
}

double widest(const std::vector<ChartText>& texts) {
    double width = 0.0;
    for (const ChartText& t : texts) {
        width = std::max(width, t.box.width);
    }
    return width;
}

// The legend's entries, measured and flowed into rows under the plot from `top`, within
// [left, right]; returns the bottom of the last row.
double placeLegend(const ChartPanel& panel, double left, double right, double top,
                   std::vector<ChartLegendEntry>& legend) {
    const double row = std::max(lineHeight(kLabelPixels), 12.0) + 4.0;
    double x = left, y = top;
    for (size_t s = 0; s < panel.series.size(); ++s) {
        ChartText label = measured(panel.series[s].label, kLabelPixels);
        const double width = kSampleWidth + kGap + label.box.width;
        if (x > left && x + width > right) {
            x = left, y += row;
        }
        label.box.x = x + kSampleWidth + kGap;
        label.box.y = y + (row - label.box.height) / 2;
        legend.push_back({s, {x, y, kSampleWidth, row}, label});
        x += width + 3 * kGap;
    }
    return panel.series.empty() ? top : y + row;
}

}  // namespace

bool ChartBox::overlaps(const ChartBox& other) const {
    return x < other.x + other.width && other.x < x + width && y < other.y + other.height && other.y < y + height;
}

glm::dvec2 ChartPanelLayout::toPixel(glm::dvec2 point) const {
    return {plot.x + (axisValue(point.x, logX) - x0) / (x1 - x0) * plot.width,
            plot.y + plot.height - (axisValue(point.y, logY) - y0) / (y1 - y0) * plot.height};
}

namespace {

// One panel from `left` across: its width is the chart's unless a text needs more.
ChartPanelLayout panelLayout(const ChartPanel& panel, const Chart& chart, double left, double& width, double& bottom) {
    ChartPanelLayout layout;
    layout.logX = panel.logX, layout.logY = panel.logY;
    findRanges(panel, layout);
    layout.xTicks = layout.logX ? logTicks(layout.x0, layout.x1) : linearTicks(layout.x0, layout.x1);
    layout.yTicks = layout.logY ? logTicks(layout.y0, layout.y1) : linearTicks(layout.y0, layout.y1);
    std::vector<ChartText> xLabels = tickLabels(layout.xTicks, layout.logX);
    std::vector<ChartText> yLabels = tickLabels(layout.yTicks, layout.logY);
    layout.title = measured(panel.title, kTitlePixels);
    layout.xLabel = measured(panel.xLabel, kLabelPixels);
    layout.yLabel = measured(panel.yLabel, kLabelPixels);
    layout.yLabel.vertical = true;
    std::swap(layout.yLabel.box.width, layout.yLabel.box.height);

    const double tickRoom = kTickLength + 3.0;
    const double top = kPad + layout.title.box.height + kPad;
    const double marginLeft = kPad + layout.yLabel.box.width + kGap + widest(yLabels) + tickRoom;
    const double marginRight = std::max(2 * kPad, widest(xLabels) / 2 + kPad);
    const double marginBottom = tickRoom + lineHeight(kTickPixels) + kGap + layout.xLabel.box.height + kPad;
    double legendWidest = 0.0;
    for (const ChartSeries& series : panel.series) {
        legendWidest = std::max(legendWidest, kSampleWidth + kGap + textAdvance(series.label, kLabelPixels));
    }
    width = std::max({double(chart.panelWidth), marginLeft + kMinPlot + marginRight,
                      layout.title.box.width + 2 * kPad, marginLeft + layout.xLabel.box.width + marginRight,
                      legendWidest + 2 * kPad});
    const double plotHeight = std::max({double(chart.panelHeight) - top - marginBottom, kMinPlot,
                                        layout.yLabel.box.height});
    layout.plot = {left + marginLeft, top, width - marginLeft - marginRight, plotHeight};
    const ChartBox& plot = layout.plot;

    for (size_t i = 0; i < xLabels.size(); ++i) {
        const double x = plot.x + (layout.xTicks[i] - layout.x0) / (layout.x1 - layout.x0) * plot.width;
        xLabels[i].box.x = x - xLabels[i].box.width / 2, xLabels[i].box.y = plot.y + plot.height + tickRoom;
    }
    for (size_t i = 0; i < yLabels.size(); ++i) {
        const double y = plot.y + plot.height - (layout.yTicks[i] - layout.y0) / (layout.y1 - layout.y0) * plot.height;
        yLabels[i].box.x = plot.x - tickRoom - yLabels[i].box.width, yLabels[i].box.y = y - yLabels[i].box.height / 2;
    }
    // Bottom to top, so that neighbours are next to each other as on the x axis.
    layout.xTickLabels = keptLabels(xLabels, layout.xTicks, layout.logX);
    layout.yTickLabels = keptLabels(yLabels, layout.yTicks, layout.logY);

    layout.title.box.x = std::clamp(plot.x + (plot.width - layout.title.box.width) / 2, left + kPad,
                                    left + width - kPad - layout.title.box.width);
    layout.title.box.y = kPad;
    layout.xLabel.box.x = plot.x + (plot.width - layout.xLabel.box.width) / 2;
    layout.xLabel.box.y = plot.y + plot.height + tickRoom + lineHeight(kTickPixels) + kGap;
    layout.yLabel.box.x = plot.x - tickRoom - widest(yLabels) - kGap - layout.yLabel.box.width;
    layout.yLabel.box.y = plot.y + (plot.height - layout.yLabel.box.height) / 2;
    bottom = placeLegend(panel, left + kPad, left + width - kPad, plot.y + plot.height + marginBottom - kPad / 2,
                         layout.legend) + kPad;
    return layout;
}

}  // namespace

ChartLayout chartLayout(const Chart& chart) {
    ChartLayout layout;
    double left = 0.0, bottom = 0.0;
    for (const ChartPanel& panel : chart.panels) {
        double width = 0.0, panelBottom = 0.0;
        layout.panels.push_back(panelLayout(panel, chart, left, width, panelBottom));
        left += width;
        bottom = std::max(bottom, panelBottom);
    }
    layout.width = std::max(1, int(std::ceil(left)));
    layout.height = std::max({1, chart.panelHeight, int(std::ceil(bottom))});
    return layout;
}

}  // namespace patina
