#include "image/caption.h"

#include <algorithm>

// stb_easy_font is header-only with static functions; this file uses only some of them.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace patina {

namespace {

constexpr int kMaxQuadsPerGlyph = 16;   // the busiest glyph of stb_easy_font has 11
constexpr int kFloatsPerQuad = 16;      // 4 vertices of x, y, z and 4 colour bytes

bool isDrawable(char c) {
    return c >= ' ' && c <= '~';
}

// Font pixels from one glyph's origin to the next; c must be drawable.
int advance(char c) {
    char glyph[2] = {c, '\0'};
    return stb_easy_font_width(glyph);
}

void fillBlock(LdrImage& image, int x0, int y0, int x1, int y1, Rgb8 colour) {
    for (int y = std::max(y0, 0); y < std::min(y1, image.height); ++y) {
        for (int x = std::max(x0, 0); x < std::min(x1, image.width); ++x) {
            uint8_t* pixel = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
            pixel[0] = colour.r;
            pixel[1] = colour.g;
            pixel[2] = colour.b;
            pixel[3] = 255;
        }
    }
}

}  // namespace

int captionHeight(int scale) {
    return (kGlyphHeight + 2 * kCaptionPadding) * scale;
}

int textWidth(std::string_view text, int scale) {
    int width = 0;
    for (const char c : drawableText(text)) {
        width += advance(c);
    }
    return width * scale;
}

std::string drawableText(std::string_view text) {
    std::string out;
    for (const char c : text) {
        const auto byte = uint8_t(c);
        if (isDrawable(c)) {
            out.push_back(c);
        } else if (c == '\t' || c == '\n' || c == '\r') {
            out.push_back(' ');
        } else if (byte < 0x80 || byte >= 0xC0) {   // a control or the lead byte of UTF-8
            out.push_back('?');
        }
    }
    return out;
}

std::string fitText(std::string_view text, int maxWidth, int scale) {
    const std::string drawable = drawableText(text);
    if (textWidth(drawable, scale) <= maxWidth) {
        return drawable;
    }
    const std::string ellipsis = "...";
    const int room = maxWidth - textWidth(ellipsis, scale);
    if (room < 0) {
        std::string dots;
        while (dots.size() < ellipsis.size() && textWidth(dots + '.', scale) <= maxWidth) {
            dots.push_back('.');
        }
        return dots;
    }
    size_t kept = 0;
    for (int width = 0; kept < drawable.size(); ++kept) {
        width += advance(drawable[kept]) * scale;
        if (width > room) {
            break;
        }
    }
    std::string cut = drawable.substr(0, kept);
    cut.erase(cut.find_last_not_of(' ') + 1);   // "gold ..." reads worse than "gold..."
    return cut + ellipsis;
}

void drawText(LdrImage& image, int x, int y, std::string_view text, int scale, Rgb8 colour) {
    int pen = x;
    for (char c : drawableText(text)) {
        if (pen >= image.width) {
            break;
        }
        char glyph[2] = {c, '\0'};
        float vertices[kMaxQuadsPerGlyph * kFloatsPerQuad];
        const int quads = stb_easy_font_print(0.0f, 0.0f, glyph, nullptr, vertices, sizeof vertices);
        for (int q = 0; q < quads; ++q) {
            // Vertices 0 and 2 of a quad are opposite corners, on whole font pixels.
            const float* first = &vertices[q * kFloatsPerQuad];
            const float* third = first + kFloatsPerQuad / 2;
            fillBlock(image, pen + int(first[0]) * scale, y + int(first[1]) * scale,
                      pen + int(third[0]) * scale, y + int(third[1]) * scale, colour);
        }
        pen += advance(c) * scale;
    }
}

}  // namespace patina
