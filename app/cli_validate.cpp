#include <cstdio>
#include <iostream>
#include <memory>

#include "assets/asset_cache.h"
#include "cli.h"
#include "files/input_error.h"
#include "inputs.h"
#include "io/file_kinds.h"
#include "io/scene_file.h"
#include "model/pbr_validation.h"

namespace patina::cli {

namespace {
// "dielectric, albedo 12 sRGB, below 30 (30-240)": what a base colour's check found.
std::string describe(const PbrCheck& check, const PbrRanges& ranges) {
    char text[200];
    if (check.metal) {
        std::snprintf(text, sizeof text, "metal, reflectance %d sRGB%s (%d-255)", check.value,
                      check.verdict == PbrVerdict::MetalTooDark ? ", below the darkest measured metal" : "",
                      ranges.metalMin);
    } else {
        // A transmitting dielectric's bright end is its reflected share's (pbr_validation.h).
        char reflected[96] = "";
        if (check.reflected != check.value) {
            std::snprintf(reflected, sizeof reflected, ", %d sRGB of it reflected diffusely (the rest passes through)",
                          check.reflected);
        }
        std::snprintf(text, sizeof text, "dielectric, albedo %d sRGB%s%s (%d-%d)", check.value, reflected,
                      check.verdict == PbrVerdict::DielectricTooDark     ? ", darker than any real dielectric"
                      : check.verdict == PbrVerdict::DielectricTooBright ? ", brighter than any real dielectric"
                                                                         : "",
                      ranges.dielectricMin, ranges.dielectricMax);
    }
    return text;
}

// One line for a material judged by one colour; whether it is in range.
bool reportColour(const std::string& where, glm::vec3 baseColor, float metallic, float transmission,
                  const PbrRanges& ranges) {
    const PbrCheck check = checkBaseColor(baseColor, metallic, transmission, ranges);
    std::cout << where << ": " << (check.verdict == PbrVerdict::Ok ? "ok: " : "out of range: ")
              << describe(check, ranges) << "\n";
    return check.verdict == PbrVerdict::Ok;
}

std::string percent(size_t part, size_t whole) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f%%", 100.0 * double(part) / double(whole));
    return text;
}

// One line for a glTF material: its base colour map's texels, or its factors where it has none.
// Whether it is in range.
bool reportModelMaterial(const std::string& where, const Model& model, const ModelMaterial& material,
                         const PbrRanges& ranges) {
    const PbrTally tally = checkBaseColorTexels(model, material, ranges);
    if (tally.texels == 0) {
        return reportColour(where, material.factors.baseColor, material.factors.metallic,
                            material.factors.transmission, ranges);
    }
    std::cout << where << ": " << (tally.flagged() == 0 ? "ok: " : "out of range: ") << "base colour map, "
              << percent(tally.flagged(), tally.texels) << " of " << tally.texels << " texels flagged (dielectric below "
              << ranges.dielectricMin << " sRGB " << percent(tally.dielectricDark, tally.texels) << ", above "
              << ranges.dielectricMax << " " << percent(tally.dielectricBright, tally.texels) << "; metal below "
              << ranges.metalMin << " " << percent(tally.metalDark, tally.texels) << ")\n";
    return tally.flagged() == 0;
}

// Every material of `path` checked, a line each; how many were out of range and in all.
std::pair<int, int> validateFile(const std::string& path, const PbrRanges& ranges, AssetCache& assets) {
    if (gltfExtension(path).empty()) {
        std::vector<std::string> warnings;
        const Material material = loadMaterialFile(path, warnings);
        return {reportColour(path, material.baseColor, material.metallic, material.transmission, ranges) ? 0 : 1, 1};
    }
    const std::shared_ptr<const LoadedModel> file = assets.model(path);
    const Model* model = &file->model;
    printWarnings(model->notes);   // what the picture lacks of the file, as render and the editor say
    int bad = 0;
    for (size_t i = 0; i < model->materials.size(); ++i) {
        const std::string where = path + " material " + std::to_string(i) + " \"" + model->materials[i].name + "\"";
        bad += reportModelMaterial(where, *model, model->materials[i], ranges) ? 0 : 1;
    }
    return {bad, int(model->materials.size())};
}
}  // namespace

Command addValidateCommand(CLI::App& app) {
    struct Options {
        std::vector<std::string> files;
        bool strict = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "validate", "Check materials' base colours against the ranges real materials have (Substance's PBR Validate), "
                    "a line each; exit 1 when any is out of range");
    command->add_option("materials", options->files, "Material JSON files and glTF models (.gltf, .glb)")->required();
    command->add_flag("--strict", options->strict,
                      "Strict ranges: dielectric albedo 50-240 sRGB, metal reflectance 180-255 (default 30-240, 155-255)");
    return [options] {
        const PbrRanges ranges = options->strict ? PbrRanges::strict() : PbrRanges{};
        AssetCache assets;
        int bad = 0, total = 0, unreadable = 0;
        for (const std::string& file : options->files) {
            try {
                const auto [out, all] = validateFile(file, ranges, assets);
                bad += out;
                total += all;
            } catch (const std::exception& error) {   // the others are still checked
                std::cout.flush();   // the lines so far before this one, where both go to one place
                std::cerr << "error: " << error.what() << "\n";
                ++unreadable;
            }
        }
        std::cout.flush();   // every line before the summary on stderr
        if (unreadable > 0) {
            throw InputError(std::to_string(unreadable) + " of " + std::to_string(options->files.size()) +
                             " files could not be read");
        }
        if (bad > 0) {
            throw std::runtime_error(std::to_string(bad) + " of " + std::to_string(total) +
                                     " materials out of range");
        }
    };
}

}  // namespace patina::cli
