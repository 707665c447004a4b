#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "image/image.h"

namespace patina {

struct Rgb8 {
    uint8_t r = 0, g = 0, b = 0;
};

// Captions are drawn on the CPU with stb_easy_font: one line of printable ASCII, each font
// pixel a scale x scale block. Glyphs are at most kGlyphHeight font pixels tall.
inline constexpr int kGlyphHeight = 9;
inline constexpr int kCaptionPadding = 4;   // font pixels above and below the text

// Height of a strip holding one line of text: (kGlyphHeight + 2 kCaptionPadding) * scale.
int captionHeight(int scale);
// Width in pixels of drawableText(text).
int textWidth(std::string_view text, int scale);

// The text with what the font cannot draw replaced: one '?' per UTF-8 character outside
// ' '..'~', a space for tabs and line breaks.
std::string drawableText(std::string_view text);
// drawableText(text), cut to at most maxWidth pixels with "..." at the end when too long.
std::string fitText(std::string_view text, int maxWidth, int scale);

// Draws drawableText(text) with its top left corner at (x, y), clipped to the image.
void drawText(LdrImage& image, int x, int y, std::string_view text, int scale, Rgb8 colour);

}  // namespace patina
