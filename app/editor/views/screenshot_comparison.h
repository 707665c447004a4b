#pragma once
// A screenshot of a comparison carries, beside its scene (image/png_text.h), what it compares:
// material A, the view and the split, so that it reopens as the comparison it shows.
#include <filesystem>
#include <optional>
#include <string>

#include "state/interaction.h"

namespace patina::editor {

inline constexpr const char* kComparisonTextKeyword = "patina-comparison";

struct ScreenshotComparison {
    Material a;
    int part = 0;   // the model's part A was on (Interaction::selectedModelMaterial)
    CompareView view = CompareView::Split;
    float split = 0.5f;
};

// "A: gold", "B: copper": what a comparison calls each side, in the viewport and in a split
// screenshot, so a picture of two says which is which (a side by side one's captions add the
// parameters).
std::string comparisonLabel(char side, const Material& material);

// {"format": "patina-comparison", "version": 1, "view": "split" | "side-by-side", "split",
// "part", "a": a material file's object}; empty when the editor shows no comparison. "part" is
// the shown model's part both sides are drawn on (0 without a model; a screenshot from before it
// was written reads 0).
std::string comparisonText(const Interaction& interaction);
// What a screenshot's comparison text holds; nothing for a screenshot without one. Throws
// InputError naming the file when the text is there but wrong.
std::optional<ScreenshotComparison> comparisonFromPng(const std::filesystem::path& png);

}  // namespace patina::editor
