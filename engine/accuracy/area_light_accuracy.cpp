#include "accuracy/area_light_accuracy.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <glm/glm.hpp>

#include "image/caption.h"
#include "reference/probe_reference.h"
#include "scene/light_packing.h"
#include "scene/probe.h"
#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"

namespace patina {

namespace {

struct Method {
    const char* name;
    shader::AreaLightMethod method;
};
const Method kSpecularMethods[] = {{"karis-s/2d", {shader::WIDENING_UE4, false}},
                                   {"karis-s/3d", {shader::WIDENING_THIRD, false}}};
const Method kDiffuseMethods[] = {{"karis", {shader::WIDENING_UE4, false}},
                                  {"frostbite", {shader::WIDENING_UE4, true}}};

// A tube's length over the distance of its centre, in every measurement.
constexpr double kTubeLength = 1.0;

// A physical light (inverse square, no window: radiance exactly I / (pi s^2), lighting.md) of
// intensity 1 whose centre lies at distance 1 and `elevation` from the normal +Z, in the x-z
// plane. A tube lies across that plane, along y.
Light physicalLight(bool tube, double size, double elevation) {
    Light light;
    light.type = tube ? LightType::Tube : LightType::Sphere;
    light.position = glm::vec3(float(std::sin(elevation)), 0.0f, float(std::cos(elevation)));
    light.start = light.position - glm::vec3(0.0f, float(0.5 * kTubeLength), 0.0f);
    light.end = light.position + glm::vec3(0.0f, float(0.5 * kTubeLength), 0.0f);
    light.sourceRadius = float(size);
    light.range = 0.0f;
    light.attenuation = {0.0f, 0.0f, 1.0f};
    light.intensity = 1.0f;
    return light;
}

// Whether part of the light lies below the horizon of N = +Z.
bool crossesHorizon(const Light& light) {
    const float lowest = light.type == LightType::Tube ? std::min(light.start.z, light.end.z) : light.position.z;
    return lowest < light.sourceRadius;
}

glm::vec3 viewAt(double theta) {
    return {float(std::sin(theta)), 0.0f, float(std::cos(theta))};
}

// A white metal (F = 1, no diffuse) for the specular lobe; white Lambert with no specular
// reflectance (F0 = 0, Fresnel's tail only) for the diffuse one.
Material specularMaterial(double roughness) {
    Material m;
    m.baseColor = glm::vec3(1.0f);
    m.metallic = 1.0f;
    m.roughness = float(roughness);
    return m;
}

Material diffuseMaterial() {
    Material m;
    m.baseColor = glm::vec3(1.0f);
    m.specular = 0.0f;
    m.roughness = 1.0f;
    return m;
}

// Views through the highlight: around the mirror of the light's centre, over the angle the
// light and the lobe span, above the horizon.
std::vector<ProbeSample> highlightSweep(double elevation, double size, double roughness, int count) {
    const double halfWidth = std::max(2.5 * (std::asin(std::min(size, 1.0)) + roughness * roughness), 0.02);
    std::vector<ProbeSample> samples;
    for (int i = 0; i < count; ++i) {
        const double theta = std::clamp(-elevation + halfWidth * (2.0 * i / (count - 1) - 1.0), -1.53, 1.53);
        samples.push_back({glm::vec3(0.0f), {0, 0, 1}, viewAt(theta)});
    }
    return samples;
}

void addSpecularRows(std::vector<AreaAccuracyRow>& rows, bool tube, double roughness, double size, double elevation,
                     int views, int samples) {
    const Light light = physicalLight(tube, size, elevation);
    const Material material = specularMaterial(roughness);
    const std::vector<ProbeSample> sweep = highlightSweep(elevation, size, roughness, views);
    const std::vector<ReferenceRow> truth = probeReference(material, {light}, sweep, nullptr, samples);
    double truthSum = 0.0, truthVariance = 0.0;
    for (const ReferenceRow& t : truth) {
        truthSum += t.value.r;
        truthVariance += double(t.standardError.r) * t.standardError.r;
    }
    const shader::PackedLight packed = packLight(light);
    const shader::SurfaceMaterial surface = surfaceMaterial(material);
    for (const Method& method : kSpecularMethods) {
        double difference = 0.0, approximationSum = 0.0;
        for (size_t i = 0; i < sweep.size(); ++i) {
            const float value = shadeAreaLight(BrdfModelId::Epic, packed, method.method, surface, sweep[i].position,
                                               sweep[i].normal, sweep[i].toViewer).r;
            difference += std::abs(double(value) - double(truth[i].value.r));
            approximationSum += value;
        }
        rows.push_back({tube ? "tube" : "sphere", "specular", method.name, roughness, size, glm::degrees(elevation),
                        crossesHorizon(light), difference / truthSum, approximationSum / truthSum,
                        std::sqrt(truthVariance) / truthSum});
    }
}

void addDiffuseRows(std::vector<AreaAccuracyRow>& rows, bool tube, double size, double elevation, int samples) {
    const Light light = physicalLight(tube, size, elevation);
    const Material material = diffuseMaterial();
    const ProbeSample sample{glm::vec3(0.0f), {0, 0, 1}, {0, 0, 1}};
    const ReferenceRow truth = probeReference(material, {light}, {sample}, nullptr, samples)[0];
    // E / pi over the illuminance straight above, I / d^2 = 1.
    const double scale = 1.0 / std::numbers::pi;
    for (const Method& method : kDiffuseMethods) {
        if (tube && method.method.exactSphereDiffuse) {
            continue;   // Frostbite's closed form is a sphere's
        }
        const float value = shadeAreaLight(BrdfModelId::Epic, packLight(light), method.method, surfaceMaterial(material),
                                           sample.position, sample.normal, sample.toViewer).r;
        const double ratio = truth.value.r > 0.0f ? double(value) / double(truth.value.r) : (value > 0.0f ? 0.0 : 1.0);
        rows.push_back({tube ? "tube" : "sphere", "diffuse", method.name, 1.0, size, glm::degrees(elevation),
                        crossesHorizon(light), std::abs(double(value) - double(truth.value.r)) / scale, ratio,
                        double(truth.standardError.r) / scale});
    }
}

// Nanoseconds per call of `shade` over many random configurations on one core.
template <typename Shade>
double timePerCall(Shade shade, int count) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<glm::vec3> positions(1024);
    for (glm::vec3& p : positions) {
        p = 0.3f * glm::vec3(unit(rng), unit(rng), unit(rng));
    }
    const glm::vec3 N = glm::normalize(glm::vec3(0.1f, 0.2f, 1.0f)), V = glm::normalize(glm::vec3(-0.3f, 0.1f, 1.0f));
    glm::vec3 sum(0.0f);
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i) {
        sum += shade(positions[size_t(i) % positions.size()], N, V);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The sum is used, so the calls are not optimised away.
    return std::isfinite(sum.x) ? seconds * 1e9 / count : 0.0;
}

std::vector<AreaCost> measureCosts(int count) {
    const shader::SurfaceMaterial surface = surfaceMaterial(specularMaterial(0.5));
    Light point = physicalLight(false, 0.0, 0.5);
    const shader::PackedLight packedPoint = packLight(point);
    const shader::PackedLight sphere = packLight(physicalLight(false, 0.2, 0.5));
    const shader::PackedLight tube = packLight(physicalLight(true, 0.2, 0.5));
    std::vector<AreaCost> costs;
    costs.push_back({"point", timePerCall([&](glm::vec3 P, glm::vec3 N, glm::vec3 V) {
                         return shadeLight(BrdfModelId::Epic, packedPoint, surface, P, N, V);
                     }, count)});
    for (const auto& [name, light, method] :
         {std::tuple{"sphere karis", sphere, shader::AreaLightMethod(shader::WIDENING_UE4, false)},
          std::tuple{"sphere frostbite", sphere, shader::AreaLightMethod(shader::WIDENING_UE4, true)},
          std::tuple{"tube karis", tube, shader::AreaLightMethod(shader::WIDENING_UE4, false)}}) {
        costs.push_back({name, timePerCall([&](glm::vec3 P, glm::vec3 N, glm::vec3 V) {
                             return shadeAreaLight(BrdfModelId::Epic, light, method, surface, P, N, V);
                         }, count)});
    }
    return costs;
}
}  // namespace

AreaAccuracyResult runAreaAccuracy(bool quick) {
    AreaAccuracyResult result;
    result.referenceSamples = quick ? 256 : 8192;
    const std::vector<double> roughness =
        quick ? std::vector<double>{0.05, 0.5, 1.0} : std::vector<double>{0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0};
    const std::vector<double> sizes =
        quick ? std::vector<double>{0.05, 0.3} : std::vector<double>{0.02, 0.05, 0.1, 0.2, 0.4};
    const int views = quick ? 9 : 33;
    for (bool tube : {false, true}) {
        // 30 degrees: above the horizon; 75: the larger lights cross it.
        for (double elevation : {glm::radians(30.0), glm::radians(75.0)}) {
            for (double size : sizes) {
                for (double r : roughness) {
                    addSpecularRows(result.rows, tube, r, size, elevation, views, result.referenceSamples);
                }
            }
        }
        const std::vector<double> diffuseSizes =
            quick ? std::vector<double>{0.3} : std::vector<double>{0.1, 0.3, 0.5, 0.7, 0.9};
        for (double size : diffuseSizes) {
            // From straight above to the light's last sliver above the horizon.
            const double last = std::numbers::pi / 2.0 + std::asin(size);
            const int steps = quick ? 4 : 16;
            for (int i = 0; i <= steps; ++i) {
                addDiffuseRows(result.rows, tube, size, last * i / (steps + 1), result.referenceSamples * 4);
            }
        }
    }
    result.costs = measureCosts(quick ? 20000 : 2000000);
    return result;
}

std::string areaAccuracyCsv(const AreaAccuracyResult& result) {
    std::string csv = "light,lobe,method,roughness,size,elevation_deg,crosses_horizon,error,energy_ratio,truth_error\n";
    char line[256];
    for (const AreaAccuracyRow& row : result.rows) {
        std::snprintf(line, sizeof line, "%s,%s,%s,%.3g,%.3g,%.4g,%d,%.6g,%.6g,%.3g\n", row.light.c_str(),
                      row.lobe.c_str(), row.method.c_str(), row.roughness, row.size, row.elevationDegrees,
                      row.crossesHorizon ? 1 : 0, row.error, row.energyRatio, row.truthError);
        csv += line;
    }
    return csv;
}

std::string areaCostCsv(const AreaAccuracyResult& result) {
    std::string csv = "method,ns_per_point,ratio_to_point\n";
    const double point = result.costs.empty() ? 0.0 : result.costs.front().nanoseconds;
    char line[160];
    for (const AreaCost& cost : result.costs) {
        std::snprintf(line, sizeof line, "%s,%.4g,%.3g\n", cost.method.c_str(), cost.nanoseconds,
                      point > 0.0 ? cost.nanoseconds / point : 0.0);
        csv += line;
    }
    return csv;
}

Chart areaAccuracyChart(const AreaAccuracyResult& result) {
    Chart chart;
    chart.panelWidth = 480;
    for (const char* light : {"sphere", "tube"}) {
        ChartPanel panel{std::string(light) + " specular, light at 30 deg", "roughness r",
                         "sum |approx - truth| / sum truth", false, true, {}};
        std::vector<double> sizes;
        for (const AreaAccuracyRow& row : result.rows) {
            if (row.light == light && row.lobe == "specular" &&
                std::find(sizes.begin(), sizes.end(), row.size) == sizes.end()) {
                sizes.push_back(row.size);
            }
        }
        size_t style = 0;
        for (size_t k = 0; k < sizes.size(); ++k) {
            for (const Method& method : kSpecularMethods) {
                const bool third = method.method.widening == shader::WIDENING_THIRD;
                char label[64];
                std::snprintf(label, sizeof label, "s/d %.2g, %s", sizes[k], third ? "s/(3d)" : "s/(2d)");
                ChartSeries series{label, {}, style++, true, true, third, {}, {}};
                for (const AreaAccuracyRow& row : result.rows) {
                    if (row.light == light && row.lobe == "specular" && row.method == method.name &&
                        row.size == sizes[k] && std::abs(row.elevationDegrees - 30.0) < 1e-6) {
                        series.points.emplace_back(row.roughness, std::max(row.error, 1e-5));
                        series.errors.push_back(row.truthError);
                    }
                }
                panel.series.push_back(series);
            }
        }
        chart.panels.push_back(panel);
    }
    // Diffuse: a colour and marker per size and method, Karis's line solid and Frostbite's dashed;
    // each bar is the ground truth's standard error.
    for (const char* light : {"sphere", "tube"}) {
        ChartPanel diffuse{std::string(light) + " diffuse across the horizon", "elevation of the centre (deg)",
                           "|approx - truth| / (I / d^2)", false, true, {}};
        std::vector<double> sizes;
        for (const AreaAccuracyRow& row : result.rows) {
            if (row.light == light && row.lobe == "diffuse" &&
                std::find(sizes.begin(), sizes.end(), row.size) == sizes.end()) {
                sizes.push_back(row.size);
            }
        }
        size_t style = 0;
        for (size_t k = 0; k < sizes.size(); ++k) {
            for (const Method& method : kDiffuseMethods) {
                char label[64];
                std::snprintf(label, sizeof label, "s/d %.2g, %s", sizes[k], method.name);
                ChartSeries series{label, {}, style++, true, true, method.method.exactSphereDiffuse, {}, {}};
                for (const AreaAccuracyRow& row : result.rows) {
                    if (row.light == light && row.lobe == "diffuse" && row.method == method.name && row.size == sizes[k]) {
                        series.points.emplace_back(row.elevationDegrees, std::max(row.error, 1e-5));
                        series.errors.push_back(row.truthError);
                    }
                }
                if (!series.points.empty()) {
                    diffuse.series.push_back(series);
                }
            }
        }
        chart.panels.push_back(diffuse);
    }
    return chart;
}

LdrImage areaLightSpheres(bool quick) {
    const std::vector<float> roughness = {0.05f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f};
    const int cell = quick ? 24 : 96;
    const int samples = quick ? 16 : 1024;
    const int header = captionHeight(1);
    const int margin = 170;   // the row captions
    const int rows = 6;       // per light: approximation, truth, error
    LdrImage image{margin + int(roughness.size()) * cell, header + rows * cell, {}};
    image.rgba.assign(size_t(image.width) * size_t(image.height) * 4, 0);
    for (size_t i = 3; i < image.rgba.size(); i += 4) {
        image.rgba[i] = 255;
    }
    auto put = [&](int x, int y, glm::vec3 srgb) {
        uint8_t* p = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
        for (int c = 0; c < 3; ++c) {
            p[c] = uint8_t(std::lround(std::clamp(srgb[c], 0.0f, 1.0f) * 255.0f));
        }
    };
    auto display = [](glm::vec3 linear) { return shader::displayTransform(linear, 0.0f, shader::TONEMAP_PBR_NEUTRAL); };
    const Rgb8 white{230, 230, 230};
    for (size_t k = 0; k < roughness.size(); ++k) {
        char text[32];
        std::snprintf(text, sizeof text, "r = %.2g", double(roughness[k]));
        drawText(image, margin + int(k) * cell + 4, 0, text, 1, white);
    }
    // A unit sphere seen down -Z (orthographic), lit from above, right and in front.
    Light sphere;
    sphere.type = LightType::Sphere;
    sphere.position = {1.5f, 1.5f, 2.5f};
    sphere.sourceRadius = 0.6f;
    sphere.range = 0.0f;
    sphere.attenuation = {0.0f, 0.0f, 1.0f};
    sphere.intensity = 12.0f;
    Light tube = sphere;
    tube.type = LightType::Tube;
    tube.start = {-1.5f, 2.0f, 2.5f};
    tube.end = {1.5f, 2.0f, 2.5f};
    tube.sourceRadius = 0.15f;
    const Light lights[] = {sphere, tube};
    const char* captions[] = {"sphere light: Karis s/(2d)", "sphere: ground truth", "sphere: |error| x 4",
                              "tube light: Karis s/(2d)",   "tube: ground truth",   "tube: |error| x 4"};
    for (int row = 0; row < rows; ++row) {
        drawText(image, 4, header + row * cell + cell / 2 - captionHeight(1) / 2, captions[row], 1, white);
    }
    for (int l = 0; l < 2; ++l) {
        for (size_t k = 0; k < roughness.size(); ++k) {
            Material material;
            material.baseColor = {0.5f, 0.5f, 0.5f};
            material.roughness = roughness[k];
            std::vector<ProbeSample> pixels;
            std::vector<glm::ivec2> where;
            for (int y = 0; y < cell; ++y) {
                for (int x = 0; x < cell; ++x) {
                    const float u = (2.0f * (float(x) + 0.5f) / float(cell) - 1.0f) * 1.05f;
                    const float v = (1.0f - 2.0f * (float(y) + 0.5f) / float(cell)) * 1.05f;
                    if (u * u + v * v < 1.0f) {
                        const glm::vec3 n(u, v, std::sqrt(1.0f - u * u - v * v));
                        pixels.push_back({n, n, {0.0f, 0.0f, 1.0f}});
                        where.emplace_back(margin + int(k) * cell + x, header + 3 * l * cell + y);
                    }
                }
            }
            const std::vector<glm::vec3> approximation = probeOnCpu(material, {lights[l]}, pixels);
            const std::vector<ReferenceRow> truth = probeReference(material, {lights[l]}, pixels, nullptr, samples);
            for (size_t i = 0; i < pixels.size(); ++i) {
                put(where[i].x, where[i].y, display(approximation[i]));
                put(where[i].x, where[i].y + cell, display(truth[i].value));
                put(where[i].x, where[i].y + 2 * cell, display(4.0f * glm::abs(approximation[i] - truth[i].value)));
            }
        }
    }
    return image;
}

}  // namespace patina
