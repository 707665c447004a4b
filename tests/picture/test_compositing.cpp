// Captions (engine/image/caption.h) and the images compare and sheet write (engine/image/compositing.h).
#include <gtest/gtest.h>

#include "common/luminance.h"
#include "image/caption.h"
#include "picture/compositing.h"
#include "image/text.h"

namespace patina {
namespace {

LdrImage solid(int width, int height, Rgb8 colour) {
    LdrImage image{width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 4, 255)};
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i] = colour.r;
        image.rgba[i + 1] = colour.g;
        image.rgba[i + 2] = colour.b;
    }
    return image;
}

Rgb8 pixel(const LdrImage& image, int x, int y) {
    const uint8_t* p = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
    return {p[0], p[1], p[2]};
}

bool operator==(Rgb8 a, Rgb8 b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
}

// Pixels of `colour` in [x0, x1) x [y0, y1).
int countColour(const LdrImage& image, Rgb8 colour, int x0, int y0, int x1, int y1) {
    int count = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            count += pixel(image, x, y) == colour;
        }
    }
    return count;
}

// Pixels not of `background` in [x0, x1) x [y0, y1): text's ink, anti-aliased edges included.
int countInk(const LdrImage& image, Rgb8 background, int x0, int y0, int x1, int y1) {
    return (x1 - x0) * (y1 - y0) - countColour(image, background, x0, y0, x1, y1);
}

constexpr Rgb8 kBlack{0, 0, 0};
constexpr Rgb8 kInk{200, 100, 50};

// A thumbnail is the box mean of the pixels under each of its pixels, with the aspect kept.
TEST(ShrunkToFit, AveragesEachBoxAndKeepsTheAspect) {
    // 4 x 2: left half values 0 and 100 in alternate rows, right half all 200.
    std::vector<uint8_t> rgba;
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 4; ++x) {
            const uint8_t v = x < 2 ? uint8_t(y == 0 ? 0 : 100) : 200;
            rgba.insert(rgba.end(), {v, v, v, 255});
        }
    }
    const LdrImage half = shrunkToFit(4, 2, rgba, 2);
    ASSERT_EQ(half.width, 2);
    ASSERT_EQ(half.height, 1);
    EXPECT_TRUE(pixel(half, 0, 0) == (Rgb8{50, 50, 50}));
    EXPECT_TRUE(pixel(half, 1, 0) == (Rgb8{200, 200, 200}));
    EXPECT_EQ(half.rgba[3], 255);
    const LdrImage same = shrunkToFit(4, 2, rgba, 16);   // fits: copied
    EXPECT_EQ(same.width, 4);
    EXPECT_EQ(same.rgba, rgba);
    const LdrImage tall = shrunkToFit(3, 300, std::vector<uint8_t>(3 * 300 * 4, 9), 100);
    EXPECT_EQ(tall.width, 1);
    EXPECT_EQ(tall.height, 100);
    EXPECT_TRUE(shrunkToFit(4, 2, {1, 2, 3}, 2).rgba.empty());   // too few bytes: nothing
}

TEST(Caption, DrawsOnlyInsideTheMeasuredBox) {
    const std::string text = "Hg|y 0.5";
    for (const int scale : {1, 3}) {
        LdrImage image = solid(200, 80, kBlack);
        drawText(image, 5, 7, text, scale, kInk);
        // A pixel of room for anti-aliasing at the edges of the box.
        const int right = 5 + textWidth(text, scale) + 1, bottom = 7 + textHeight(scale) + 1;
        ASSERT_LE(right, image.width);
        const int inside = countInk(image, kBlack, 4, 6, right, bottom);
        EXPECT_GT(inside, 20 * scale * scale);
        EXPECT_EQ(countInk(image, kBlack, 0, 0, image.width, image.height), inside);
        EXPECT_GT(countColour(image, kInk, 0, 0, image.width, image.height), 0) << "stems in the ink itself";
    }
}

TEST(Caption, GrowsWithTheScale) {
    EXPECT_NEAR(textWidth("Ab3 caption", 2), 2 * textWidth("Ab3 caption", 1), 2);
    EXPECT_NEAR(textHeight(2), 2 * textHeight(1), 2);
    EXPECT_EQ(captionHeight(2), textHeight(2) + 4 * kCaptionPadding);
    EXPECT_GT(captionHeight(1), textHeight(1));
}

TEST(Caption, ClipsAtTheImageEdges) {
    LdrImage whole = solid(30, 20, kBlack), shifted = solid(30, 20, kBlack);
    drawText(whole, 0, 0, "W#", 1, kInk);
    drawText(shifted, -3, -2, "W#", 1, kInk);
    for (int y = 0; y + 2 < 20; ++y) {
        for (int x = 0; x + 3 < 30; ++x) {
            ASSERT_TRUE(pixel(shifted, x, y) == pixel(whole, x + 3, y + 2)) << x << "," << y;
        }
    }
    drawText(shifted, 28, 15, "far past the right and bottom edges", 4, kInk);
    drawText(shifted, -100000, -100000, "nowhere", 1, kInk);
    EXPECT_EQ(shifted.rgba.size(), 30u * 20u * 4u);
}

// A name in any script shows: not as '?', the old font's stand-in for every non-ASCII character.
TEST(Caption, DrawsUtf8AsItsOwnCharacters) {
    const std::string text = "Kupfer \xE2\x80\x93 Messing \xE2\x9C\x93 \xE9\x8A\x85";   // "Kupfer – Messing ✓ 銅"
    LdrImage utf8 = solid(300, 30, kBlack), asked = solid(300, 30, kBlack);
    drawText(utf8, 2, 2, text, 1, kInk);
    drawText(asked, 2, 2, "Kupfer ? Messing ? ?", 1, kInk);
    EXPECT_NE(utf8.rgba, asked.rgba);
    // Each of the three draws ink of its own, unlike '?' and unlike an empty box (DejaVu lacks 銅).
    for (const char* character : {"\xE2\x80\x93", "\xE2\x9C\x93", "\xE9\x8A\x85"}) {
        LdrImage one = solid(40, 30, kBlack), question = solid(40, 30, kBlack);
        drawText(one, 2, 2, character, 1, kInk);
        drawText(question, 2, 2, "?", 1, kInk);
        EXPECT_GT(countInk(one, kBlack, 0, 0, 40, 30), 0) << character;
        EXPECT_NE(one.rgba, question.rgba) << character;
    }
    EXPECT_GT(textWidth("\xE9\x8A\x85", 1), textWidth("?", 1)) << "a CJK character is wide: a font that has it";
}

TEST(Caption, KeepsOneLineOfValidUtf8) {
    EXPECT_EQ(oneLineText("caf\xc3\xa9\tok\x01~ \xe2\x9c\x93!"), "caf\xc3\xa9 ok~ \xe2\x9c\x93!");
    EXPECT_EQ(oneLineText("a\xff" "b\xe2\x9c"), "a\xEF\xBF\xBD" "b\xEF\xBF\xBD\xEF\xBF\xBD");   // U+FFFD
    EXPECT_EQ(oneLineText("\xc0\xaf"), "\xEF\xBF\xBD\xEF\xBF\xBD") << "an overlong '/' is no character";
    EXPECT_EQ(textWidth("", 3), 0);
}

TEST(Caption, CutsLongTextWithAnEllipsis) {
    const std::string ellipsis = "\xE2\x80\xA6";
    const std::string name = "a very long material name that goes on";
    EXPECT_EQ(fitText(name, textWidth(name, 1), 1), name);
    for (const int width : {30, 61, 100, 150}) {
        const std::string cut = fitText(name, width, 1);
        EXPECT_LE(textWidth(cut, 1), width) << cut;
        ASSERT_GE(cut.size(), 4u) << cut;
        EXPECT_EQ(cut.substr(cut.size() - 3), ellipsis);
        EXPECT_EQ(name.rfind(cut.substr(0, cut.size() - 3), 0), 0u) << cut;
        EXPECT_NE(cut[cut.size() - 4], ' ') << cut;
    }
    EXPECT_EQ(fitText(name, textWidth(ellipsis, 2), 2), ellipsis);
    EXPECT_EQ(fitText(name, 0, 1), "");
    EXPECT_EQ(fitText(name, -5, 1), "");
}

// Every cut of a name of two-, three- and four-byte characters ends between characters.
TEST(Caption, CutsBetweenUtf8CharactersNeverInside) {
    const std::string name = "\xC3\xA9t\xC3\xA9 \xE9\x8A\x85\xE9\x8A\x85 Messing \xF0\x9F\x99\x82 \xE2\x9C\x93\xE2\x9C\x93 Kupfer";
    const std::string ellipsis = "\xE2\x80\xA6";
    for (int width = 0; width <= textWidth(name, 1); ++width) {
        const std::string cut = fitText(name, width, 1);
        EXPECT_LE(textWidth(cut, 1), width) << cut;
        if (cut.empty() || cut == name) {
            continue;
        }
        ASSERT_EQ(cut.substr(cut.size() - 3), ellipsis) << width;
        const std::string kept = cut.substr(0, cut.size() - 3);
        ASSERT_EQ(name.rfind(kept, 0), 0u) << width;
        EXPECT_EQ(oneLineText(kept), kept) << "a character split at " << width << ": " << kept;
        // The next byte of the name starts a character: not a continuation byte (10xxxxxx).
        EXPECT_TRUE(kept.size() == name.size() || (uint8_t(name[kept.size()]) & 0xC0) != 0x80) << width;
    }
}

// One convention for colours: a caption shows the base colour in sRGB, as the editor's field
// does (gold's linear 1.0 0.7099 0.3148 shows as 1.000 0.860 0.597 there), and says so.
TEST(Compositing, ACaptionShowsTheBaseColourInSrgbAndNamesIt) {
    Material gold;
    gold.name = "gold";
    gold.baseColor = {1.0f, 0.7099f, 0.3148f};
    gold.roughness = 0.3f;
    gold.metallic = 1.0f;
    EXPECT_EQ(materialCaption(gold, 1000), "gold  r 0.30 s 0.50 m 1.00  base sRGB 1.00 0.86 0.60");
    Material gltf = gold;   // another model than the seed's is named: A and B may differ in it alone
    gltf.model = BrdfModelId::Gltf;
    EXPECT_EQ(materialCaption(gltf, 1000), "gold  r 0.30 s 0.50 m 1.00  gltf  base sRGB 1.00 0.86 0.60");
    // A part's layers are named, so that A with a coat and B without are not captioned alike.
    Material layered = gltf;
    layered.clearcoat = 1.0f;
    layered.sheenColor = {0.2f, 0.5f, 0.1f};
    layered.transmission = 0.75f;
    EXPECT_EQ(materialCaption(layered, 2000),
              "gold  r 0.30 s 0.50 m 1.00  gltf  coat 1.00  sheen 0.50  transmission 0.75  base sRGB 1.00 0.86 0.60");
    // And the stretch, the specular's tint and weight, and a thin film.
    Material more = gltf;
    more.anisotropyStrength = 0.5f;
    more.specularTint = {2.0f, 1.0f, 0.5f};
    more.specularWeight = 0.8f;
    more.iridescence = 1.0f;
    EXPECT_EQ(materialCaption(more, 3000), "gold  r 0.30 s 0.50 m 1.00  gltf  anisotropy 0.50  tint 2.00 1.00 0.50 w 0.80  "
                                           "film 1.00 400 nm  base sRGB 1.00 0.86 0.60");
}

// A side-by-side half is narrow: the name is what tells A from B, so numbers give way first.
TEST(Compositing, ANarrowCaptionKeepsTheNameBeforeTheNumbers) {
    Material material;
    material.name = "A: terracotta";
    const std::string full = materialCaption(material, 1000);
    EXPECT_EQ(full.rfind("A: terracotta  r 0.40 s 0.50 m 0.00  base sRGB", 0), 0u) << full;
    // The name and the numbers are measured apart, each rounded up to whole pixels.
    const int withoutBase = textWidth("A: terracotta", 1) + textWidth("  r 0.40 s 0.50 m 0.00", 1) + 2 * kCaptionPadding;
    EXPECT_EQ(materialCaption(material, withoutBase), "A: terracotta  r 0.40 s 0.50 m 0.00");
    EXPECT_EQ(materialCaption(material, withoutBase - 30), "A: terracotta");
    material.name = std::string(40, 'W');
    const std::string cut = materialCaption(material, 200);
    EXPECT_EQ(cut.substr(cut.size() - 3), "\xE2\x80\xA6");   // "…"
    EXPECT_LE(textWidth(cut, 1), 200 - 2 * kCaptionPadding);
}

TEST(Compositing, LaysOutCellsWithCaptionStrips) {
    const SheetLayout layout = sheetLayout(50, 40, 3, 2);
    EXPECT_EQ(layout.columns, 2);
    EXPECT_EQ(layout.rows, 2);
    EXPECT_EQ(layout.captionHeight, captionHeight(1));
    EXPECT_EQ(layout.width, 2 * 50 + kCellGap);
    EXPECT_EQ(layout.height, 2 * (40 + captionHeight(1)) + kCellGap);
    EXPECT_EQ(layout.cellX(1), 50 + kCellGap);
    EXPECT_EQ(layout.cellY(2), 40 + captionHeight(1) + kCellGap);
    EXPECT_EQ(sheetLayout(50, 40, 2, 8).columns, 2);   // no empty columns
    EXPECT_EQ(captionScale(799), 1);
    EXPECT_EQ(captionScale(800), 2);
    EXPECT_EQ(captionScale(100000), 4);
    EXPECT_EQ(sheetLayout(800, 800, 1, 1).captionHeight, captionHeight(2));
}

TEST(Compositing, ContactSheetPlacesAndCaptionsEveryCell) {
    const std::vector<LdrImage> cells{solid(50, 40, {255, 0, 0}), solid(50, 40, {0, 255, 0}),
                                      solid(50, 40, {0, 0, 255})};
    const LdrImage sheet = contactSheet(cells, {"red", "", "blue"}, 2);
    const SheetLayout layout = sheetLayout(50, 40, 3, 2);
    ASSERT_EQ(sheet.width, layout.width);
    ASSERT_EQ(sheet.height, layout.height);
    for (int i = 0; i < 3; ++i) {
        const int x = layout.cellX(i), y = layout.cellY(i);
        EXPECT_TRUE(pixel(sheet, x + 25, y + 20) == pixel(cells[size_t(i)], 0, 0)) << i;
        EXPECT_EQ(countColour(sheet, pixel(cells[size_t(i)], 0, 0), x, y, x + 50, y + 40), 50 * 40);
        const int ink = countInk(sheet, kSheetBackground, x, y + 40, x + 50, y + 40 + layout.captionHeight);
        EXPECT_EQ(ink > 0, i != 1) << i;   // the second cell has no name
    }
    EXPECT_TRUE(pixel(sheet, 50, 10) == kSheetBackground);                  // the gap
    EXPECT_TRUE(pixel(sheet, layout.cellX(1) + 25, layout.cellY(3) + 20) == kSheetBackground);
}

TEST(Compositing, LongCaptionsStayInTheirCell) {
    const std::string longName(200, 'W');
    const LdrImage sheet =
        contactSheet({solid(40, 30, kBlack), solid(40, 30, kBlack)}, {longName, longName}, 2);
    const SheetLayout layout = sheetLayout(40, 30, 2, 2);
    EXPECT_GT(countInk(sheet, kSheetBackground, 0, 30, 40, sheet.height), 0);
    EXPECT_EQ(countInk(sheet, kSheetBackground, 40, 0, 40 + kCellGap, sheet.height), 0);
    EXPECT_EQ(countInk(sheet, kSheetBackground, 0, 30, 1, sheet.height), 0);
    EXPECT_EQ(countInk(sheet, kSheetBackground, layout.width - 1, 30, layout.width, sheet.height), 0);
}

TEST(Compositing, CentresSmallerCells) {
    const LdrImage sheet =
        contactSheet({solid(20, 10, {255, 0, 0}), solid(50, 40, {0, 0, 255})}, {"a", "b"}, 2);
    EXPECT_EQ(countColour(sheet, {255, 0, 0}, 15, 15, 35, 25), 20 * 10);
    EXPECT_EQ(countColour(sheet, {255, 0, 0}, 0, 0, sheet.width, sheet.height), 20 * 10);
}

TEST(Compositing, SideBySideIsATwoColumnSheet) {
    const LdrImage a = solid(30, 20, {255, 0, 0}), b = solid(30, 20, {0, 0, 255});
    const LdrImage pair = sideBySide(a, b, "left", "right");
    EXPECT_EQ(pair.width, 2 * 30 + kCellGap);
    EXPECT_EQ(pair.height, 20 + captionHeight(1));
    EXPECT_TRUE(pixel(pair, 15, 10) == pixel(a, 0, 0));
    EXPECT_TRUE(pixel(pair, 30 + kCellGap + 15, 10) == pixel(b, 0, 0));
    EXPECT_EQ(pair.rgba, contactSheet({a, b}, {"left", "right"}, 2).rgba);
}

// Built cell by cell, a sheet's finished rows never change again (the sheet command encodes
// them while the next cells render), they grow a row of cells at a time, and the result is
// the sheet made at once.
TEST(Compositing, SheetBuilderFinishesRowsThatNoLaterCellChanges) {
    std::vector<LdrImage> cells;
    std::vector<std::string> names;
    for (int i = 0; i < 7; ++i) {
        cells.push_back(solid(30, 20, {uint8_t(30 * i), 255, uint8_t(255 - 30 * i)}));
        names.push_back("cell " + std::to_string(i));
    }
    SheetBuilder sheet(30, 20, names, 3);
    const SheetLayout& layout = sheet.layout();
    EXPECT_EQ(sheet.finishedRows(), 0);
    std::vector<std::pair<int, std::vector<uint8_t>>> snapshots;   // finished rows, their bytes
    for (size_t i = 0; i < cells.size(); ++i) {
        sheet.add(cells[i]);
        const int rows = sheet.finishedRows();
        const int expected = i + 1 == cells.size() ? layout.height : layout.cellY(int(i) + 1);
        EXPECT_EQ(rows, expected) << "after cell " << i;
        const auto& bytes = sheet.image().rgba;
        snapshots.emplace_back(rows, std::vector<uint8_t>(bytes.begin(), bytes.begin() + size_t(rows) * layout.width * 4));
    }
    for (const auto& [rows, bytes] : snapshots) {
        EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), sheet.image().rgba.begin())) << rows << " rows";
    }
    EXPECT_EQ(sheet.image().rgba, contactSheet(cells, names, 3).rgba);
    EXPECT_THROW(sheet.add(cells[0]), std::invalid_argument);   // no name left
    SheetBuilder small(30, 20, {"a"}, 1);
    EXPECT_THROW(small.add(solid(31, 20, kBlack)), std::invalid_argument);   // larger than its box
}

TEST(Compositing, RefusesBadArguments) {
    const LdrImage a = solid(4, 4, kBlack);
    EXPECT_THROW(contactSheet({}, {}, 1), std::invalid_argument);
    EXPECT_THROW(contactSheet({a}, {"a", "b"}, 1), std::invalid_argument);
    EXPECT_THROW(contactSheet({a}, {"a"}, 0), std::invalid_argument);
    EXPECT_THROW(contactSheet({a, LdrImage{4, 4, {}}}, {"a", "b"}, 2), std::invalid_argument);
    EXPECT_THROW(sheetLayout(kMaxSheetSide, 10, 2, 2), std::invalid_argument);
    EXPECT_THROW(sheetLayout(10, 2000000000, 2, 1), std::invalid_argument);
    EXPECT_NO_THROW(sheetLayout(kMaxSheetSide, 10, 1, 1));
    EXPECT_THROW(differenceHeatMap(a, solid(4, 5, kBlack)), std::invalid_argument);
    EXPECT_THROW(differenceStats(a, solid(5, 4, kBlack)), std::invalid_argument);
}

TEST(Compositing, HeatMapIsBlackWhereEqualAndShowsTheLargestChannel) {
    const LdrImage a = solid(8, 6, {100, 100, 100});
    LdrImage b = a;
    EXPECT_EQ(countColour(differenceHeatMap(a, b), kBlack, 0, 0, 8, 6), 8 * 6);
    EXPECT_EQ(differenceStats(a, b).max, 0);
    b.rgba[(2 * 8 + 3) * 4 + 0] = 110;   // +10 red, -40 green, +5 blue at (3, 2)
    b.rgba[(2 * 8 + 3) * 4 + 1] = 60;
    b.rgba[(2 * 8 + 3) * 4 + 2] = 105;
    const LdrImage map = differenceHeatMap(a, b);
    EXPECT_TRUE(pixel(map, 3, 2) == heatColour(40));
    EXPECT_EQ(countColour(map, kBlack, 0, 0, 8, 6), 8 * 6 - 1);
    const DifferenceStats stats = differenceStats(a, b);
    EXPECT_EQ(stats.max, 40);
    EXPECT_DOUBLE_EQ(stats.mean, 40.0 / 48.0);
}

TEST(Compositing, HeatRampRisesInLuma) {
    EXPECT_TRUE(heatColour(0) == kBlack);
    EXPECT_TRUE(heatColour(-5) == kBlack);
    EXPECT_TRUE(heatColour(300) == heatColour(255));
    auto luma = [](Rgb8 c) {
        const float rgb[] = {float(c.r), float(c.g), float(c.b)};
        return luminance(rgb);
    };
    for (int d = 1; d <= 255; ++d) {
        EXPECT_GT(luma(heatColour(d)), luma(heatColour(d - 1))) << d;
    }
    EXPECT_GT(luma(heatColour(255)), 240.0f);
}

}  // namespace
}  // namespace patina
