#include "bench/bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <epoxy/gl.h>

#include "assets/prepare_scene.h"
#include "shading/cpu_shading.h"
#include "gl/gpu_prefilter.h"
#include "gl/gpu_probe.h"
#include "gl/renderer.h"
#include "bench/timing.h"

namespace patina {

namespace {
constexpr int kBenchLights = 16;
// The reference has no error against itself: on the log axis it sits at this floor.
constexpr double kErrorFloor = 1e-3;
constexpr const char* kBenchHeader =
    "model,gpu_ns_per_fragment_light,cpu_ns_per_evaluation,cpu_fp32_rel_rmse,cpu_fp32_max_rel,"
    "gpu_fp32_rel_rmse,gpu_fp32_max_rel,physical_rel_rmse,physical_max_rel,image_rel_rmse";

// The sphere fills the frame: every pixel shades, every light is in front.
Scene workloadScene(BrdfModelId model, int lights) {
    Scene scene = defaultScene();
    scene.material.model = model;
    scene.camera.position = {0.0f, 0.0f, 1.3f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fovYDegrees = 90.0f;
    scene.lights.clear();
    for (int i = 0; i < lights; ++i) {
        const float angle = 2.0f * std::numbers::pi_v<float> * float(i) / float(lights);
        Light light;
        light.type = LightType::Directional;
        light.direction = {0.4f * std::cos(angle), 0.4f * std::sin(angle), -1.0f};
        light.intensity = 0.1f;
        scene.lights.push_back(light);
    }
    return scene;
}

double gpuCost(Renderer& renderer, BrdfModelId model, int size, int runs) {
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.samples = 1;
    const Scene lit = workloadScene(model, kBenchLights), unlit = workloadScene(model, 0);
    const std::shared_ptr<const Mesh> sphere = builtinMesh(MeshKind::Sphere);   // no environment: nothing to load
    const double withLights = medianOf(runs, [&] { return renderer.timedDraw({lit, sphere, nullptr}, settings); });
    const double without = medianOf(runs, [&] { return renderer.timedDraw({unlit, sphere, nullptr}, settings); });
    return std::max(withLights - without, 0.0) * 1e6 / (double(size) * size * kBenchLights);
}

double cpuCost(BrdfModelId model, const AccuracySet& set, int runs) {
    std::vector<shader::SurfaceMaterial> materials;
    std::vector<glm::vec3> N, V, L;
    for (const AccuracySample& s : set.samples) {
        materials.push_back(surfaceMaterial(s.material));
        N.emplace_back(s.N);
        V.emplace_back(s.V);
        L.emplace_back(s.L);
    }
    volatile float sink = 0.0f;
    const double seconds = medianOf(runs, [&] {
        const auto start = std::chrono::steady_clock::now();
        float sum = 0.0f;
        for (size_t i = 0; i < materials.size(); ++i) {
            sum += evaluateBrdf(model, materials[i], N[i], V[i], L[i]).specular.x;
        }
        sink = sink + sum;
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    });
    return seconds * 1e9 / double(materials.size());
}

ErrorStats gpuImplementationError(GpuProbe& probe, BrdfModelId model, const AccuracySet& set) {
    ErrorAccumulator errors;
    for (size_t m = 0; m + 1 < set.materialStart.size(); ++m) {
        Material material = set.samples[set.materialStart[m]].material;
        material.model = model;
        const std::vector<glm::vec3> gpu = probe.evaluate(material, {accuracyLight()}, probeSamples(set, m));
        for (size_t i = 0; i < gpu.size(); ++i) {
            const AccuracySample& sample = set.samples[set.materialStart[m] + i];
            errors.add(glm::dvec3(gpu[i]), reflectedF64(model, sample));
        }
    }
    return errors.stats();
}

double imageError(const HdrImage& image, const HdrImage& reference) {
    double error = 0.0, total = 0.0;
    for (size_t i = 0; i < image.rgb.size(); ++i) {
        error += (double(image.rgb[i]) - reference.rgb[i]) * (double(image.rgb[i]) - reference.rgb[i]);
        total += double(reference.rgb[i]) * reference.rgb[i];
    }
    return total > 0 ? std::sqrt(error / total) : 0.0;
}
}  // namespace

BenchResult runBench(const BenchOptions& options) {
    const AccuracySet set = options.quick ? stratifiedAccuracySet(4, 3, 3, 128, 1)
                                          : stratifiedAccuracySet(8, 5, 5, 512, 1);
    const int runs = options.quick ? 3 : options.runs;
    const int size = options.quick ? 128 : 512;
    BenchResult result;
    result.samples = set.samples.size();
    result.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    Renderer renderer;
    GpuProbe probe;
    RenderSettings imageSettings;
    imageSettings.width = imageSettings.height = options.quick ? 128 : 256;
    Scene scene = defaultScene();
    scene.material.model = BrdfModelId::Reference;
    AssetCache assets;
    std::vector<std::string> notes;   // a built-in environment has none
    const PreparedScene prepared = prepareScene(scene, assets, notes, prefilterCubeOnGpu);   // the model changes below
    const HdrImage reference = renderer.render(prepared, imageSettings).hdr;
    for (const BrdfModelInfo& model : brdfModels()) {
        BenchRow row;
        row.model = std::string(model.name);
        row.cpuImplementation = cpuImplementationError(model.id, set);
        row.physical = physicalError(model.id, set);
        row.gpuImplementation = gpuImplementationError(probe, model.id, set);
        row.cpuNsPerEvaluation = cpuCost(model.id, set, runs);
        row.gpuNsPerFragmentLight = gpuCost(renderer, model.id, size, runs);
        scene.material.model = model.id;
        row.imageRelativeRmse = imageError(renderer.render(prepared, imageSettings).hdr, reference);
        result.rows.push_back(row);
    }
    return result;
}

std::string benchCsv(const BenchResult& result) {
    std::string csv = std::string(kBenchHeader) + "\n";
    char line[512];
    for (const BenchRow& r : result.rows) {
        std::snprintf(line, sizeof line, "%s,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g\n", r.model.c_str(),
                      r.gpuNsPerFragmentLight, r.cpuNsPerEvaluation, r.cpuImplementation.relativeRmse,
                      r.cpuImplementation.maxRelative, r.gpuImplementation.relativeRmse,
                      r.gpuImplementation.maxRelative, r.physical.relativeRmse, r.physical.maxRelative,
                      r.imageRelativeRmse);
        csv += line;
    }
    return csv;
}

BenchResult parseBenchCsv(const CsvFile& csv) {
    const std::string& source = csv.source;
    BenchResult result;
    for (const CsvLine& line : csvBody(csv, kBenchHeader)) {
        expectCells(line, 10, source);
        auto number = [&](size_t column) { return csvNumber(line, column, source); };
        BenchRow row;
        row.model = line.cells[0];
        row.gpuNsPerFragmentLight = number(1);
        row.cpuNsPerEvaluation = number(2);
        row.cpuImplementation.relativeRmse = number(3);
        row.cpuImplementation.maxRelative = number(4);
        row.gpuImplementation.relativeRmse = number(5);
        row.gpuImplementation.maxRelative = number(6);
        row.physical.relativeRmse = number(7);
        row.physical.maxRelative = number(8);
        row.imageRelativeRmse = number(9);
        result.rows.push_back(row);
    }
    return result;
}

Chart benchChart(const BenchResult& result) {
    Chart chart;
    auto panel = [&](const char* title, const char* xLabel, auto cost) {
        ChartPanel p{title, xLabel, "physical error: relative RMSE of f*NoL vs reference", true, true, {}};
        ChartSeries points{"models", {}, 0, false, true, false, {}, {}};
        for (const BenchRow& r : result.rows) {
            points.points.emplace_back(std::max(cost(r), 1e-3), std::max(r.physical.relativeRmse, kErrorFloor));
            points.pointLabels.push_back(r.physical.relativeRmse < kErrorFloor ? r.model + " (error 0)" : r.model);
        }
        // Pareto front: sorted by cost, keep each point cheaper-or-equal and more accurate than all before.
        std::vector<glm::dvec2> sorted = points.points;
        std::sort(sorted.begin(), sorted.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        ChartSeries front{"Pareto front", {}, 1, true, false, true, {}, {}};
        double best = INFINITY;
        for (const glm::dvec2& point : sorted) {
            if (point.y < best) {
                front.points.push_back(point);
                best = point.y;
            }
        }
        p.series = {front, points};
        chart.panels.push_back(p);
    };
    panel("GPU cost vs error", "GPU ns per fragment per light", [](const BenchRow& r) { return r.gpuNsPerFragmentLight; });
    panel("CPU cost vs error", "CPU ns per evaluation (fp32)", [](const BenchRow& r) { return r.cpuNsPerEvaluation; });
    return chart;
}

}  // namespace patina
