#pragma once
// One line of text through Cairo, for captions and charts: DejaVu Sans (fonts-dejavu-core) and,
// for a character it lacks, the first font fontconfig sorts after it that has one, so that a
// name in any script shows instead of '?'. No shaping: each character is one glyph.
#include <cstddef>
#include <string>
#include <string_view>

#include <cairo.h>

namespace patina {

// The text as one line of valid UTF-8: tabs and line breaks become spaces, other control
// characters are dropped, a byte that starts no valid character becomes U+FFFD.
std::string oneLineText(std::string_view text);

// Bytes of the UTF-8 character that starts at text[at] (1 for a byte that starts none).
size_t characterLength(std::string_view text, size_t at);

// The font's ascent and descent at `pixels` per em, the same for every text.
struct FontLine {
    double ascent = 0.0, descent = 0.0;
};
FontLine fontLine(double pixels);

// How far oneLineText(text) advances at `pixels` per em.
double textAdvance(std::string_view text, double pixels);

// Draws oneLineText(text) in cr's source with its baseline from cr's current point, which
// moves to its end.
void showText(cairo_t* cr, std::string_view text, double pixels);

}  // namespace patina
