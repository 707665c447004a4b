#include "accuracy/shadow_accuracy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "common/luminance.h"
#include "gl/renderer.h"
#include "gl/shadow_settings.h"
#include "reference/pixel_surfaces.h"
#include "reference/reference_draws.h"
#include "reference/reference_render.h"
#include "scene/view.h"

namespace patina {

namespace {
// Where the light comes from, seen from the sphere's centre: 55 degrees above the floor and
// behind the sphere, so that its shadow falls towards the camera, in view.
const glm::vec3 kTowardsLight = glm::normalize(glm::vec3(0.0f, 1.0f, -0.7f));
constexpr float kSphereLightDistance = 5.0f;
// The light the floor takes where nothing shadows it, for both kinds: I cos / d^2 = 3 cos.
constexpr float kIrradiance = 3.0f;

Light shadowedLight(std::optional<float> sourceRadius) {
    Light light;
    light.shadows = true;
    if (!sourceRadius) {
        light.type = LightType::Directional;
        light.direction = -kTowardsLight;
        light.intensity = kIrradiance;
        return light;
    }
    light.type = LightType::Sphere;
    light.position = kSphereLightDistance * kTowardsLight;
    light.sourceRadius = *sourceRadius;
    light.range = 0.0f;                      // no window: the inverse square, as the truth's
    light.attenuation = {0.0f, 0.0f, 1.0f};
    light.intensity = kIrradiance * kSphereLightDistance * kSphereLightDistance;
    return light;
}

// The unit sphere over the floor, seen from above and in front, lit by `light` alone.
Scene shadowScene(const Light& light) {
    Scene scene = defaultScene();
    scene.mesh = MeshKind::Sphere;
    scene.camera.position = {0.0f, 7.0f, 3.0f};
    scene.camera.target = {0.0f, -1.0f, 0.7f};
    scene.lights = {light};
    scene.display.ground = Ground::Floor;
    return scene;
}

// Pixels of the floor and of the model, as the ground truth's rasteriser sees them (the floor
// is the last draw, referenceDraws).
struct Regions {
    std::vector<size_t> floor, model;
    std::vector<uint8_t> isFloor;   // per pixel
};
Regions regionsOf(const PixelSurfaces& surfaces) {
    Regions regions;
    regions.isFloor.assign(surfaces.sampleOfPixel.size(), 0);
    const int32_t floorDraw = int32_t(surfaces.materials.size()) - 1;
    for (size_t pixel = 0; pixel < surfaces.sampleOfPixel.size(); ++pixel) {
        const int32_t i = surfaces.sampleOfPixel[pixel];
        if (i < 0) {
            continue;
        }
        const bool floor = surfaces.drawOfSample[size_t(i)] == floorDraw;
        (floor ? regions.floor : regions.model).push_back(pixel);
        regions.isFloor[pixel] = floor;
    }
    return regions;
}

double luminanceAt(const HdrImage& image, size_t pixel) {
    return luminance(&image.rgb[pixel * 3]);
}

RegionError regionError(const HdrImage& render, const HdrImage& truth, const std::vector<size_t>& pixels) {
    double squared = 0.0, signedSum = 0.0, truthSum = 0.0;
    for (const size_t pixel : pixels) {
        const double difference = luminanceAt(render, pixel) - luminanceAt(truth, pixel);
        squared += difference * difference;
        signedSum += difference;
        truthSum += luminanceAt(truth, pixel);
    }
    RegionError error;
    error.pixels = int(pixels.size());
    if (pixels.empty() || !(truthSum > 0.0)) {
        return error;
    }
    const double n = double(pixels.size()), truthMean = truthSum / n;
    error.rmse = std::sqrt(squared / n) / truthMean;
    error.meanError = signedSum / n / truthMean;
    return error;
}

// The light's visibility on the floor's pixels: the shadowed radiance over the unshadowed; -1
// elsewhere and where the floor takes no light.
std::vector<float> visibilityOf(const HdrImage& shadowed, const HdrImage& open, const Regions& regions) {
    std::vector<float> visibility(regions.isFloor.size(), -1.0f);
    for (const size_t pixel : regions.floor) {
        const double lit = luminanceAt(open, pixel);
        if (lit > 1e-6) {
            visibility[pixel] = float(luminanceAt(shadowed, pixel) / lit);
        }
    }
    return visibility;
}

// The line across the shadow's middle on the floor, and how the camera sees it.
struct Transect {
    glm::vec3 centre{0.0f}, across{1.0f, 0.0f, 0.0f};
    glm::mat4 viewProjection{1.0f};
    int width = 0, height = 0;

    // The visibility at floor point p, bilinear between the floor pixels' centres around it
    // (the others left out); -1 where none is floor.
    float visibilityAt(const std::vector<float>& visibility, glm::vec3 p) const {
        const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
        const float x = (clip.x / clip.w * 0.5f + 0.5f) * float(width) - 0.5f;
        const float y = (0.5f - clip.y / clip.w * 0.5f) * float(height) - 0.5f;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        double sum = 0.0, weights = 0.0;
        for (int dy = 0; dy <= 1; ++dy) {
            for (int dx = 0; dx <= 1; ++dx) {
                const int px = x0 + dx, py = y0 + dy;
                if (px < 0 || py < 0 || px >= width || py >= height) {
                    continue;
                }
                const float v = visibility[size_t(py) * size_t(width) + size_t(px)];
                const double weight = (dx ? x - float(x0) : 1.0f - (x - float(x0))) *
                                      (dy ? y - float(y0) : 1.0f - (y - float(y0)));
                if (v >= 0.0f && weight > 0.0) {
                    sum += weight * v;
                    weights += weight;
                }
            }
        }
        return weights > 0.0 ? float(sum / weights) : -1.0f;
    }

    // World units between where the visibility first exceeds 0.1 and where it first reaches
    // 0.9, walking out from the middle, the mean of both sides (NaN where a side never does).
    double penumbraWidth(const std::vector<float>& visibility, double step) const {
        double total = 0.0;
        for (const float side : {1.0f, -1.0f}) {
            double inner = std::nan(""), outer = std::nan("");
            for (double t = 0.0; t < 4.0 && std::isnan(outer); t += step) {
                const float v = visibilityAt(visibility, centre + side * float(t) * across);
                if (std::isnan(inner) && v > 0.1f) {
                    inner = t;
                }
                if (v >= 0.9f) {
                    outer = t;
                }
            }
            total += outer - inner;
        }
        return total / 2.0;
    }
};

Transect transectOf(const Scene& scene, float floorHeight, int width, int height) {
    Transect transect;
    // The ray from the light through the sphere's centre (the origin) meets the floor here.
    transect.centre = -kTowardsLight * (-floorHeight / kTowardsLight.y);
    transect.across = glm::normalize(glm::cross(kTowardsLight, glm::vec3(0.0f, 1.0f, 0.0f)));
    transect.viewProjection = viewProjection(scene.camera, float(width) / float(height));
    transect.width = width;
    transect.height = height;
    return transect;
}

// A floor pixel's width in world units at the shadow's middle, across the shadow.
double pixelFootprint(const Transect& transect) {
    auto pixelX = [&](glm::vec3 p) {
        const glm::vec4 clip = transect.viewProjection * glm::vec4(p, 1.0f);
        return (clip.x / clip.w * 0.5f + 0.5f) * float(transect.width);
    };
    const float span = 0.2f;
    return span / std::abs(pixelX(transect.centre + span * transect.across) - pixelX(transect.centre));
}

// The rows of one light: the truth with and without visibility, the render without shadows,
// then the shadowed render at every map size and bias.
void measureLight(std::optional<float> sourceRadius, const ShadowAccuracyOptions& options, Renderer& renderer,
                  ShadowAccuracyResult& result) {
    const Scene scene = shadowScene(shadowedLight(sourceRadius));
    Scene open = scene;
    open.lights[0].shadows = false;
    const std::shared_ptr<const Mesh> sphere = builtinMesh(MeshKind::Sphere);
    const PreparedScene prepared{scene, sphere, nullptr};
    const PreparedScene openPrepared{open, sphere, nullptr};
    const std::optional<Mesh> ground = groundOf(prepared);
    const PixelSurfaces surfaces =
        rasterizeSurfaces(referenceDraws(prepared, ground), scene.camera, options.width, options.height);
    const Regions regions = regionsOf(surfaces);
    ReferenceRenderOptions reference;
    reference.samplesPerPixel = sourceRadius ? options.referenceSamples : 1;   // a directional light is exact
    reference.visibility = true;
    const HdrImage truth = renderReference(prepared, surfaces, reference).value;
    reference.visibility = false;
    const HdrImage truthOpen = renderReference(prepared, surfaces, reference).value;

    RenderSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    settings.samples = 1;   // pixel centres, as the truth's
    settings.path = RenderPath::Specialised;
    const HdrImage renderOpen = renderer.render(openPrepared, settings).hdr;
    const Transect transect = transectOf(scene, ground->positions.front().y, options.width, options.height);
    result.pixelFootprint = pixelFootprint(transect);
    const double step = result.pixelFootprint / 8.0;
    const double truthWidth = transect.penumbraWidth(visibilityOf(truth, truthOpen, regions), step);
    for (const int size : options.mapSizes) {
        for (const float bias : options.biasScales) {
            settings.shadowMaps = {size, bias};
            const HdrImage render = renderer.render(prepared, settings).hdr;
            ShadowAccuracyRow row;
            row.light = sourceRadius ? "sphere" : "directional";
            row.sourceRadius = sourceRadius.value_or(0.0f);
            row.mapSize = size;
            row.biasScale = bias;
            row.floor = regionError(render, truth, regions.floor);
            row.model = regionError(render, truth, regions.model);
            row.floorUnshadowed = regionError(renderOpen, truthOpen, regions.floor);
            row.modelUnshadowed = regionError(renderOpen, truthOpen, regions.model);
            row.penumbraWidth = transect.penumbraWidth(visibilityOf(render, renderOpen, regions), step);
            row.truthPenumbraWidth = truthWidth;
            result.rows.push_back(row);
        }
    }
}

std::string lightLabel(const ShadowAccuracyRow& row) {
    if (row.light == "directional") {
        return "directional";
    }
    char label[48];
    std::snprintf(label, sizeof label, "sphere, radius %.2g", row.sourceRadius);
    return label;
}

// One series per light of `y` against `x` over the rows `keep` takes.
template <typename Keep, typename X, typename Y>
void addLightSeries(ChartPanel& panel, const ShadowAccuracyResult& result, Keep keep, X x, Y y) {
    std::vector<std::string> labels;
    for (const ShadowAccuracyRow& row : result.rows) {
        if (std::find(labels.begin(), labels.end(), lightLabel(row)) == labels.end()) {
            labels.push_back(lightLabel(row));
        }
    }
    for (size_t k = 0; k < labels.size(); ++k) {
        ChartSeries series{labels[k], {}, k, true, true, false, {}, {}};
        for (const ShadowAccuracyRow& row : result.rows) {
            if (lightLabel(row) == labels[k] && keep(row)) {
                series.points.emplace_back(x(row), y(row));
            }
        }
        panel.series.push_back(series);
    }
}
}  // namespace

ShadowAccuracyOptions shadowAccuracyOptions(bool quick) {
    ShadowAccuracyOptions options;
    if (quick) {
        options.width = 160;
        options.height = 120;
        options.referenceSamples = 32;
        options.mapSizes = {256, 1024, kShadowMapSize};
        options.biasScales = {0.0f, 1.0f, 4.0f};
        options.sphereRadii = {0.25f, 1.0f};
    }
    return options;
}

ShadowAccuracyResult measureShadowAccuracy(const ShadowAccuracyOptions& options) {
    ShadowAccuracyResult result;
    result.width = options.width;
    result.height = options.height;
    result.referenceSamples = options.referenceSamples;
    Renderer renderer;
    if (options.directional) {
        measureLight(std::nullopt, options, renderer, result);
    }
    for (const float radius : options.sphereRadii) {
        measureLight(radius, options, renderer, result);
    }
    return result;
}

std::string shadowAccuracyCsv(const ShadowAccuracyResult& result) {
    std::string csv =
        "light,source_radius,map_size,bias_scale,floor_pixels,floor_rmse,floor_mean_error,model_pixels,model_rmse,"
        "model_mean_error,floor_rmse_unshadowed,model_rmse_unshadowed,penumbra_width,truth_penumbra_width\n";
    char line[320];
    for (const ShadowAccuracyRow& row : result.rows) {
        std::snprintf(line, sizeof line, "%s,%.3g,%d,%.3g,%d,%.5g,%.5g,%d,%.5g,%.5g,%.5g,%.5g,%.4g,%.4g\n",
                      row.light.c_str(), row.sourceRadius, row.mapSize, row.biasScale, row.floor.pixels,
                      row.floor.rmse, row.floor.meanError, row.model.pixels, row.model.rmse, row.model.meanError,
                      row.floorUnshadowed.rmse, row.modelUnshadowed.rmse, row.penumbraWidth, row.truthPenumbraWidth);
        csv += line;
    }
    return csv;
}

Chart shadowAccuracyChart(const ShadowAccuracyResult& result) {
    Chart chart;
    chart.panelWidth = 480;
    auto defaultBias = [](const ShadowAccuracyRow& row) { return row.biasScale == 1.0; };
    auto defaultSize = [](const ShadowAccuracyRow& row) { return row.mapSize == kShadowMapSize; };
    auto mapSize = [](const ShadowAccuracyRow& row) { return double(row.mapSize); };
    auto bias = [](const ShadowAccuracyRow& row) { return row.biasScale; };
    auto floorRmse = [](const ShadowAccuracyRow& row) { return row.floor.rmse; };
    ChartPanel bySize{"floor, by map size (bias 1x)", "map size (texels a side)", "RMSE / mean truth", true, true, {}};
    addLightSeries(bySize, result, defaultBias, mapSize, floorRmse);
    ChartPanel modelByBias{"sphere, by bias (2048 map)", "bias scale", "RMSE / mean truth", false, true, {}};
    addLightSeries(modelByBias, result, defaultSize, bias, [](const ShadowAccuracyRow& row) { return row.model.rmse; });
    ChartPanel floorByBias{"floor, by bias (2048 map)", "bias scale", "RMSE / mean truth", false, true, {}};
    addLightSeries(floorByBias, result, defaultSize, bias, floorRmse);
    ChartPanel penumbra{"penumbra on the floor (2048 map, bias 1x)", "light's radius (0: directional)",
                        "width (world units)", false, false, {}};
    ChartSeries render{"shadow map", {}, 0, true, true, false, {}, {}};
    ChartSeries truth{"ground truth", {}, 1, true, true, true, {}, {}};
    for (const ShadowAccuracyRow& row : result.rows) {
        if (defaultBias(row) && defaultSize(row)) {
            render.points.emplace_back(row.sourceRadius, row.penumbraWidth);
            truth.points.emplace_back(row.sourceRadius, row.truthPenumbraWidth);
        }
    }
    penumbra.series = {render, truth};
    chart.panels = {bySize, modelByBias, floorByBias, penumbra};
    return chart;
}

}  // namespace patina
