#include "accuracy/albedo_curve.h"

#include <cmath>
#include <memory>

#include <glm/trigonometric.hpp>

#include "common/luminance.h"
#include "common/parallel_for.h"
#include "environment/builtin_environments.h"
#include "environment/cube_map.h"
#include "environment/environment.h"
#include "reference/radiance.h"
#include "shading/channel_inputs.h"
#include "shading/cpu_shading.h"

namespace patina {

namespace {
// The white furnace, prepared once for the process (its chain and SH for the split sum, its
// image for the ground truth).
const Environment& whiteFurnace() {
    static const std::shared_ptr<const Environment> white =
        prepareEnvironment(*builtinEnvironment("white"), builtinSource("white"));
    return *white;
}
bool layered(const MaterialParameters& material) {
    return material.clearcoat > 0.0f || material.sheenColor != glm::vec3(0.0f) || material.transmission > 0.0f;
}

// A material with a coat, a sheen or a transmission as the renderer shades it under the
// furnace: the CPU twin's (shade.frag's environment with its layers, channel_inputs.h), no
// lights; its radiance and its light through the wall.
shader::ChannelInputs layeredProduct(const MaterialParameters& material, const Environment& white, glm::vec3 N,
                                     glm::vec3 V) {
    ChannelPoint point = channelPointOf(material);
    point.geometryNormal = point.N = N;
    point.V = V;
    point.anisotropyTangent = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);   // surfaceMaterialInLobeFrame's
    ChannelEnvironment environment;
    environment.prefiltered = [&white](glm::vec3 d, float lod) { return sampleCube(white.prefiltered, d, lod); };
    environment.maxLod = white.maxLod();
    environment.irradiance = irradianceReader(white);
    return gatherChannelInputs(material.model, point, {}, -1, -1, &environment);
}
}  // namespace

AlbedoPoint albedoAt(const MaterialParameters& material, float thetaVDegrees, int samples, uint64_t seed) {
    const Environment& white = whiteFurnace();
    static const EnvironmentDistribution distribution(white.image);
    const ReferenceEnvironment reference{&white, &distribution, 1.0f, 0.0f};
    const shader::SurfaceMaterial surface = surfaceMaterialInLobeFrame(material);   // V in the tangent's plane
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    const float theta = glm::radians(thetaVDegrees);
    const glm::vec3 V(std::sin(theta), 0.0f, std::cos(theta));
    AlbedoPoint point;
    point.thetaVDegrees = thetaVDegrees;
    if (layered(material)) {
        const shader::ChannelInputs layers = layeredProduct(material, white, N, V);
        point.product = layers.radiance;
        point.productTransmitted = layers.transmission;
    } else {
        point.product = shadeEnvironmentOnCpu(material.model, surface, white, 1.0f, 0.0f, N, V);
    }
    ReferenceOptions options;
    options.samples = samples;
    options.seed = seed;
    const ReferenceEstimate truth = referenceRadiance(material.model, surface, reference, {}, glm::vec3(0.0f), N, V,
                                                      withLayersOf(options, material));
    point.truth = truth.value;
    point.standardError = truth.standardError;
    point.truthTransmitted = truth.transmitted;
    return point;
}

std::vector<AlbedoPoint> albedoCurve(const MaterialParameters& material, int points, int samples) {
    std::vector<AlbedoPoint> curve(size_t(std::max(points, 2)));
    parallelFor(curve.size(), [&](size_t i) {
        curve[i] = albedoAt(material, 88.5f * float(i) / float(curve.size() - 1), samples, 0x9E3779B97F4A7C15ull * (i + 1));
    });
    return curve;
}

namespace {
// A material's transmitted albedo as a dashed line of the split sum's in its colour (none when it
// transmits nothing): what of the curve above it comes through the wall.
void addTransmittedSeries(ChartPanel& panel, const std::string& name, const std::vector<AlbedoPoint>& curve,
                          size_t style) {
    ChartSeries transmitted{name + ": transmitted (split sum)", {}, style, true, false, true, {}, {}};
    bool any = false;
    for (const AlbedoPoint& p : curve) {
        transmitted.points.emplace_back(p.thetaVDegrees, luminance(p.productTransmitted));
        any = any || p.productTransmitted != glm::vec3(0.0f);
    }
    if (any) {
        panel.series.push_back(std::move(transmitted));
    }
}
}  // namespace

Chart albedoChart(const std::vector<std::pair<std::string, std::vector<AlbedoPoint>>>& curves) {
    ChartPanel panel{"Directional albedo under a white furnace", "theta_v (degrees)", "albedo (luminance)", false,
                     false, {}};
    for (size_t i = 0; i < curves.size(); ++i) {
        ChartSeries product{curves[i].first + ": split sum", {}, i, true, false, false, {}, {}};
        ChartSeries truth{curves[i].first + ": ground truth, 1 s.e.", {}, i, false, true, false, {}, {}};
        for (const AlbedoPoint& p : curves[i].second) {
            product.points.emplace_back(p.thetaVDegrees, luminance(p.product));
            truth.points.emplace_back(p.thetaVDegrees, luminance(p.truth));
            truth.errors.push_back(luminance(p.standardError));
        }
        panel.series.push_back(std::move(product));
        panel.series.push_back(std::move(truth));
        addTransmittedSeries(panel, curves[i].first, curves[i].second, i);
    }
    Chart chart;
    chart.panels.push_back(std::move(panel));
    return chart;
}

}  // namespace patina
