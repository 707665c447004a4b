#include "picture/compositing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "shading/brdf_models.h"
#include "shading/shading.h"

namespace patina {

namespace {

void checkImage(const LdrImage& image, const std::string& what) {
    if (image.width < 1 || image.height < 1 ||
        image.rgba.size() != size_t(image.width) * size_t(image.height) * 4) {
        throw std::invalid_argument(what + " is not a valid image");
    }
}

void checkSameSize(const LdrImage& a, const LdrImage& b) {
    checkImage(a, "the first image");
    checkImage(b, "the second image");
    if (a.width != b.width || a.height != b.height) {
        throw std::invalid_argument("cannot compare a " + std::to_string(a.width) + "x" +
                                    std::to_string(a.height) + " image with a " +
                                    std::to_string(b.width) + "x" + std::to_string(b.height) + " one");
    }
}

LdrImage filledImage(int width, int height, Rgb8 colour) {
    LdrImage image{width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 4)};
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i] = colour.r;
        image.rgba[i + 1] = colour.g;
        image.rgba[i + 2] = colour.b;
        image.rgba[i + 3] = 255;
    }
    return image;
}

// `from` must lie inside `to` at (x, y).
void paste(LdrImage& to, const LdrImage& from, int x, int y) {
    const size_t rowBytes = size_t(from.width) * 4;
    for (int row = 0; row < from.height; ++row) {
        std::memcpy(&to.rgba[((size_t(y) + size_t(row)) * size_t(to.width) + size_t(x)) * 4],
                    &from.rgba[size_t(row) * rowBytes], rowBytes);
    }
}

int maxChannelDifference(const uint8_t* a, const uint8_t* b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

}  // namespace

int captionScale(int cellWidth) {
    return std::clamp(cellWidth / 800 + 1, 1, 4);
}

SheetLayout sheetLayout(int cellWidth, int cellHeight, int count, int columns) {
    if (cellWidth < 1 || cellHeight < 1 || count < 1 || columns < 1) {
        throw std::invalid_argument("a contact sheet needs at least one cell and one column");
    }
    SheetLayout layout;
    layout.columns = std::min(columns, count);
    layout.rows = (count + layout.columns - 1) / layout.columns;
    layout.cellWidth = cellWidth;
    layout.cellHeight = cellHeight;
    layout.captionHeight = captionHeight(captionScale(cellWidth));
    const int64_t width = int64_t(layout.columns) * cellWidth + int64_t(layout.columns - 1) * kCellGap;
    const int64_t height = int64_t(layout.rows) * (int64_t(cellHeight) + layout.captionHeight) +
                           int64_t(layout.rows - 1) * kCellGap;
    if (width > kMaxSheetSide || height > kMaxSheetSide) {
        throw std::invalid_argument("a " + std::to_string(width) + "x" + std::to_string(height) +
                                    " image is larger than " + std::to_string(kMaxSheetSide) +
                                    " pixels per side");
    }
    layout.width = int(width);
    layout.height = int(height);
    return layout;
}

LdrImage shrunkToFit(int width, int height, const std::vector<uint8_t>& rgba, int maxSide) {
    if (width <= 0 || height <= 0 || maxSide <= 0 || rgba.size() < size_t(width) * size_t(height) * 4) {
        return {};
    }
    const double scale = std::min(1.0, double(maxSide) / double(std::max(width, height)));
    LdrImage out;
    out.width = std::max(1, int(std::lround(width * scale)));
    out.height = std::max(1, int(std::lround(height * scale)));
    out.rgba.resize(size_t(out.width) * size_t(out.height) * 4);
    for (int y = 0; y < out.height; ++y) {
        const int y0 = int(int64_t(y) * height / out.height), y1 = std::max(y0 + 1, int(int64_t(y + 1) * height / out.height));
        for (int x = 0; x < out.width; ++x) {
            const int x0 = int(int64_t(x) * width / out.width), x1 = std::max(x0 + 1, int(int64_t(x + 1) * width / out.width));
            uint64_t sum[4] = {0, 0, 0, 0};
            for (int sy = y0; sy < y1; ++sy) {
                const uint8_t* row = &rgba[(size_t(sy) * size_t(width) + size_t(x0)) * 4];
                for (int sx = 0; sx < (x1 - x0) * 4; ++sx) {
                    sum[sx % 4] += row[sx];
                }
            }
            const uint64_t count = uint64_t(x1 - x0) * uint64_t(y1 - y0);
            for (int c = 0; c < 4; ++c) {
                out.rgba[(size_t(y) * size_t(out.width) + size_t(x)) * 4 + size_t(c)] = uint8_t((sum[c] + count / 2) / count);
            }
        }
    }
    return out;
}

LdrImage contactSheet(const std::vector<LdrImage>& cells, const std::vector<std::string>& names,
                      int columns) {
    if (names.size() != cells.size()) {
        throw std::invalid_argument(std::to_string(cells.size()) + " cells but " +
                                    std::to_string(names.size()) + " names");
    }
    int cellWidth = 0, cellHeight = 0;
    for (size_t i = 0; i < cells.size(); ++i) {
        checkImage(cells[i], "cell " + std::to_string(i));
        cellWidth = std::max(cellWidth, cells[i].width);
        cellHeight = std::max(cellHeight, cells[i].height);
    }
    SheetBuilder sheet(cellWidth, cellHeight, names, columns);
    for (const LdrImage& cell : cells) {
        sheet.add(cell);
    }
    return std::move(sheet).release();
}

SheetBuilder::SheetBuilder(int cellWidth, int cellHeight, std::vector<std::string> names, int columns)
    : layout_(sheetLayout(cellWidth, cellHeight, int(names.size()), columns)), names_(std::move(names)),
      sheet_(filledImage(layout_.width, layout_.height, kSheetBackground)) {}

void SheetBuilder::add(const LdrImage& cell) {
    if (added_ >= names_.size()) {
        throw std::invalid_argument("the sheet has room for " + std::to_string(names_.size()) + " cells");
    }
    checkImage(cell, "cell " + std::to_string(added_));
    if (cell.width > layout_.cellWidth || cell.height > layout_.cellHeight) {
        throw std::invalid_argument("cell " + std::to_string(added_) + " is larger than the sheet's boxes");
    }
    const int scale = captionScale(layout_.cellWidth);
    const int padding = kCaptionPadding * scale;
    const int x = layout_.cellX(int(added_));
    const int y = layout_.cellY(int(added_));
    paste(sheet_, cell, x + (layout_.cellWidth - cell.width) / 2, y + (layout_.cellHeight - cell.height) / 2);
    const std::string caption = fitText(names_[added_], layout_.cellWidth - 2 * padding, scale);
    drawText(sheet_, x + (layout_.cellWidth - textWidth(caption, scale)) / 2, y + layout_.cellHeight + padding,
             caption, scale, kCaptionColour);
    ++added_;
}

int SheetBuilder::finishedRows() const {
    return added_ == names_.size() ? layout_.height : layout_.cellY(int(added_));
}

LdrImage sideBySide(const LdrImage& a, const LdrImage& b, const std::string& captionA,
                    const std::string& captionB) {
    return contactSheet({a, b}, {captionA, captionB}, 2);
}

DifferenceStats differenceStats(const LdrImage& a, const LdrImage& b) {
    checkSameSize(a, b);
    DifferenceStats stats;
    double sum = 0.0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) {
        const int difference = maxChannelDifference(&a.rgba[i], &b.rgba[i]);
        stats.max = std::max(stats.max, difference);
        sum += difference;
    }
    stats.mean = sum / (double(a.width) * double(a.height));
    return stats;
}

LdrImage differenceHeatMap(const LdrImage& a, const LdrImage& b) {
    checkSameSize(a, b);
    LdrImage map{a.width, a.height, std::vector<uint8_t>(a.rgba.size())};
    for (size_t i = 0; i < a.rgba.size(); i += 4) {
        const Rgb8 colour = heatColour(maxChannelDifference(&a.rgba[i], &b.rgba[i]));
        map.rgba[i] = colour.r;
        map.rgba[i + 1] = colour.g;
        map.rgba[i + 2] = colour.b;
        map.rgba[i + 3] = 255;
    }
    return map;
}

Rgb8 heatColour(int difference) {
    // Luma of the stops (Rec. 709 weights): 0, 28, 76, 155, 246, so brighter reads as larger.
    static constexpr std::array<Rgb8, 5> kStops{
        {{0, 0, 0}, {60, 10, 110}, {190, 40, 90}, {250, 140, 30}, {255, 250, 180}}};
    constexpr int kSegments = int(kStops.size()) - 1;
    const int position = std::clamp(difference, 0, 255) * kSegments;   // 255 per segment
    const int segment = std::min(position / 255, kSegments - 1);
    const int t = position - segment * 255;
    auto mix = [t](uint8_t from, uint8_t to) {
        return uint8_t((from * (255 - t) + to * t + 127) / 255);
    };
    const Rgb8 from = kStops[size_t(segment)], to = kStops[size_t(segment) + 1];
    return {mix(from.r, to.r), mix(from.g, to.g), mix(from.b, to.b)};
}

std::string materialCaption(const Material& material, int panelWidth) {
    // The base colour as the editor's field shows it: sRGB, and named so (files hold linear).
    const glm::vec3 base = shader::srgbColor(material.baseColor);
    char full[256], parameters[192];
    // The BRDF model where it is not the seed's: A and B may differ in it alone (a glTF part
    // under `gltf` against the same under `epic`).
    std::string model =
        material.model == BrdfModelId::Epic ? std::string() : "  " + std::string(brdfModel(material.model).name);
    // The layers a part has, so that A with a coat and B without are not captioned alike.
    char layer[48];
    if (material.clearcoat > 0.0f) {
        std::snprintf(layer, sizeof layer, "  coat %.2f", double(material.clearcoat));
        model += layer;
    }
    if (material.sheenColor != glm::vec3(0.0f)) {
        const float sheen = std::max({material.sheenColor.r, material.sheenColor.g, material.sheenColor.b});
        std::snprintf(layer, sizeof layer, "  sheen %.2f", double(sheen));
        model += layer;
    }
    if (material.transmission > 0.0f) {
        std::snprintf(layer, sizeof layer, "  transmission %.2f", double(material.transmission));
        model += layer;
    }
    if (material.anisotropyStrength > 0.0f) {
        std::snprintf(layer, sizeof layer, "  anisotropy %.2f", double(material.anisotropyStrength));
        model += layer;
    }
    if (material.specularTint != glm::vec3(1.0f) || material.specularWeight != 1.0f) {
        const glm::vec3& t = material.specularTint;
        std::snprintf(layer, sizeof layer, "  tint %.2f %.2f %.2f w %.2f", double(t.r), double(t.g), double(t.b),
                      double(material.specularWeight));
        model += layer;
    }
    if (material.iridescence > 0.0f) {
        std::snprintf(layer, sizeof layer, "  film %.2f %.0f nm", double(material.iridescence),
                      double(material.iridescenceThicknessMaximum));
        model += layer;
    }
    std::snprintf(parameters, sizeof parameters, "  r %.2f s %.2f m %.2f%s", double(material.roughness),
                  double(material.specular), double(material.metallic), model.c_str());
    std::snprintf(full, sizeof full, "%s  base sRGB %.2f %.2f %.2f", parameters, double(base.r), double(base.g),
                  double(base.b));
    const int scale = captionScale(panelWidth);
    const int width = panelWidth - 2 * kCaptionPadding * scale;
    // The name comes first: the base colour, then the parameters, give way before the name is
    // cut below a dozen characters (a side-by-side half is too narrow for all of it).
    const int nameRoom = std::min(textWidth(material.name, scale), textWidth("MMMMMMMMMMMM", scale));
    for (const char* numbers : {full, parameters}) {
        if (const int room = width - textWidth(numbers, scale); room >= nameRoom) {
            return fitText(material.name, room, scale) + numbers;
        }
    }
    return fitText(material.name, std::max(width, textWidth("...", scale)), scale);
}

}  // namespace patina
