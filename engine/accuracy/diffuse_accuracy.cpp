#include "accuracy/diffuse_accuracy.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "common/luminance.h"
#include "common/parallel_for.h"
#include "environment/irradiance.h"
#include "environment/spherical_harmonics.h"
#include "gl/renderer.h"
#include "reference/environment_distribution.h"
#include "reference/exact_irradiance.h"
#include "reference/pixel_surfaces.h"
#include "reference/radiance.h"
#include "reference/reference_render.h"
#include "scene/channel.h"
#include "shading/cpu_shading.h"

namespace patina {

namespace {

IrradianceErrorRow errorsOf(const std::string& environment, const std::string& method,
                            const std::vector<double>& exact, const std::vector<double>& values) {
    IrradianceErrorRow row{environment, method};
    for (size_t i = 0; i < exact.size(); ++i) {
        const double relative = (values[i] - exact[i]) / std::max(exact[i], 1e-9);
        row.meanRelativeError += std::abs(relative) / double(exact.size());
        row.meanSignedError += relative / double(exact.size());
        row.maxRelativeError = std::max(row.maxRelativeError, std::abs(relative));
    }
    return row;
}

double percentile(std::vector<double> values, double p) {
    if (values.empty()) {
        return std::nan("");
    }
    const size_t at = std::min(values.size() - 1, size_t(p * double(values.size() - 1) + 0.5));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(at), values.end());
    return values[at];
}

double mean(const std::vector<double>& values) {
    double sum = 0.0;
    for (double v : values) {
        sum += v;
    }
    return values.empty() ? std::nan("") : sum / double(values.size());
}

// A cube of side 1.2 at the origin, each face its own four corners with the face's normal,
// turned so that the default camera sees three faces: the top and two sides.
std::shared_ptr<const Mesh> turnedCube() {
    const glm::mat4 turn = glm::rotate(glm::rotate(glm::mat4(1.0f), glm::radians(25.0f), glm::vec3(1, 0, 0)),
                                       glm::radians(40.0f), glm::vec3(0, 1, 0));
    auto mesh = std::make_shared<Mesh>();
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {1.0f, -1.0f}) {
            const glm::vec3 n = axes[axis] * sign;
            const glm::vec3 u = axes[(axis + 1) % 3] * sign, v = axes[(axis + 2) % 3];
            const uint32_t first = uint32_t(mesh->positions.size());
            for (const glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                mesh->positions.push_back(glm::vec3(turn * glm::vec4(0.6f * (n + corner.x * u + corner.y * v), 1.0f)));
                mesh->normals.push_back(glm::vec3(turn * glm::vec4(n, 0.0f)));
            }
            for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) {
                mesh->indices.push_back(first + i);
            }
        }
    }
    return mesh;
}

Scene matteScene(const NamedEnvironment& environment) {
    Scene scene;
    scene.material.name = "matte";
    scene.material.baseColor = glm::vec3(0.5f);
    scene.material.specular = 0.0f;
    scene.material.roughness = 1.0f;
    scene.material.metallic = 0.0f;
    Light light;
    light.type = LightType::Environment;
    light.name = environment.name;
    light.source = environment.environment->source;
    scene.lights = {light};
    scene.display.background = glm::vec3(0.0f);
    return scene;
}

}  // namespace

std::vector<IrradianceErrorRow> measureIrradiance(const NamedEnvironment& named, int normalCount,
                                                  int referenceSamples) {
    const Environment& environment = *named.environment;
    const std::vector<glm::vec3> normals = spreadNormals(normalCount);
    const ExactIrradiance exactIrradiance(environment.image);
    std::vector<double> exact(normals.size());
    parallelFor(normals.size(), [&](size_t i) { exact[i] = luminance(glm::vec3(exactIrradiance.at(normals[i]))); });
    std::vector<IrradianceErrorRow> rows;
    auto add = [&](const std::string& method, auto irradiance) {
        std::vector<double> values(normals.size());
        for (size_t i = 0; i < normals.size(); ++i) {
            values[i] = luminance(irradiance(normals[i]));
        }
        rows.push_back(errorsOf(named.name, method, exact, values));
    };
    add("irradiance map " + std::to_string(kIrradianceFaceSize) + " cells " + std::to_string(kIrradianceCellSize) +
            " (as shipped)",
        [&](glm::vec3 n) { return sampleCubeLevel(environment.irradiance, n); });
    for (const auto& [face, cells] : {std::pair{16, 16}, std::pair{64, 16}, std::pair{32, 8}, std::pair{32, 32}}) {
        const CubeLevel map = irradianceCube(environment.image, face, cells);
        add("irradiance map " + std::to_string(face) + " cells " + std::to_string(cells),
            [&](glm::vec3 n) { return sampleCubeLevel(map, n); });
    }
    const ShCoefficients sh = projectSH(environment.image), windowed = windowSH(sh);
    add("SH 9 coefficients clamped at 0",
        [&](glm::vec3 n) { return glm::max(irradianceUnclamped(sh, n), glm::vec3(0.0f)); });
    add("SH 9 coefficients windowed and clamped",
        [&](glm::vec3 n) { return glm::max(irradianceUnclamped(windowed, n), glm::vec3(0.0f)); });
    // The Monte Carlo reference's own estimate: a white Lambert surface's diffuse lobe is E / pi.
    const EnvironmentDistribution distribution(environment.image);
    const ReferenceEnvironment reference{&environment, &distribution, 1.0f, 0.0f};
    std::vector<double> estimates(normals.size());
    parallelFor(normals.size(), [&](size_t i) {
        ReferenceOptions options;
        options.samples = referenceSamples;
        options.seed = 0x9E3779B97F4A7C15ull * (i + 1);
        options.specular = false;
        const shader::SurfaceMaterial white = shader::deriveSurfaceMaterial(glm::vec3(1.0f), 1.0f, 0.0f, 0.0f);
        estimates[i] = double(std::numbers::pi_v<float>) *
                       luminance(referenceRadiance(BrdfModelId::Epic, white, reference, {}, glm::vec3(0.0f), normals[i],
                                                   normals[i], options)
                                     .value);
    });
    rows.push_back(errorsOf(named.name, "reference " + std::to_string(referenceSamples) + " iterations", exact,
                            estimates));
    return rows;
}

const char* matteShapeName(MatteShape shape) {
    return shape == MatteShape::Cube ? "cube" : "sphere";
}

MatteRow measureMatte(const NamedEnvironment& named, MatteShape shape, const MatteOptions& matte) {
    const int size = matte.size, samples = matte.samples;
    const Scene scene = matteScene(named);
    const std::shared_ptr<const Mesh> mesh = shape == MatteShape::Cube ? turnedCube() : builtinMesh(MeshKind::Sphere);
    const PreparedScene prepared{scene, mesh, named.environment};
    Renderer renderer;
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.samples = 1;   // pixel centres, as the ground truth
    settings.environment = matte.shading;
    const HdrImage render = renderer.render(prepared, settings).hdr;
    settings.channel = *channelFromName("diffuse");
    const HdrImage diffuse = renderer.render(prepared, settings).hdr;
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, size, size);
    ReferenceRenderOptions referenceOptions;
    referenceOptions.samplesPerPixel = samples;
    const ReferenceImage reference =
        matte.referenceRender ? renderReference(prepared, surfaces, referenceOptions) : ReferenceImage{};
    // The truth with its diffuse lobe exact, its specular lobe by the same estimator.
    const ExactIrradiance exact(named.environment->image);
    const EnvironmentDistribution distribution(named.environment->image);
    const ReferenceEnvironment environment{named.environment.get(), &distribution, 1.0f, 0.0f};
    const shader::SurfaceMaterial material = surfaceMaterial(scene.material);
    std::vector<glm::dvec3> exactDiffuse(surfaces.samples.size());
    std::vector<ReferenceEstimate> specular(surfaces.samples.size());
    parallelFor(surfaces.samples.size(), [&](size_t i) {
        const ProbeSample& p = surfaces.samples[i];
        const glm::vec3 N = shader::safeNormalize(p.normal);
        exactDiffuse[i] = glm::dvec3(shader::Fd_Lambert(material.diffuseColor)) * exact.at(N);
        ReferenceOptions options;
        options.samples = samples;
        options.seed = 0xD1B54A32D192ED03ull * (i + 1);
        options.diffuse = false;
        specular[i] =
            referenceRadiance(BrdfModelId::Epic, material, environment, {}, p.position, N, p.toViewer, options);
    });
    std::vector<double> ratios, truthErrors, referenceRatios, referenceErrors, diffuseRatios;
    double referenceVariance = 0.0;
    for (size_t pixel = 0; pixel < surfaces.sampleOfPixel.size(); ++pixel) {
        const int32_t i = surfaces.sampleOfPixel[pixel];
        if (i < 0) {
            continue;
        }
        const double shown = luminance(&render.rgb[pixel * 3]);
        const double exactLobe = luminance(glm::vec3(exactDiffuse[size_t(i)]));
        const double truth = exactLobe + luminance(specular[size_t(i)].value);
        ratios.push_back(shown / std::max(truth, 1e-12));
        truthErrors.push_back(luminance(specular[size_t(i)].standardError) / std::max(truth, 1e-12));
        if (matte.referenceRender) {
            const double estimate = luminance(&reference.value.rgb[pixel * 3]);
            const double ratio = shown / std::max(estimate, 1e-12);
            const double error = luminance(&reference.standardError.rgb[pixel * 3]) / std::max(estimate, 1e-12);
            referenceRatios.push_back(ratio);
            referenceErrors.push_back(error);
            referenceVariance += ratio * ratio * error * error;
        }
        diffuseRatios.push_back(luminance(&diffuse.rgb[pixel * 3]) / std::max(exactLobe, 1e-12));
    }
    MatteRow row{named.name, matteShapeName(shape), std::string(environmentMethodName(matte.shading.method)),
                 int(ratios.size()), mean(ratios), percentile(ratios, 0.05),
                 percentile(ratios, 0.5), percentile(ratios, 0.95)};
    row.truthMedianRelativeError = percentile(truthErrors, 0.5);
    row.truthP95RelativeError = percentile(truthErrors, 0.95);
    row.referenceMeanRatio = mean(referenceRatios);
    row.referenceMeanRatioStandardError =
        matte.referenceRender ? std::sqrt(referenceVariance) / double(std::max<size_t>(ratios.size(), 1)) : std::nan("");
    row.referenceMedianRelativeError = percentile(referenceErrors, 0.5);
    row.diffuseMeanRatio = mean(diffuseRatios);
    row.diffuseP5 = percentile(diffuseRatios, 0.05);
    row.diffuseP95 = percentile(diffuseRatios, 0.95);
    return row;
}

HdrImage sunEnvironment(int width, float elevation, float radius) {
    const int height = width / 2;
    HdrImage image{width, height, std::vector<float>(size_t(width) * size_t(height) * 3)};
    const float e = glm::radians(elevation);
    const glm::vec3 sun(0.6f * std::cos(e), std::sin(e), -0.8f * std::cos(e));
    const float cosRadius = std::cos(glm::radians(radius));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const glm::vec3 d = shader::equirectToDirection(
                glm::vec2((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)));
            const glm::vec3 sky = d.y >= 0.0f ? glm::vec3(0.35f, 0.5f, 0.8f) * (0.6f + 0.4f * d.y)
                                              : glm::vec3(0.12f, 0.1f, 0.08f);
            const glm::vec3 value = glm::dot(d, sun) >= cosRadius ? glm::vec3(1.0f, 0.95f, 0.85f) * 1.0e4f * 0.5f : sky;
            std::copy(&value.x, &value.x + 3, &image.rgb[(size_t(y) * size_t(width) + size_t(x)) * 3]);
        }
    }
    return image;
}

std::string irradianceCsv(const std::vector<IrradianceErrorRow>& rows) {
    std::ostringstream csv;
    csv << "environment,method,mean_relative_error,max_relative_error,mean_signed_error\n";
    csv.precision(6);
    for (const IrradianceErrorRow& row : rows) {
        csv << row.environment << ",\"" << row.method << "\"," << row.meanRelativeError << "," << row.maxRelativeError
            << "," << row.meanSignedError << "\n";
    }
    return csv.str();
}

std::string matteCsv(const std::vector<MatteRow>& rows) {
    std::ostringstream csv;
    csv << "environment,shape,method,pixels,mean_ratio,p5,p50,p95,truth_median_rse,truth_p95_rse,reference_mean_ratio,"
           "reference_mean_ratio_se,reference_median_rse,diffuse_mean_ratio,diffuse_p5,diffuse_p95\n";
    csv.precision(6);
    for (const MatteRow& row : rows) {
        csv << row.environment << "," << row.shape << "," << row.method << "," << row.pixels << "," << row.meanRatio
            << "," << row.p5 << "," << row.p50 << "," << row.p95 << "," << row.truthMedianRelativeError << "," << row.truthP95RelativeError
            << "," << row.referenceMeanRatio << "," << row.referenceMeanRatioStandardError << ","
            << row.referenceMedianRelativeError << "," << row.diffuseMeanRatio << "," << row.diffuseP5 << ","
            << row.diffuseP95 << "\n";
    }
    return csv.str();
}

}  // namespace patina
