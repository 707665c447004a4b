#include "image/caption.h"

#include <algorithm>
#include <cmath>

#include "image/cairo_image.h"
#include "image/text.h"

namespace patina {

namespace {

constexpr char kEllipsis[] = "\xE2\x80\xA6";   // U+2026

double pixels(int scale) {
    return kCaptionPixels * scale;
}

}  // namespace

int textHeight(int scale) {
    const FontLine line = fontLine(pixels(scale));
    return int(std::ceil(line.ascent + line.descent));
}

int captionHeight(int scale) {
    return textHeight(scale) + 2 * kCaptionPadding * scale;
}

int textWidth(std::string_view text, int scale) {
    return int(std::ceil(textAdvance(text, pixels(scale)) - 1e-9));
}

std::string fitText(std::string_view text, int maxWidth, int scale) {
    const std::string line = oneLineText(text);
    if (textWidth(line, scale) <= maxWidth) {
        return line;
    }
    const int room = maxWidth - textWidth(kEllipsis, scale);
    if (room < 0) {
        return "";
    }
    // The longest run of whole characters that fits before the ellipsis.
    size_t kept = 0;
    for (size_t next = 0; next < line.size();) {
        next += characterLength(line, next);
        if (textWidth(std::string_view(line).substr(0, next), scale) > room) {
            break;
        }
        kept = next;
    }
    std::string cut = line.substr(0, kept);
    cut.erase(cut.find_last_not_of(' ') + 1);   // "gold …" reads worse than "gold…"
    return cut + kEllipsis;
}

void drawText(LdrImage& image, int x, int y, std::string_view text, int scale, Rgb8 colour) {
    // Only the text's box, with a pixel of room for anti-aliasing, goes through Cairo.
    const int slack = 2 * scale;
    const int x0 = std::max(x - slack, 0), y0 = std::max(y - slack, 0);
    const int x1 = int(std::min<int64_t>(int64_t(x) + textWidth(text, scale) + slack, image.width));
    const int y1 = int(std::min<int64_t>(int64_t(y) + textHeight(scale) + slack, image.height));
    if (x0 >= x1 || y0 >= y1) {
        return;
    }
    cairo_surface_t* surface = surfaceFromImage(image, x0, y0, x1 - x0, y1 - y0);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, colour.r / 255.0, colour.g / 255.0, colour.b / 255.0);
    cairo_move_to(cr, x - x0, y - y0 + fontLine(pixels(scale)).ascent);
    showText(cr, text, pixels(scale));
    cairo_destroy(cr);
    copySurfaceToImage(surface, image, x0, y0);
    cairo_surface_destroy(surface);
}

}  // namespace patina
