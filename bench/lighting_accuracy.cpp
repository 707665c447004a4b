#include "bench/lighting_accuracy.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include <epoxy/gl.h>
#include <sstream>

#include "bench/timing.h"
#include "common/luminance.h"
#include "files/input_error.h"
#include "gl/renderer.h"
#include "picture/compositing.h"
#include "picture/display_image.h"
#include "reference/pixel_surfaces.h"
#include "reference/reference_render.h"

namespace patina {

namespace {
// The methods that render differently, with the shading that renders each.
std::optional<EnvironmentShading> shadingOf(const std::string& method) {
    if (method == "split sum") {
        return EnvironmentShading{EnvironmentMethod::SplitSum, 1};
    }
    if (method == "split sum, dominant direction") {
        return EnvironmentShading{EnvironmentMethod::Dominant, 1};
    }
    if (method.starts_with("stochastic, ")) {
        return EnvironmentShading{EnvironmentMethod::Stochastic, std::stoi(method.substr(12))};
    }
    return std::nullopt;
}

// lighting_cost.csv's last row, the baseline without an environment.
constexpr const char* kDirectionalRow = "one directional light (no environment)";

std::vector<SplitSumErrorRow> parseSplitSumRows(const CsvFile& csv) {
    std::vector<SplitSumErrorRow> rows;
    for (const CsvLine& line : csvBody(csv, "environment,method,NoV,roughness,f0,relative_error,truth_relative_se")) {
        expectCells(line, 7, csv.source);
        auto number = [&](size_t column) { return csvNumber(line, column, csv.source); };
        rows.push_back({line.cells[0], line.cells[1], float(number(2)), float(number(3)), float(number(4)), number(5),
                        number(6)});
    }
    return rows;
}

// The sphere of sphereUnder's scenes, which are prepared with the environment already made.
std::shared_ptr<const Mesh> sphereMesh() {
    return builtinMesh(MeshKind::Sphere);
}

Scene sphereUnder(const NamedEnvironment& named, float roughness, float metallic) {
    Scene scene;
    scene.material.name = "grid";
    scene.material.baseColor = metallic > 0.5f ? glm::vec3(1.0f, 0.78f, 0.34f) : glm::vec3(0.6f, 0.6f, 0.6f);
    scene.material.roughness = roughness;
    scene.material.metallic = metallic;
    Light light;
    light.type = LightType::Environment;
    light.name = named.name;
    light.source = named.environment->source;
    scene.lights = {light};
    scene.display.backgroundFromEnvironment = true;
    scene.display.backgroundBlur = 0.5f;
    scene.display.tonemap = Tonemap::PbrNeutral;
    return scene;
}

// Cells blitted into one image, `columns` across, no gaps (a grid reads as one picture).
LdrImage tile(const std::vector<LdrImage>& cells, int columns) {
    const int w = cells.front().width, h = cells.front().height;
    const int rows = int((cells.size() + size_t(columns) - 1) / size_t(columns));
    LdrImage image{w * columns, h * rows, std::vector<uint8_t>(size_t(w * columns) * size_t(h * rows) * 4, 255)};
    for (size_t i = 0; i < cells.size(); ++i) {
        const int x0 = int(i) % columns * w, y0 = int(i) / columns * h;
        for (int y = 0; y < h; ++y) {
            std::copy_n(&cells[i].rgba[size_t(y) * size_t(w) * 4], size_t(w) * 4,
                        &image.rgba[(size_t(y0 + y) * size_t(image.width) + size_t(x0)) * 4]);
        }
    }
    return image;
}
}  // namespace

LightingAccuracyResult runLightingAccuracy(const std::vector<NamedEnvironment>& environments, bool quick) {
    LightingAccuracyResult result;
    SplitSumAccuracyOptions options;
    options.quick = quick;
    result.accuracy = measureSplitSum(environments, options);

    // Frame time: a sphere filling most of the image, lit by the first environment alone.
    result.width = result.height = lightingFrameSize(quick);
    RenderSettings settings;
    settings.width = result.width;
    settings.height = result.height;
    settings.samples = 1;
    settings.readHdr = false;
    Renderer renderer;
    const int runs = quick ? 3 : 9;
    Scene scene = sphereUnder(environments.front(), 0.5f, 1.0f);
    scene.display.backgroundFromEnvironment = false;
    auto under = [&](const Scene& shown) { return PreparedScene{shown, sphereMesh(), environments.front().environment}; };
    for (const std::string& method : splitSumMethods(quick)) {
        if (const std::optional<EnvironmentShading> shading = shadingOf(method)) {
            settings.environment = *shading;
            result.costs.push_back({method, *shading, medianOf(runs, [&] { return renderer.timedDraw(under(scene), settings); })});
        }
    }
    Scene directional = scene;
    Light sun;
    sun.type = LightType::Directional;
    directional.lights = {sun};
    settings.environment = {};
    result.directionalFrameMs = medianOf(runs, [&] { return renderer.timedDraw(under(directional), settings); });
    const char* version = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    result.renderer = version ? version : "?";
    return result;
}

int lightingFrameSize(bool quick) {
    return quick ? 128 : 512;
}

std::string lightingCostCsv(const LightingAccuracyResult& result) {
    std::vector<std::string> names;
    for (const SplitSumErrorRow& row : result.accuracy.rows) {
        if (std::find(names.begin(), names.end(), row.environment) == names.end()) {
            names.push_back(row.environment);
        }
    }
    std::ostringstream csv;
    csv.precision(5);
    csv << "method,frame_ms,mean_relative_error";
    for (const std::string& name : names) {
        csv << "," << name;
    }
    csv << "\n";
    for (const LightingCostRow& cost : result.costs) {
        csv << "\"" << cost.method << "\"," << cost.frameMs << "," << meanError(result.accuracy.rows, cost.method);
        for (const std::string& name : names) {
            csv << "," << meanError(result.accuracy.rows, cost.method, name);
        }
        csv << "\n";
    }
    csv << "\"" << kDirectionalRow << "\"," << result.directionalFrameMs << ",\n";
    return csv.str();
}

LightingAccuracyResult parseLightingAccuracy(const CsvFile& splitSum, const CsvFile& cost, bool quick) {
    LightingAccuracyResult result;
    result.accuracy.rows = parseSplitSumRows(splitSum);
    result.width = result.height = lightingFrameSize(quick);
    for (const CsvLine& line : csvBody(cost, "method,frame_ms,mean_relative_error")) {
        const std::string& method = line.cells[0];
        const double frameMs = csvNumber(line, 1, cost.source);
        if (method == kDirectionalRow) {
            result.directionalFrameMs = frameMs;
        } else if (const std::optional<EnvironmentShading> shading = shadingOf(method)) {
            result.costs.push_back({method, *shading, frameMs});
        } else {
            throw InputError(cost.source + ":" + std::to_string(line.number) + ": no such method: " + method);
        }
    }
    return result;
}

Chart lightingAccuracyChart(const LightingAccuracyResult& result) {
    const std::vector<SplitSumErrorRow>& rows = result.accuracy.rows;
    std::vector<std::string> environments, methods;
    for (const SplitSumErrorRow& row : rows) {
        if (std::find(environments.begin(), environments.end(), row.environment) == environments.end()) {
            environments.push_back(row.environment);
        }
        if (std::find(methods.begin(), methods.end(), row.method) == methods.end()) {
            methods.push_back(row.method);
        }
    }
    Chart chart;
    ChartPanel cost{"Cost against error", "frame time, ms (" + std::to_string(result.width) + "^2, llvmpipe)",
                    "mean relative error against the ground truth", true, true, {}};
    for (size_t e = 0; e < environments.size(); ++e) {
        ChartSeries series{environments[e], {}, e, false, true, false, {}, {}};
        for (const LightingCostRow& row : result.costs) {
            series.points.emplace_back(row.frameMs, std::max(meanError(rows, row.method, environments[e]), 1e-5));
            series.pointLabels.push_back(e == 0 ? row.method : "");
        }
        cost.series.push_back(series);
    }
    chart.panels.push_back(cost);

    // Each error source against roughness and against NoV, over environments, F0 and the rest.
    auto byAxis = [&](const char* title, const char* axis, auto value) {
        ChartPanel panel{title, axis, "mean relative error", false, true, {}};
        size_t colour = 0;
        for (const std::string& method : methods) {
            if (method.starts_with("stochastic") && method != "stochastic, 16 samples") {
                continue;   // one of them stands for the rest here
            }
            struct Sum {
                double error = 0.0, truthVariance = 0.0;
                int count = 0;
            };
            std::map<float, Sum> sums;
            for (const SplitSumErrorRow& row : rows) {
                if (row.method == method) {
                    Sum& sum = sums[value(row)];
                    sum.error += row.relativeError;
                    sum.truthVariance += row.truthRelativeStandardError * row.truthRelativeStandardError;
                    ++sum.count;
                }
            }
            // The bars: the ground truth's standard error carried into the mean (to first order,
            // a relative error moves by the truth's relative error; the rows' truths are independent).
            ChartSeries series{method, {}, colour++, true, true, false, {}, {}};
            for (const auto& [x, sum] : sums) {
                series.points.emplace_back(x, std::max(sum.error / sum.count, 1e-6));
                series.errors.push_back(std::sqrt(sum.truthVariance) / sum.count);
            }
            panel.series.push_back(series);
        }
        chart.panels.push_back(panel);
    };
    byAxis("Error by source against roughness", "roughness r", [](const SplitSumErrorRow& r) { return r.roughness; });
    byAxis("Error by source against NoV", "NoV", [](const SplitSumErrorRow& r) { return r.NoV; });
    return chart;
}

LdrImage roughnessMetallicGrid(const NamedEnvironment& environment, int cellSize, int samples) {
    const float roughnesses[] = {0.05f, 0.25f, 0.5f, 0.75f, 1.0f};
    std::vector<LdrImage> split, truth, error;
    Renderer renderer;
    RenderSettings settings;
    settings.width = settings.height = cellSize;
    settings.samples = 1;   // pixel centres, as the ground truth
    for (float metallic : {0.0f, 1.0f}) {
        for (float roughness : roughnesses) {
            const Scene scene = sphereUnder(environment, roughness, metallic);
            const PreparedScene prepared{scene, sphereMesh(), environment.environment};
            const RenderOutput render = renderer.render(prepared, settings);
            const PixelSurfaces surfaces = rasterizeSurfaces(prepared, cellSize, cellSize);
            ReferenceRenderOptions options;
            options.samplesPerPixel = samples;
            const ReferenceImage reference = renderReference(prepared, surfaces, options);
            split.push_back(render.ldr);
            truth.push_back(displayImage(reference.value, scene.display, reference.backdrop));
            LdrImage map{cellSize, cellSize, std::vector<uint8_t>(size_t(cellSize) * size_t(cellSize) * 4, 255)};
            for (size_t pixel = 0; pixel < surfaces.sampleOfPixel.size(); ++pixel) {
                const float t = luminance(&reference.value.rgb[pixel * 3]);
                const float s = luminance(&render.hdr.rgb[pixel * 3]);
                const float relative = surfaces.sampleOfPixel[pixel] < 0 ? 0.0f : std::abs(s - t) / std::max(t, 1e-4f);
                const Rgb8 c = heatColour(int(std::min(relative / 0.25f, 1.0f) * 255.0f));
                map.rgba[pixel * 4] = c.r;
                map.rgba[pixel * 4 + 1] = c.g;
                map.rgba[pixel * 4 + 2] = c.b;
            }
            error.push_back(map);
        }
    }
    const int columns = int(std::size(roughnesses));
    return contactSheet({tile(split, columns), tile(truth, columns), tile(error, columns)},
                        {environment.name + ": split sum (r 0.05 to 1; dielectric, then gold)",
                         "ground truth, " + std::to_string(samples) + " samples a pixel",
                         "|split - truth| / truth, black 0 to yellow 25%"},
                        1);
}

}  // namespace patina
