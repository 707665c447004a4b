#include "views/screenshot_comparison.h"

#include "picture/png_text.h"
#include "io/json_reader.h"
#include "files/regular_file.h"
#include "io/scene_file.h"

namespace patina::editor {

namespace {
constexpr const char* kFormat = "patina-comparison";
constexpr int kVersion = 1;

const char* viewName(CompareView view) {
    return view == CompareView::SideBySide ? "side-by-side" : "split";
}
}  // namespace

std::string comparisonLabel(char side, const Material& material) {
    // Appended, not `string + (cond ? "" : ": " + name)`: GCC 12 warns falsely (-Wrestrict) on that.
    std::string label(1, side);
    if (!material.name.empty()) {
        label += ": " + material.name;
    }
    return label;
}

std::string comparisonText(const Interaction& interaction) {
    if (!interaction.compareA || interaction.compareView == CompareView::Single) {
        return "";
    }
    const Json json{{"format", kFormat},
                    {"version", kVersion},
                    {"view", viewName(interaction.compareView)},
                    {"split", interaction.splitPosition},
                    {"part", interaction.selectedModelMaterial},
                    {"a", materialToJson(*interaction.compareA)}};
    return json.dump();
}

std::optional<ScreenshotComparison> comparisonFromPng(const std::filesystem::path& png) {
    const RegularFile file(png, 0, png.string());
    file.requireAtMost(kMaxPngBytes, "PNGs with a scene");
    const std::map<std::string, std::string> entries = readPngText(file.readAll());
    const auto found = entries.find(kComparisonTextKeyword);
    if (found == entries.end()) {
        return std::nullopt;
    }
    const std::string where = png.string() + " (" + kComparisonTextKeyword + ")";
    const Json json = parseJsonText(found->second, where);
    JsonObjectReader reader(json, "", where);
    reader.checkFormatAndVersion(kFormat, kVersion);
    ScreenshotComparison comparison;
    const std::string view = reader.string("view", "split");
    if (view != "split" && view != "side-by-side") {
        reader.fail("view", "expected \"split\" or \"side-by-side\"");
    }
    comparison.view = view == "split" ? CompareView::Split : CompareView::SideBySide;
    comparison.split = reader.number("split", 0.5f, {0.0, 1.0});
    comparison.part = reader.integer("part", 0, {0.0, 1e9});
    std::vector<std::string> warnings;   // A's unknown keys: the scene's own notes say enough
    comparison.a = materialFromJson(reader.required("a"), reader.pointerOf("a"), where, false, warnings);
    return comparison;
}

}  // namespace patina::editor
