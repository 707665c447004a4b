#pragma once
#include <string>
#include <utility>
#include <vector>

#include "image/caption.h"
#include "scene/material.h"
#include "image/image.h"

namespace patina {

// Behind the images: the gaps between cells and the caption strips.
inline constexpr Rgb8 kSheetBackground{24, 24, 28};
inline constexpr Rgb8 kCaptionColour{230, 230, 230};
inline constexpr int kCellGap = 4;            // pixels between neighbouring cells
inline constexpr int kMaxSheetSide = 16384;   // pixels; larger sheets are refused

// An RGBA8 image of width x height (rows top first) shrunk to fit maxSide x maxSide, its aspect
// kept: each pixel the mean of the source pixels its box covers (the encoded values averaged: a
// thumbnail to recognise a map by, not a mip level). An image that fits is copied as it is;
// an empty one gives an empty image.
LdrImage shrunkToFit(int width, int height, const std::vector<uint8_t>& rgba, int maxSide);

// The caption scale for cells of this width: 1 below 800 pixels, 2 from 800, at most 4.
int captionScale(int cellWidth);

// Where contactSheet puts things: min(columns, count) columns of cellWidth x cellHeight
// images, each with a captionHeight strip under it, kCellGap apart.
struct SheetLayout {
    int columns = 0, rows = 0;
    int cellWidth = 0, cellHeight = 0, captionHeight = 0;
    int width = 0, height = 0;

    int cellX(int index) const { return index % columns * (cellWidth + kCellGap); }
    int cellY(int index) const { return index / columns * (cellHeight + captionHeight + kCellGap); }
};
// Throws std::invalid_argument for counts or sizes below 1, or a side above kMaxSheetSide.
SheetLayout sheetLayout(int cellWidth, int cellHeight, int count, int columns);

// The cells in a grid, row by row, each captioned with its name (cut with "..." to fit).
// Cells may differ in size: each is centred in a box of the largest width and height.
// Throws std::invalid_argument for no cells, a name count that differs, or a bad image.
LdrImage contactSheet(const std::vector<LdrImage>& cells, const std::vector<std::string>& names,
                      int columns);

// A contact sheet put together as its cells come, in order, so that its finished rows can be
// encoded (PngStream) while the next cells are drawn. contactSheet is this with every cell
// at hand.
class SheetBuilder {
public:
    // One cell per name, in boxes of cellWidth x cellHeight. Throws std::invalid_argument as
    // sheetLayout does.
    SheetBuilder(int cellWidth, int cellHeight, std::vector<std::string> names, int columns);
    // The next cell, centred in its box and captioned. Throws std::invalid_argument for a bad
    // image, one larger than the box, or a cell past the last name.
    void add(const LdrImage& cell);
    // Rows of the sheet no later cell changes: all above the next cell's box.
    int finishedRows() const;
    const LdrImage& image() const { return sheet_; }
    LdrImage release() && { return std::move(sheet_); }
    const SheetLayout& layout() const { return layout_; }

private:
    SheetLayout layout_;
    std::vector<std::string> names_;
    LdrImage sheet_;
    size_t added_ = 0;
};
// "name  r 0.30 s 0.50 m 1.00  base sRGB 1.00 0.86 0.60" in a caption of a panel this wide:
// where the name would be cut below a dozen characters, the base colour is left out, then the
// parameters; a name longer still is cut with "...".
std::string materialCaption(const Material& material, int panelWidth);

// a and b next to each other, captioned: a two-column contact sheet.
LdrImage sideBySide(const LdrImage& a, const LdrImage& b, const std::string& captionA,
                    const std::string& captionB);

// Per pixel, the largest |a - b| over R, G and B, in 0..255.
struct DifferenceStats {
    int max = 0;
    double mean = 0.0;
};
// Both throw std::invalid_argument when the sizes differ.
DifferenceStats differenceStats(const LdrImage& a, const LdrImage& b);
// That difference through heatColour: black where equal.
LdrImage differenceHeatMap(const LdrImage& a, const LdrImage& b);
// A ramp of rising luminance, black (0) through purple, red and orange to pale yellow (255).
Rgb8 heatColour(int difference);

}  // namespace patina
