#pragma once
// Captions on images (contact sheets, comparisons, the editor's screenshots, heat maps): one
// line of UTF-8 drawn through Cairo in the charts' font (image/text.h), anti-aliased.
#include <cstdint>
#include <string>
#include <string_view>

#include "image/image.h"

namespace patina {

struct Rgb8 {
    uint8_t r = 0, g = 0, b = 0;
};

inline constexpr double kCaptionPixels = 12.0;   // the font's size at scale 1, pixels per em
inline constexpr int kCaptionPadding = 4;        // pixels above and below the text, at scale 1

// Pixels from a caption's top to the bottom of its lowest glyph: the font's ascent and descent.
int textHeight(int scale);
// Height of a strip holding one line of text: textHeight(scale) + 2 kCaptionPadding * scale.
int captionHeight(int scale);
// Width in pixels of oneLineText(text), rounded up.
int textWidth(std::string_view text, int scale);

// oneLineText(text), cut to at most maxWidth pixels, with "…" at the end when too long; cut
// between characters, never inside one. "" when not even "…" fits.
std::string fitText(std::string_view text, int maxWidth, int scale);

// Draws oneLineText(text) with its top left corner at (x, y), clipped to the image.
void drawText(LdrImage& image, int x, int y, std::string_view text, int scale, Rgb8 colour);

}  // namespace patina
