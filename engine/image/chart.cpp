#include "image/chart.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include "image/chart_layout.h"
#include "image/cairo_image.h"
#include "image/text.h"

namespace patina {

namespace {

constexpr double kMarkerRadius = 4.5;
constexpr double kPointLabelPixels = 10.0;
constexpr double kCap = 4.0;   // half an error bar's cap

void setColour(cairo_t* cr, Rgb8 c) {
    cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
}

void setGrey(cairo_t* cr, double v) {
    cairo_set_source_rgb(cr, v, v, v);
}

void drawText(cairo_t* cr, const ChartText& text) {
    const FontLine line = fontLine(text.pixels);
    cairo_save(cr);
    if (text.vertical) {   // reads bottom to top: its baseline runs up the box's right side
        cairo_move_to(cr, text.box.x + line.ascent, text.box.y + text.box.height);
        cairo_rotate(cr, -std::numbers::pi / 2);
    } else {
        cairo_move_to(cr, text.box.x, text.box.y + line.ascent);
    }
    showText(cr, text.text, text.pixels);
    cairo_restore(cr);
}

// A marker's outline around the origin; filled except the cross and the plus, which are strokes.
void markerPath(cairo_t* cr, ChartMarker marker, double r) {
    cairo_new_path(cr);   // a text drawn before leaves a current point, which a polygon's first line_to would join
    auto polygon = [cr](int corners, double radius, double turn) {
        for (int k = 0; k < corners; ++k) {
            const double a = turn + 2 * std::numbers::pi * k / corners;
            cairo_line_to(cr, radius * std::sin(a), -radius * std::cos(a));
        }
        cairo_close_path(cr);
    };
    switch (marker) {
    case ChartMarker::Circle: cairo_arc(cr, 0, 0, r, 0, 2 * std::numbers::pi); break;
    case ChartMarker::Square: cairo_rectangle(cr, -0.85 * r, -0.85 * r, 1.7 * r, 1.7 * r); break;
    case ChartMarker::Triangle: polygon(3, 1.2 * r, 0.0); break;
    case ChartMarker::Diamond: polygon(4, 1.2 * r, 0.0); break;
    case ChartMarker::InvertedTriangle: polygon(3, 1.2 * r, std::numbers::pi); break;
    case ChartMarker::Cross:
    case ChartMarker::Plus: {
        const double a = marker == ChartMarker::Cross ? std::numbers::pi / 4 : 0.0;
        for (int k = 0; k < 2; ++k) {
            const double c = std::cos(a + k * std::numbers::pi / 2) * r, s = std::sin(a + k * std::numbers::pi / 2) * r;
            cairo_move_to(cr, -c, -s);
            cairo_line_to(cr, c, s);
        }
        break;
    }
    case ChartMarker::Star:
        for (int k = 0; k < 10; ++k) {
            const double a = std::numbers::pi * k / 5, radius = k % 2 ? 0.5 * r : 1.3 * r;
            cairo_line_to(cr, radius * std::sin(a), -radius * std::cos(a));
        }
        cairo_close_path(cr);
        break;
    }
}

void drawMarker(cairo_t* cr, glm::dvec2 at, ChartMarker marker) {
    cairo_save(cr);
    cairo_translate(cr, at.x, at.y);
    markerPath(cr, marker, kMarkerRadius);
    if (marker == ChartMarker::Cross || marker == ChartMarker::Plus) {
        cairo_set_line_width(cr, 2.0);
        cairo_stroke(cr);
    } else {
        cairo_fill(cr);
    }
    cairo_restore(cr);
}

void setLine(cairo_t* cr, bool dashed) {
    const double dash[] = {6.0, 4.0};
    cairo_set_dash(cr, dash, dashed ? 2 : 0, 0.0);
    cairo_set_line_width(cr, 2.0);
}

// The bar from y - se to y + se with a cap at each end; on a log axis an end at or below zero
// runs to the plot's bottom without a cap.
void drawErrorBar(cairo_t* cr, const ChartPanelLayout& panel, glm::dvec2 point, double error) {
    const glm::dvec2 top = panel.toPixel({point.x, point.y + error});
    const bool lowShown = !panel.logY || point.y - error > 0;
    const glm::dvec2 low = lowShown ? panel.toPixel({point.x, point.y - error})
                                    : glm::dvec2(top.x, panel.plot.y + panel.plot.height);
    cairo_set_line_width(cr, 1.5);
    cairo_move_to(cr, top.x, top.y);
    cairo_line_to(cr, low.x, low.y);
    cairo_move_to(cr, top.x - kCap, top.y);
    cairo_line_to(cr, top.x + kCap, top.y);
    if (lowShown) {
        cairo_move_to(cr, low.x - kCap, low.y);
        cairo_line_to(cr, low.x + kCap, low.y);
    }
    cairo_stroke(cr);
}

bool drawable(const ChartPanelLayout& panel, glm::dvec2 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && (!panel.logX || p.x > 0) && (!panel.logY || p.y > 0);
}

void drawSeries(cairo_t* cr, const ChartPanelLayout& panel, const ChartSeries& series) {
    setColour(cr, chartColour(series.style));
    if (series.line) {
        setLine(cr, series.dashed);
        for (const glm::dvec2& p : series.points) {
            if (drawable(panel, p)) {
                const glm::dvec2 q = panel.toPixel(p);
                cairo_line_to(cr, q.x, q.y);
            }
        }
        cairo_stroke(cr);
    }
    setLine(cr, false);
    for (size_t i = 0; i < series.points.size(); ++i) {
        if (!drawable(panel, series.points[i])) {
            continue;
        }
        if (i < series.errors.size() && series.errors[i] > 0 && std::isfinite(series.errors[i])) {
            drawErrorBar(cr, panel, series.points[i], series.errors[i]);
        }
        if (series.markers) {
            drawMarker(cr, panel.toPixel(series.points[i]), chartMarker(series.style));
        }
    }
}

// Where a point's label goes: the first of these places beside it that stays inside the plot
// and clear of the labels placed before, else the first inside the plot (the old right-above).
ChartBox placeLabel(const ChartPanelLayout& panel, glm::dvec2 q, double width, const std::vector<ChartBox>& placed) {
    const FontLine line = fontLine(kPointLabelPixels);
    const double height = line.ascent + line.descent;
    const double left = q.x - 7 - width, right = q.x + 7, above = q.y - 6 - line.ascent, below = q.y + 6;
    const glm::dvec2 corners[] = {{right, above}, {right, below}, {left, above}, {left, below},
                                  {right, above - height}, {left, above - height}, {right, below + height},
                                  {left, below + height}};
    const ChartBox& plot = panel.plot;
    auto inside = [&](const ChartBox& box) {
        return box.x >= plot.x && box.x + box.width <= plot.x + plot.width && box.y >= plot.y &&
               box.y + box.height <= plot.y + plot.height;
    };
    std::optional<ChartBox> fallback;
    for (const glm::dvec2 corner : corners) {
        const ChartBox box{corner.x, corner.y, width, height};
        if (!inside(box)) {
            continue;
        }
        if (std::none_of(placed.begin(), placed.end(), [&](const ChartBox& other) { return box.overlaps(other); })) {
            return box;
        }
        fallback = fallback.value_or(box);
    }
    return fallback.value_or(ChartBox{right, above, width, height});
}

void drawPointLabels(cairo_t* cr, const ChartPanelLayout& panel, const ChartSeries& series, std::vector<ChartBox>& placed) {
    setGrey(cr, 0.2);
    const double ascent = fontLine(kPointLabelPixels).ascent;
    for (size_t i = 0; i < series.points.size() && i < series.pointLabels.size(); ++i) {
        if (drawable(panel, series.points[i]) && !series.pointLabels[i].empty()) {
            const double width = textAdvance(series.pointLabels[i], kPointLabelPixels);
            const ChartBox box = placeLabel(panel, panel.toPixel(series.points[i]), width, placed);
            placed.push_back(box);
            cairo_move_to(cr, box.x, box.y + ascent);
            showText(cr, series.pointLabels[i], kPointLabelPixels);
        }
    }
}

void drawAxes(cairo_t* cr, const ChartPanelLayout& panel) {
    const ChartBox& plot = panel.plot;
    setLine(cr, false);
    cairo_set_line_width(cr, 1.0);
    setGrey(cr, 0.88);
    for (double t : panel.xTicks) {
        const double x = std::round(plot.x + (t - panel.x0) / (panel.x1 - panel.x0) * plot.width) + 0.5;
        cairo_move_to(cr, x, plot.y);
        cairo_line_to(cr, x, plot.y + plot.height + 4.0);
    }
    for (double t : panel.yTicks) {
        const double y = std::round(plot.y + plot.height - (t - panel.y0) / (panel.y1 - panel.y0) * plot.height) + 0.5;
        cairo_move_to(cr, plot.x - 4.0, y);
        cairo_line_to(cr, plot.x + plot.width, y);
    }
    cairo_stroke(cr);
    setGrey(cr, 0.12);
    cairo_rectangle(cr, std::round(plot.x) + 0.5, std::round(plot.y) + 0.5, std::round(plot.width),
                    std::round(plot.height));
    cairo_stroke(cr);
    for (const auto* labels : {&panel.xTickLabels, &panel.yTickLabels}) {
        for (const ChartText& label : *labels) {
            drawText(cr, label);
        }
    }
    drawText(cr, panel.title);
    drawText(cr, panel.xLabel);
    drawText(cr, panel.yLabel);
}

void drawLegend(cairo_t* cr, const ChartPanelLayout& panel, const ChartPanel& source) {
    for (const ChartLegendEntry& entry : panel.legend) {
        const ChartSeries& series = source.series[entry.series];
        const double y = entry.sample.y + entry.sample.height / 2;
        setColour(cr, chartColour(series.style));
        if (series.line || !series.markers) {
            setLine(cr, series.dashed);
            cairo_move_to(cr, entry.sample.x + 1, y);
            cairo_line_to(cr, entry.sample.x + entry.sample.width - 1, y);
            cairo_stroke(cr);
        }
        if (series.markers) {
            drawMarker(cr, {entry.sample.x + entry.sample.width / 2, y}, chartMarker(series.style));
        }
        setGrey(cr, 0.12);
        drawText(cr, entry.label);
    }
}

// The one drawing of a chart, whatever the surface.
void drawChart(cairo_t* cr, const Chart& chart, const ChartLayout& layout) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    for (size_t p = 0; p < chart.panels.size(); ++p) {
        const ChartPanelLayout& panel = layout.panels[p];
        drawAxes(cr, panel);
        cairo_save(cr);
        cairo_rectangle(cr, panel.plot.x, panel.plot.y, panel.plot.width, panel.plot.height);
        cairo_clip(cr);
        for (const ChartSeries& series : chart.panels[p].series) {
            drawSeries(cr, panel, series);
        }
        std::vector<ChartBox> placed;   // labels kept apart across the panel's series
        for (const ChartSeries& series : chart.panels[p].series) {
            drawPointLabels(cr, panel, series, placed);
        }
        cairo_restore(cr);
        drawLegend(cr, panel, chart.panels[p]);
    }
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

// The chart drawn onto a vector surface that `create` makes, writing into the returned bytes.
template <typename Create>
std::string vectorChart(const Chart& chart, Create create) {
    const ChartLayout layout = chartLayout(chart);
    std::string bytes;
    cairo_surface_t* surface = create(&bytes, layout.width, layout.height);
    cairo_t* cr = cairo_create(surface);
    drawChart(cr, chart, layout);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    const cairo_status_t status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS) {
        throw std::runtime_error(std::string("cannot draw the chart: ") + cairo_status_to_string(status));
    }
    return bytes;
}

}  // namespace

Rgb8 chartColour(size_t style) {
    // Okabe and Ito's colours for colour-blind readers ("Color Universal Design", 2008) without
    // their yellow, which is faint on white, then a dark yellow, grey and brown.
    static const Rgb8 palette[] = {{0, 114, 178},   {213, 94, 0},    {0, 158, 115},  {204, 121, 167},
                                   {230, 159, 0},   {86, 180, 233},  {0, 0, 0},      {170, 150, 0},
                                   {128, 128, 128}, {140, 80, 40}};
    return palette[style % (sizeof palette / sizeof palette[0])];
}

ChartMarker chartMarker(size_t style) {
    return ChartMarker(style % 8);
}

LdrImage chartToImage(const Chart& chart) {
    const ChartLayout layout = chartLayout(chart);
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, layout.width, layout.height);
    cairo_t* cr = cairo_create(surface);
    drawChart(cr, chart, layout);
    cairo_destroy(cr);
    LdrImage image = imageFromSurface(surface);
    cairo_surface_destroy(surface);
    return image;
}

std::string chartToSvg(const Chart& chart) {
    return vectorChart(chart, [](std::string* bytes, int width, int height) {
        cairo_surface_t* surface = cairo_svg_surface_create_for_stream(append, bytes, width, height);
        cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
        return surface;
    });
}

std::string chartToPdf(const Chart& chart) {
    return vectorChart(chart, [](std::string* bytes, int width, int height) {
        return cairo_pdf_surface_create_for_stream(append, bytes, width, height);
    });
}

}  // namespace patina
