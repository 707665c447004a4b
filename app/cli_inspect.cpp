// `patina inspect`: one pixel's whole story (reference/pixel_story.h) as JSON on stdout.
#include <iostream>
#include <memory>

#include "assets/asset_cache.h"
#include "cli.h"
#include "inputs.h"
#include "reference/pixel_story.h"
#include "scene/json_value.h"

namespace patina::cli {

namespace {
template <typename Vector>
Json array(const Vector& v) {
    Json values = Json::array();
    for (int i = 0; i < Vector::length(); ++i) {
        values.push_back(v[i]);
    }
    return values;
}

Json shareJson(const LightShare& share) {
    return {{"name", share.name}, {"type", share.type}, {"diffuse", array(share.diffuse)},
            {"specular", array(share.specular)}};
}

Json storyJson(const PixelStory& s) {
    const shader::ChannelInputs& c = s.inputs;
    Json lights = Json::array();
    for (const LightShare& share : s.lights) {
        lights.push_back(shareJson(share));
    }
    return {{"surface", true},
            {"item", s.item},
            {"material", s.material},
            {"model", s.model},
            {"position", array(s.position)},
            {"geometryNormal", array(c.geometryNormal)},
            {"normal", array(c.shadingNormal)},
            {"view", array(s.view)},
            {"uv0", array(c.uv0)},
            {"uv1", array(c.uv1)},
            {"tangent", array(c.tangent)},
            {"baseColor", array(c.baseColor)},
            {"alpha", c.alpha},
            {"roughness", c.roughness},
            {"metallic", c.metallic},
            {"specular", c.specular},
            {"f0", array(c.f0)},
            {"diffuseColor", array(c.diffuseColor)},
            {"occlusion", c.occlusion},
            {"emission", array(c.emission)},
            {"NoV", c.NoV},
            {"keyLight", s.keyLight},
            {"D", c.D},
            {"G", c.G},
            {"F", array(c.F)},
            {"lights", lights},
            {"environment", s.environment ? shareJson(*s.environment) : Json(nullptr)},
            {"clearcoat", array(c.clearcoat)},
            {"sheen", array(c.sheen)},
            {"transmission", array(c.transmission)},
            {"anisotropy", s.anisotropy ? Json{{"direction", array(s.anisotropy->direction)},
                                               {"strength", s.anisotropy->strength},
                                               {"alphaT", s.anisotropy->alphaT},
                                               {"alphaB", s.anisotropy->alphaB}}
                                        : Json(nullptr)},
            {"radiance", array(c.radiance)},
            {"display", {s.display[0], s.display[1], s.display[2]}}};
}
}  // namespace

Command addInspectCommand(CLI::App& app) {
    struct Options {
        SceneInputs inputs;
        int x = 0, y = 0, width = 800, height = 800;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "inspect", "Print one pixel's inputs and lighting as JSON (the CPU twin of the shaders; docs/INSPECTOR.md)");
    options->inputs.addOptions(*command, true, true);
    options->inputs.view.addOptions(*command);
    command->add_option("--x", options->x, "Pixel column, 0 at the left")->required()->check(CLI::NonNegativeNumber);
    command->add_option("--y", options->y, "Pixel row, 0 at the top")->required()->check(CLI::NonNegativeNumber);
    command->add_option("--width", options->width, "Image width, as render takes it")->check(CLI::Range(1, 16384));
    command->add_option("--height", options->height, "Image height")->check(CLI::Range(1, 16384));
    // A pixel outside the image is a usage mistake (exit 2), said before anything is read.
    command->callback([options] {
        if (options->x >= options->width || options->y >= options->height) {
            throw CLI::ValidationError("--x/--y", "pixel (" + std::to_string(options->x) + ", " +
                                                      std::to_string(options->y) + ") is outside the " +
                                                      std::to_string(options->width) + " x " +
                                                      std::to_string(options->height) + " image");
        }
    });
    return [options] {
        const LoadedScene loaded(options->inputs);
        const PreparedScene& prepared = loaded.prepared;
        const PixelSurfaces surfaces = rasterizeSurfaces(prepared, options->width, options->height);
        const std::optional<PixelStory> story = pixelStory(prepared, surfaces, options->x, options->y);
        Json report{{"x", options->x}, {"y", options->y}, {"width", options->width}, {"height", options->height}};
        const Json details = story ? storyJson(*story) : Json{{"surface", false}};
        report.insert(details.begin(), details.end());
        std::cout << report.dump(2) << "\n";
    };
}

}  // namespace patina::cli
