#include "image/text.h"

#include <vector>

#include <cairo-ft.h>
#include <fontconfig/fontconfig.h>

namespace patina {

namespace {

constexpr char kReplacement[] = "\xEF\xBF\xBD";   // U+FFFD

// A font fontconfig offers for DejaVu Sans, with the characters it has.
struct Font {
    FcCharSet* characters = nullptr;
    cairo_font_face_t* face = nullptr;
};

// DejaVu Sans first, then the fonts that add characters to it, in fontconfig's order. Made
// once and kept for the process: faces are shared between threads (Cairo counts references
// under a lock).
const std::vector<Font>& fonts() {
    static const std::vector<Font> list = [] {
        std::vector<Font> found;
        FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>("DejaVu Sans"));
        FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
        FcDefaultSubstitute(pattern);
        FcResult result = FcResultNoMatch;
        // Trimmed: a font that adds no character to those before it is left out.
        if (FcFontSet* set = FcFontSort(nullptr, pattern, FcTrue, nullptr, &result)) {
            for (int i = 0; i < set->nfont; ++i) {
                FcPattern* font = FcFontRenderPrepare(nullptr, pattern, set->fonts[i]);
                FcCharSet* characters = nullptr;
                if (FcPatternGetCharSet(font, FC_CHARSET, 0, &characters) == FcResultMatch) {
                    found.push_back({FcCharSetCopy(characters), cairo_ft_font_face_create_for_pattern(font)});
                }
                FcPatternDestroy(font);
            }
            FcFontSetDestroy(set);
        }
        FcPatternDestroy(pattern);
        if (found.empty()) {   // no fontconfig fonts at all: Cairo's own choice
            found.push_back({nullptr, cairo_toy_font_face_create("DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                                                                 CAIRO_FONT_WEIGHT_NORMAL)});
        }
        return found;
    }();
    return list;
}

// The font to draw a character with: the first that has it, DejaVu's missing glyph if none.
cairo_font_face_t* faceFor(char32_t character) {
    for (const Font& font : fonts()) {
        if (font.characters && FcCharSetHasChar(font.characters, character)) {
            return font.face;
        }
    }
    return fonts().front().face;
}

char32_t decode(std::string_view text, size_t at, size_t length) {
    if (length == 1) {
        return char32_t(uint8_t(text[at]));
    }
    char32_t value = uint8_t(text[at]) & (0x7F >> length);
    for (size_t i = 1; i < length; ++i) {
        value = (value << 6) | (uint8_t(text[at + i]) & 0x3F);
    }
    return value;
}

// Hinted metrics would make an advance depend on the surface; SVG, PDF and PNG charts share
// one layout, so advances are the font's own everywhere.
void setFont(cairo_t* cr, cairo_font_face_t* face, double pixels) {
    cairo_font_options_t* options = cairo_font_options_create();
    cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
    cairo_set_font_options(cr, options);
    cairo_font_options_destroy(options);
    cairo_set_font_face(cr, face);
    cairo_set_font_size(cr, pixels);
}

// Calls draw(run) for each stretch of oneLineText(text) that one font draws, with that font set.
template <typename Draw>
void forEachRun(cairo_t* cr, std::string_view text, double pixels, Draw draw) {
    const std::string line = oneLineText(text);
    size_t start = 0;
    cairo_font_face_t* face = nullptr;
    for (size_t at = 0; at <= line.size();) {
        const size_t length = at < line.size() ? characterLength(line, at) : 0;
        cairo_font_face_t* next = at < line.size() ? faceFor(decode(line, at, length)) : nullptr;
        if (next != face) {
            if (face) {
                setFont(cr, face, pixels);
                draw(line.substr(start, at - start));
            }
            face = next;
            start = at;
        }
        if (at == line.size()) {
            break;
        }
        at += length;
    }
}

// A context for measuring, on a surface no one sees.
struct Measure {
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
    cairo_t* cr = cairo_create(surface);
    ~Measure() {
        cairo_destroy(cr);
        cairo_surface_destroy(surface);
    }
};

}  // namespace

size_t characterLength(std::string_view text, size_t at) {
    const auto lead = uint8_t(text[at]);
    const size_t length = lead < 0x80 ? 1 : lead >= 0xF0 && lead < 0xF5 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
    if (length == 0 || at + length > text.size()) {
        return 1;
    }
    for (size_t i = 1; i < length; ++i) {
        if ((uint8_t(text[at + i]) & 0xC0) != 0x80) {
            return 1;
        }
    }
    // Overlong forms, surrogates and values past U+10FFFF are not characters.
    const char32_t value = decode(text, at, length);
    const bool valid = (length < 3 || value >= 0x800) && (length < 4 || (value >= 0x10000 && value <= 0x10FFFF)) &&
                       !(value >= 0xD800 && value <= 0xDFFF);
    return valid ? length : 1;
}

std::string oneLineText(std::string_view text) {
    std::string out;
    for (size_t at = 0; at < text.size();) {
        const size_t length = characterLength(text, at);
        const auto byte = uint8_t(text[at]);
        if (byte == '\t' || byte == '\n' || byte == '\r') {
            out.push_back(' ');
        } else if (byte >= 0x80 && length == 1) {
            out += kReplacement;
        } else if (byte >= 0x20 && byte != 0x7F) {
            out.append(text.substr(at, length));
        }
        at += length;
    }
    return out;
}

FontLine fontLine(double pixels) {
    const Measure measure;
    setFont(measure.cr, fonts().front().face, pixels);
    cairo_font_extents_t extents;
    cairo_font_extents(measure.cr, &extents);
    return {extents.ascent, extents.descent};
}

double textAdvance(std::string_view text, double pixels) {
    const Measure measure;
    double advance = 0.0;
    forEachRun(measure.cr, text, pixels, [&](const std::string& run) {
        cairo_text_extents_t extents;
        cairo_text_extents(measure.cr, run.c_str(), &extents);
        advance += extents.x_advance;
    });
    return advance;
}

void showText(cairo_t* cr, std::string_view text, double pixels) {
    forEachRun(cr, text, pixels, [&](const std::string& run) { cairo_show_text(cr, run.c_str()); });
}

}  // namespace patina
