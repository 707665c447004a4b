#include "bench/render_bench.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <numbers>
#include <tuple>

#include <epoxy/gl.h>

#include "environment/builtin_environments.h"
#include "environment/environment.h"
#include "shading/brdf_models.h"
#include "environment/equirect.h"
#include "gltf/export.h"
#include "gltf/model_export.h"
#include "environment/environment_files.h"
#include "gl/gpu_prefilter.h"
#include "assets/prepare_scene.h"
#include "files/file_bytes.h"
#include "files/input_error.h"
#include "geometry/hidden_faces.h"
#include "geometry/mesh.h"
#include "geometry/tangents.h"
#include "bench/brdf_floor.h"
#include "io/temporary_folder.h"
#include "bench/timing.h"

namespace patina {

namespace {
using Clock = std::chrono::steady_clock;

double threadCpuMilliseconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) * 1e3 + double(now.tv_nsec) * 1e-6;
}

struct Samples {
    std::vector<double> gpu, cpu, frame, readBack;
    FrameTiming medians() const { return {median(gpu), median(cpu), median(frame), median(readBack)}; }
};

// A renderer with two targets. Multi draws into one of its own: without MSAA it keeps a linear
// image to sum into and the others do not, so in one target every switch between them would
// allocate it again (and touch its pages first), 8-20 ms a multi frame that a user drawing
// multi never pays.
struct BenchRenderer : Renderer {
    RenderTarget multi, others;
};

// The bench's scenes without an environment name no file: their built-in mesh is all they need.
PreparedScene analyticPrepared(const Scene& scene) {
    return {scene, builtinMesh(scene.mesh), nullptr};
}

// One frame, drawn after the pipeline is idle so neither its timer query nor its wall time
// includes earlier work, then read back as `patina render` does (timed apart).
void timeFrame(BenchRenderer& renderer, const PreparedScene& scene, const RenderSettings& settings, Samples* into) {
    glFinish();
    renderer.lastGpuMilliseconds();   // collect the previous query so this draw is timed
    const Clock::time_point start = Clock::now();
    const double cpuStart = threadCpuMilliseconds();
    RenderTarget& target = settings.path == RenderPath::Multi ? renderer.multi : renderer.others;
    renderer.draw(scene, settings, target);
    const double cpu = threadCpuMilliseconds() - cpuStart;
    glFinish();
    const Clock::time_point drawn = Clock::now();
    renderer.readBack(target, false);
    const double readBack = std::chrono::duration<double, std::milli>(Clock::now() - drawn).count();
    if (into) {
        into->gpu.push_back(renderer.lastGpuMilliseconds());
        into->cpu.push_back(cpu);
        into->frame.push_back(std::chrono::duration<double, std::milli>(drawn - start).count());
        into->readBack.push_back(readBack);
    }
}

// Runs every measurement once per round, rounds interleaved, so slow drift of this machine's
// speed spreads over all of them instead of biasing one; two warm-up rounds compile shaders.
template <typename Each>
void interleaved(int runs, Each each) {
    for (int round = -2; round < runs; ++round) {
        each(round >= 0);
    }
}

// Frames of `scene` under each of `variants`, rounds interleaved: the medians, in order.
std::vector<FrameTiming> interleavedMedians(BenchRenderer& renderer, const PreparedScene& scene,
                                            const std::vector<RenderSettings>& variants, int runs) {
    std::vector<Samples> samples(variants.size());
    interleaved(runs, [&](bool keep) {
        for (size_t k = 0; k < variants.size(); ++k) {
            timeFrame(renderer, scene, variants[k], keep ? &samples[k] : nullptr);
        }
    });
    std::vector<FrameTiming> medians;
    for (Samples& each : samples) {
        medians.push_back(each.medians());
    }
    return medians;
}

// A sphere of about `triangles` triangles (2 rings x segments, segments = 2 rings).
Mesh sphereOfAbout(size_t triangles) {
    const int rings = std::max(4, int(std::lround(std::sqrt(double(triangles) / 4.0))));
    return makeUvSphere(rings, 2 * rings);
}

size_t triangleCount(const Mesh& mesh) {
    return mesh.indices.size() / 3;
}

const FrameTiming* findLights(const RenderBenchResult& result, BenchPath path, AddedLights added, int lights) {
    for (const LightCountRow& row : result.lightRows) {
        if (row.path == path && row.added == added && row.lights == lights) {
            return &row.time;
        }
    }
    return nullptr;
}

// Each path and kind of added light that bench-render measures against light count.
constexpr std::pair<BenchPath, AddedLights> kLightSeries[] = {
    {BenchPath::Multi, AddedLights::Points},       {BenchPath::Single, AddedLights::Points},
    {BenchPath::Specialised, AddedLights::Points}, {BenchPath::BrdfFloor, AddedLights::Points},
    {BenchPath::Single, AddedLights::Directionals}, {BenchPath::Single, AddedLights::PointsOtherCoefficients},
    {BenchPath::Specialised, AddedLights::PointsOtherCoefficients}, {BenchPath::Single, AddedLights::Spheres},
    {BenchPath::Specialised, AddedLights::Spheres},   {BenchPath::Single, AddedLights::Tubes},
    {BenchPath::Specialised, AddedLights::Tubes}};

// Every path with point lights added; single again with directional lights added (whose
// light arithmetic is the BRDF alone, so single's excess over the floor is its loop's cost);
// single and specialised again with points whose coefficients they must read. The floor's
// scene is the lights as directions, the same for all. The floor is also measured at as many
// lights as specialised takes as flat inputs (renderBenchTargets takes its slope up to there).
void measureLightCounts(BenchRenderer& renderer, const RenderBenchOptions& options, const RenderSettings& settings,
                        RenderBenchResult& result) {
    std::vector<int> counts = options.quick ? std::vector<int>{1, 3, 8, 16} : std::vector<int>{1, 3, 8, 16, 32};
    const int slots = int(result.flatLightSlots);
    const bool floorAtSlots =
        slots > 3 && slots < counts.back() && std::find(counts.begin(), counts.end(), slots) == counts.end();
    if (floorAtSlots) {
        counts.insert(std::upper_bound(counts.begin(), counts.end(), slots), slots);
    }
    auto measured = [&](BenchPath path, int count) {
        return path == BenchPath::BrdfFloor || !floorAtSlots || count != slots;
    };
    std::map<std::tuple<int, int, int>, Samples> samples;
    interleaved(options.runs, [&](bool keep) {
        for (int count : counts) {
            for (const auto& [path, added] : kLightSeries) {
                if (!measured(path, count)) {
                    continue;
                }
                const Scene scene = renderBenchScene(count, added);
                RenderSettings s = settings;
                s.path = renderPathOf(path);
                const bool floor = path == BenchPath::BrdfFloor;
                const Scene shown = floor ? brdfFloorScene(scene) : scene;
                timeFrame(renderer, analyticPrepared(shown), floor ? brdfFloorSettings(s) : s,
                          keep ? &samples[{int(path), int(added), count}] : nullptr);
            }
        }
    });
    for (const auto& [path, added] : kLightSeries) {
        for (int count : counts) {
            if (measured(path, count)) {
                result.lightRows.push_back({path, added, count, samples[{int(path), int(added), count}].medians()});
            }
        }
    }
}

// `mesh`: the default scene's.
void measureScale(BenchRenderer& renderer, const Mesh& mesh, const RenderBenchOptions& options,
                  const RenderSettings& settings, RenderBenchResult& result) {
    Scene scene = analyticDefaultScene();
    const std::vector<std::pair<int, int>> sizes =
        options.quick ? std::vector<std::pair<int, int>>{{256, 256}, {512, 512}}
                      : std::vector<std::pair<int, int>>{{512, 512}, {1280, 720}, {1920, 1080}, {2560, 1440}, {3840, 2160}};
    const std::vector<size_t> triangles =
        options.quick ? std::vector<size_t>{10'000, 100'000} : std::vector<size_t>{10'000, 100'000, 1'000'000};

    // One size after another: interleaved, every frame would reallocate the render targets.
    for (const auto& [width, height] : sizes) {
        RenderSettings s = settings;
        s.width = width;
        s.height = height;
        Samples samples;
        interleaved(options.runs,
                    [&](bool keep) { timeFrame(renderer, analyticPrepared(scene), s, keep ? &samples : nullptr); });
        result.scaleRows.push_back({"resolution", width, height, triangleCount(mesh), samples.medians()});
    }
    // A mesh upload per size is slow at 1M triangles: sizes one after another, not interleaved.
    // Specialised with and without flat lights too, interleaved with single: the cost per
    // triangle and the saving per pixel that flatLightsPay weighs.
    using FlatLights = RenderSettings::FlatLights;
    const std::tuple<const char*, RenderPath, FlatLights> kinds[] = {
        {"single", RenderPath::Single, FlatLights::WherePaying},
        {"specialised-flat", RenderPath::Specialised, FlatLights::Always},
        {"specialised-block", RenderPath::Specialised, FlatLights::Never}};
    std::vector<RenderSettings> variants;
    for (const auto& [path, passes, flatLights] : kinds) {
        variants.push_back(settings);
        variants.back().path = passes;
        variants.back().flatLightUse = flatLights;
    }
    for (size_t target : triangles) {
        const auto sphere = std::make_shared<const Mesh>(sphereOfAbout(target));
        const std::vector<FrameTiming> times =
            interleavedMedians(renderer, {scene, sphere, nullptr}, variants, options.runs);
        for (size_t k = 0; k < std::size(kinds); ++k) {
            result.scaleRows.push_back({k == 0 ? "triangles" : "flat-lights", settings.width, settings.height,
                                        triangleCount(*sphere), times[k], std::get<0>(kinds[k])});
        }
    }
}

// Single and multi on the default scene with its sphere's hidden faces culled and drawn
// (RenderSettings::cullHiddenFaces), interleaved: what culling saves.
void measureCulling(BenchRenderer& renderer, const RenderBenchOptions& options, const RenderSettings& settings,
                    RenderBenchResult& result) {
    const Scene scene = analyticDefaultScene();
    const std::tuple<const char*, RenderPath, bool> kinds[] = {{"single", RenderPath::Single, true},
                                                             {"single-every-face", RenderPath::Single, false},
                                                             {"multi", RenderPath::Multi, true},
                                                             {"multi-every-face", RenderPath::Multi, false}};
    std::vector<RenderSettings> variants;
    for (const auto& [path, passes, cull] : kinds) {
        variants.push_back(settings);
        variants.back().path = passes;
        variants.back().cullHiddenFaces = cull;
    }
    const std::vector<FrameTiming> times = interleavedMedians(renderer, analyticPrepared(scene), variants, options.runs);
    for (size_t k = 0; k < std::size(kinds); ++k) {
        result.scaleRows.push_back({"culling", settings.width, settings.height, result.triangles, times[k],
                                    std::get<0>(kinds[k])});
    }
}

// The brdf-model and layers rows' environment: the built-in studio, prefiltered.
std::shared_ptr<const Environment> preparedStudio() {
    return prepareEnvironment(*builtinEnvironment("studio"), builtinSource("studio"), {}, {}, prefilterCubeOnGpu);
}

// Their scenes: the sphere under 8 lights, or the default scene with its environment.
Scene brdfBenchScene(bool environment) {
    return environment ? defaultScene() : renderBenchScene(8);
}

// The specialised path at 8 lights and under the default scene's environment, the sphere shaded
// with each BRDF model a file's material may have: the seed's epic and glTF's (issue 35: within
// 10% of epic's frame).
void measureBrdfModels(BenchRenderer& renderer, const RenderBenchOptions& options, const RenderSettings& settings,
                       RenderBenchResult& result) {
    RenderSettings specialised = settings;
    specialised.path = RenderPath::Specialised;
    const std::shared_ptr<const Environment> studio = preparedStudio();
    for (const bool environment : {false, true}) {
        for (const BrdfModelId model : {BrdfModelId::Epic, BrdfModelId::Gltf}) {
            Scene scene = brdfBenchScene(environment);
            scene.material.model = model;
            const PreparedScene prepared{scene, builtinMesh(scene.mesh), environment ? studio : nullptr};
            const FrameTiming time = interleavedMedians(renderer, prepared, {specialised}, options.runs).front();
            result.scaleRows.push_back({"brdf-model", settings.width, settings.height, result.triangles, time,
                                        "specialised-" + std::string(brdfModel(model).name) +
                                            (environment ? "-default-scene" : ""),
                                        environment ? int(scene.lights.size()) : 8});
        }
    }
}

// The layers of the `gltf` model (issue 36: "cost only where used"), on the specialised path as
// the brdf-model rows: the gltf sphere bare, with KHR_materials_clearcoat's coat (factor 1,
// roughness 0.1, a car paint's), with KHR_materials_sheen's sheen (a velvet's colour 0.8, 0.2,
// 0.4 at roughness 0.5), with KHR_materials_transmission's factor 1 (a clear glass) and with
// KHR_materials_anisotropy's strength 0.8 (a brushed finish), with KHR_materials_specular's
// tint (2, 1, 0.5) and weight 0.8 (a gem-bright tinted plastic) and with
// KHR_materials_iridescence's film (strength 1, ior 1.3, 400 nm), rounds interleaved, under 8 lights and in the default scene with its
// environment. The bare material's program has no instruction of either layer (shade.frag's
// PATINA_CLEARCOAT and PATINA_SHEEN are keys of its program; compare_outputs draws it to the
// byte); its frame here, interleaved with the layered ones, against the brdf-model row's of the
// same run is the target that it costs what it did.
void measureLayers(BenchRenderer& renderer, const RenderBenchOptions& options, const RenderSettings& settings,
                   RenderBenchResult& result) {
    RenderSettings specialised = settings;
    specialised.path = RenderPath::Specialised;
    const std::shared_ptr<const Environment> studio = preparedStudio();
    for (const bool environment : {false, true}) {
        const char* const kLayers[] = {"", "clearcoat", "sheen", "transmission", "anisotropy", "specular", "iridescence"};
        std::vector<Scene> scenes;   // PreparedScene holds its scene by reference: all made first
        for (const char* layer : kLayers) {
            scenes.push_back(withBenchLayer(brdfBenchScene(environment), layer));
        }
        std::vector<std::pair<std::string, PreparedScene>> layers;
        for (size_t k = 0; k < scenes.size(); ++k) {
            layers.emplace_back("specialised-gltf" + std::string(*kLayers[k] ? "-" : "") + kLayers[k] +
                                    (environment ? "-default-scene" : ""),
                                PreparedScene{scenes[k], builtinMesh(scenes[k].mesh), environment ? studio : nullptr});
        }
        std::vector<Samples> samples(layers.size());
        interleaved(options.runs, [&](bool keep) {
            for (size_t k = 0; k < layers.size(); ++k) {
                timeFrame(renderer, layers[k].second, specialised, keep ? &samples[k] : nullptr);
            }
        });
        for (size_t k = 0; k < layers.size(); ++k) {
            result.scaleRows.push_back({"layers", settings.width, settings.height, result.triangles,
                                        samples[k].medians(), layers[k].first,
                                        int(layers[k].second.scene.lights.size())});
        }
    }
}

// The shadows rows' light of `type` (issue 37 item 6), above and beside the default scene's
// sphere, outside its bounds as a point, sphere or tube light must be to cast (no cube maps).
Light shadowBenchLight(LightType type) {
    Light light;
    light.type = type;
    light.name = std::string(lightTypeName(type));
    light.direction = {-0.4f, -1.0f, -0.3f};
    light.intensity = type == LightType::Directional ? 2.0f : 30.0f;
    light.position = {1.5f, 3.5f, 1.5f};
    light.sourceRadius = type == LightType::Tube ? 0.05f : 0.3f;
    light.start = {1.0f, 3.5f, 1.5f};
    light.end = {2.0f, 3.5f, 1.5f};
    return light;
}

// Shadows per light type (issue 37 item 6): the default scene's sphere over the floor
// (display.ground "floor") under one light of each type and the default sky, with the light's
// shadow map and without, rounds interleaved, on the single and specialised paths.
void measureShadows(BenchRenderer& renderer, const RenderBenchOptions& options, const RenderSettings& settings,
                    RenderBenchResult& result) {
    const LightType kTypes[] = {LightType::Directional, LightType::Point, LightType::Sphere, LightType::Tube};
    std::vector<Scene> scenes;   // PreparedScene holds its scene by reference: all made first
    std::vector<std::string> names;
    for (const LightType type : kTypes) {
        for (const bool shadows : {false, true}) {
            Scene scene = analyticDefaultScene();
            std::erase_if(scene.lights, [](const Light& light) { return light.type != LightType::Hemisphere; });
            scene.lights.insert(scene.lights.begin(), shadowBenchLight(type));
            scene.lights.front().shadows = shadows;
            scene.display.ground = Ground::Floor;
            scenes.push_back(scene);
            names.push_back(std::string(lightTypeName(type)) + (shadows ? "-shadowed" : ""));
        }
    }
    for (const RenderPath path : {RenderPath::Single, RenderPath::Specialised}) {
        RenderSettings variant = settings;
        variant.path = path;
        std::vector<Samples> samples(scenes.size());
        interleaved(options.runs, [&](bool keep) {
            for (size_t k = 0; k < scenes.size(); ++k) {
                timeFrame(renderer, analyticPrepared(scenes[k]), variant, keep ? &samples[k] : nullptr);
            }
        });
        for (size_t k = 0; k < scenes.size(); ++k) {
            result.scaleRows.push_back({"shadows", settings.width, settings.height, result.triangles,
                                        samples[k].medians(), std::string(renderPathName(path)) + "-" + names[k],
                                        int(scenes[k].lights.size())});
        }
    }
}

// Ambient occlusion's frame (issue 37 items 2 and 6): the default scene's sphere over a floor,
// on the specialised path, without it and with it (its values baked once, before the rounds:
// the frame draws one more vertex attribute and the environment's diffuse apart from its
// specular), rounds interleaved.
void measureAmbientOcclusion(BenchRenderer& renderer, const RenderBenchOptions& options, const RenderSettings& settings,
                             RenderBenchResult& result) {
    RenderSettings specialised = settings;
    specialised.path = RenderPath::Specialised;
    Scene floor = defaultScene();
    floor.display.ground = Ground::Floor;
    Scene occluded = floor;
    occluded.display.ambientOcclusion = true;
    const std::shared_ptr<const Mesh> mesh = builtinMesh(floor.mesh);
    const std::shared_ptr<const Environment> studio = preparedStudio();
    const std::vector<std::pair<std::string, PreparedScene>> scenes{
        {"specialised-floor", PreparedScene{floor, mesh, studio}},
        {"specialised-floor-ambient-occlusion",
         PreparedScene{occluded, mesh, studio, nullptr,
                       std::make_shared<const AmbientOcclusion>(bakeAmbientOcclusion(*mesh, nullptr, true))}}};
    std::vector<Samples> samples(scenes.size());
    interleaved(options.runs, [&](bool keep) {
        for (size_t k = 0; k < scenes.size(); ++k) {
            timeFrame(renderer, scenes[k].second, specialised, keep ? &samples[k] : nullptr);
        }
    });
    for (size_t k = 0; k < scenes.size(); ++k) {
        result.scaleRows.push_back({"ambient-occlusion", settings.width, settings.height, result.triangles,
                                    samples[k].medians(), scenes[k].first, int(floor.lights.size())});
    }
}

// The default scene's sphere with spherical UVs and MikkTSpace tangents, drawn once for each
// material, with `images` maps of `side` x `side` busy pixels (the noise a PNG cannot shrink:
// the most a decoder has to do) dealt out five a material, in mapsOf's order.
Model texturedSphere(int side, int images) {
    Mesh sphere = *builtinMesh(MeshKind::Sphere);
    for (const glm::vec3& n : sphere.normals) {
        sphere.uv0.push_back({std::atan2(n.z, n.x) / (2.0f * std::numbers::pi_v<float>) + 0.5f,
                              std::acos(std::clamp(n.y, -1.0f, 1.0f)) / std::numbers::pi_v<float>});
    }
    Model model;
    model.primitives = {withTangents(std::move(sphere), 0)};
    for (int image = 0; image < images; ++image) {
        ModelImage pixels{"map " + std::to_string(image), side, side,
                          std::vector<uint8_t>(size_t(side) * size_t(side) * 4)};
        for (size_t i = 0; i < pixels.rgba.size(); ++i) {
            pixels.rgba[i] = uint8_t(((i + size_t(image)) * 2654435761u) >> 24 | 0x80);   // busy and bright
        }
        model.images.push_back(std::move(pixels));
        if (image % kCoreMapCount == 0) {
            ModelMaterial material;
            material.factors = defaultScene().material;
            material.emissiveFactor = glm::vec3(0.1f);
            material.name = "part " + std::to_string(model.materials.size());
            model.materials.push_back(material);
            model.draws.push_back({0, int(model.materials.size()) - 1, glm::mat4(1.0f), material.name});
        }
        mapsOf(model.materials.back())[size_t(image % kCoreMapCount)].slot->image = image;
    }
    return model;
}

// A textured asset's frame against the same asset untextured, each path: texturedSphere with
// five 1024 x 1024 maps (base colour, metallic-roughness, normal, occlusion, emissive), drawn as
// a one-item model; "base colour map", the same with its base colour map alone (where the
// specialised path's program for that one map pays off); untextured, the same model whose
// material has no maps.
void measureTextured(BenchRenderer& renderer, const RenderBenchOptions& options, const RenderSettings& settings,
                     RenderBenchResult& result) {
    Model textured = texturedSphere(options.quick ? 256 : 1024, kCoreMapCount);
    Model plain = textured;
    plain.materials[0] = ModelMaterial{};
    plain.materials[0].factors = textured.materials[0].factors;
    plain.images.clear();
    Model baseOnly = textured;
    for (const auto& map : mapsOf(baseOnly.materials[0])) {
        *map.slot = map.slot == &baseOnly.materials[0].baseColor ? *map.slot : TextureSlot{};
    }
    baseOnly.materials[0].emissiveFactor = glm::vec3(0.0f);
    const Scene scene = analyticDefaultScene();
    const auto texturedModel = std::make_shared<const Model>(std::move(textured));
    const auto baseOnlyModel = std::make_shared<const Model>(std::move(baseOnly));
    const auto plainModel = std::make_shared<const Model>(std::move(plain));
    const auto mesh = std::make_shared<const Mesh>(texturedModel->primitives[0]);
    for (const RenderPath path : {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised}) {
        RenderSettings variant = settings;
        variant.path = path;
        // One model a series: a model change uploads its images again, which is loading, not drawing.
        for (const auto& [name, model] : {std::pair{"textured", texturedModel}, std::pair{"base colour map", baseOnlyModel},
                                          std::pair{"untextured", plainModel}}) {
            const PreparedScene prepared{scene, mesh, nullptr, model};
            const std::vector<FrameTiming> times = interleavedMedians(renderer, prepared, {variant}, options.runs);
            result.scaleRows.push_back({name, settings.width, settings.height,
                                        texturedModel->primitives[0].indices.size() / 3, times[0],
                                        std::string(renderPathName(path))});
        }
    }
}

// Opening a textured model: texturedSphere with one map and with eight, 2048 x 2048 PNGs beside
// a .gltf, loaded through a new AssetCache (cold: read, parse, decode, tangents) and again
// through the same one (from the cache). Eight maps against one shows the decoding spread over
// the cores.
void measureTexturedLoad(const RenderBenchOptions& options, RenderBenchResult& result) {
    const TemporaryFolder folder("patina-bench-textured");
    const int side = options.quick ? 256 : 2048;
    for (const int maps : {1, 8}) {
        const std::filesystem::path file = folder.path() / ("maps" + std::to_string(maps) + ".gltf");
        exportGltfModel(file, texturedSphere(side, maps));
        TexturedLoadRow row{maps, side};
        for (const std::filesystem::directory_entry& entry : std::filesystem::directory_iterator(folder.path())) {
            if (entry.path().stem().string().starts_with(file.stem().string() + "_")) {
                row.pngBytes += double(entry.file_size());
            }
        }
        std::vector<double> cold, cached;
        for (int run = 0; run < (options.quick ? 1 : 3); ++run) {
            AssetCache assets;
            Clock::time_point start = Clock::now();
            const std::shared_ptr<const LoadedModel> model = assets.model(file);
            cold.push_back(std::chrono::duration<double>(Clock::now() - start).count());
            start = Clock::now();
            const std::shared_ptr<const LoadedModel> again = assets.model(file);
            cached.push_back(std::chrono::duration<double>(Clock::now() - start).count());
            if (model->model.images.size() != size_t(maps) || again != model) {
                throw std::runtime_error("the textured load bench's model did not load whole");
            }
        }
        row.coldSeconds = median(cold);
        row.cachedSeconds = median(cached);
        result.texturedLoads.push_back(row);
    }
}

// Export a big sphere as GLB and time loading it as a model opens (AssetCache::model: the file read,
// hashed, imported and flattened; what opening a heavy model costs).
void measureGltfLoad(const RenderBenchOptions& options, RenderBenchResult& result) {
    const Mesh mesh = sphereOfAbout(options.quick ? 40'000 : 1'000'000);
    const TemporaryFolder folder("patina-bench-gltf");
    const std::filesystem::path file = folder.path() / "sphere.glb";
    exportGltf(file, mesh, defaultScene().material);
    result.gltfBytes = double(std::filesystem::file_size(file));
    std::vector<double> seconds, hiddenSeconds;
    for (int run = 0; run < (options.quick ? 1 : 3); ++run) {
        Clock::time_point start = Clock::now();
        AssetCache assets;   // a cold load each run
        const std::shared_ptr<const LoadedModel> imported = assets.model(file);
        seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
        result.gltfTriangles = triangleCount(imported->mesh);
        start = Clock::now();
        result.gltfClosed = hiddenFaces(imported->mesh) != HiddenFaces::None;
        hiddenSeconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    result.gltfLoadSeconds = median(seconds);
    result.hiddenFacesSeconds = median(hiddenSeconds);
}
}  // namespace

std::string_view benchPathName(BenchPath path) {
    switch (path) {
    case BenchPath::Single: return renderPathName(RenderPath::Single);
    case BenchPath::Multi: return renderPathName(RenderPath::Multi);
    case BenchPath::Specialised: return renderPathName(RenderPath::Specialised);
    case BenchPath::BrdfFloor: return "brdf-floor";
    }
    return "single";
}

RenderPath renderPathOf(BenchPath path) {
    switch (path) {
    case BenchPath::Multi: return RenderPath::Multi;
    case BenchPath::Specialised:
    case BenchPath::BrdfFloor: return RenderPath::Specialised;
    case BenchPath::Single: break;
    }
    return RenderPath::Single;
}

std::string_view addedLightsName(AddedLights added) {
    switch (added) {
    case AddedLights::Points: return "point";
    case AddedLights::PointsOtherCoefficients: return "point-other-coefficients";
    case AddedLights::Directionals: return "directional";
    case AddedLights::Spheres: return "sphere";
    case AddedLights::Tubes: return "tube";
    }
    return "point";
}

Scene analyticDefaultScene() {
    Scene scene = defaultScene();
    std::erase_if(scene.lights, [](const Light& light) { return light.type == LightType::Environment; });
    return scene;
}

Scene withBenchLayer(Scene scene, std::string_view layer) {
    scene.material.model = BrdfModelId::Gltf;
    if (layer == "clearcoat") {
        scene.material.clearcoat = 1.0f;
        scene.material.clearcoatRoughness = 0.1f;
    } else if (layer == "sheen") {
        scene.material.sheenColor = {0.8f, 0.2f, 0.4f};
        scene.material.sheenRoughness = 0.5f;
    } else if (layer == "transmission") {
        scene.material.transmission = 1.0f;
    } else if (layer == "anisotropy") {
        scene.material.anisotropyStrength = 0.8f;
        scene.material.anisotropyRotation = 0.5f;
    } else if (layer == "specular") {
        scene.material.specularTint = {2.0f, 1.0f, 0.5f};
        scene.material.specularWeight = 0.8f;
    } else if (layer == "iridescence") {
        scene.material.iridescence = 1.0f;
    }
    return scene;
}

Scene renderBenchScene(int lights, AddedLights added) {
    Scene scene = analyticDefaultScene();
    if (lights <= int(scene.lights.size())) {
        scene.lights.resize(size_t(std::max(lights, 0)));
        return scene;
    }
    const int extra = lights - int(scene.lights.size());
    for (int i = 0; i < extra; ++i) {
        const float angle = 2.0f * std::numbers::pi_v<float> * (float(i) + 0.5f) / float(extra);
        Light light;
        const bool point = added != AddedLights::Directionals;
        light.type = point ? LightType::Point : LightType::Directional;
        light.name = "ring " + std::to_string(i + 1);
        light.position = {2.5f * std::cos(angle), 2.5f * std::sin(angle), 2.0f};
        light.direction = -light.position;
        light.range = 12.0f;
        // At the ring's distance (about 3.2) both give about the same light.
        light.attenuation = added == AddedLights::PointsOtherCoefficients ? glm::vec3(0.5f, 0.25f, 0.9f)
                                                                         : glm::vec3(1.0f, 0.0f, 1.0f);
        // The ring adds about one key light in all.
        light.intensity = (point ? 24.0f : 2.0f) / float(extra);
        if (added == AddedLights::Spheres) {
            light.type = LightType::Sphere;
            light.sourceRadius = 0.3f;
        } else if (added == AddedLights::Tubes) {
            light.type = LightType::Tube;
            const glm::vec3 across(-std::sin(angle), std::cos(angle), 0.0f);
            light.start = light.position - 0.4f * across;
            light.end = light.position + 0.4f * across;
            light.sourceRadius = 0.05f;
        }
        scene.lights.push_back(light);
    }
    return scene;
}

// The studio environment against one directional light on the default sphere, alone in the
// scene, interleaved: the split sum (and its measured variants) as a share of a frame.
void measureEnvironment(BenchRenderer& renderer, const RenderBenchOptions& options, const RenderSettings& settings,
                        RenderBenchResult& result) {
    Scene directional = analyticDefaultScene();
    directional.lights.resize(2);
    directional.lights.erase(directional.lights.begin());   // the cool fill alone
    Scene environment = defaultScene();
    std::erase_if(environment.lights, [](const Light& light) { return light.type != LightType::Environment; });
    AssetCache assets;
    std::vector<std::string> notes;   // the built-in studio has none
    const PreparedScene preparedDirectional = analyticPrepared(directional);
    const PreparedScene preparedEnvironment = prepareScene(environment, assets, notes, prefilterCubeOnGpu);
    struct Kind {
        const char* name;
        const PreparedScene* scene;
        RenderPath path;
        EnvironmentShading shading;
    };
    const Kind kinds[] = {{"single-directional", &preparedDirectional, RenderPath::Single, {}},
                          {"specialised-directional", &preparedDirectional, RenderPath::Specialised, {}},
                          {"single-environment", &preparedEnvironment, RenderPath::Single, {}},
                          {"specialised-environment", &preparedEnvironment, RenderPath::Specialised, {}},
                          {"single-environment-dominant", &preparedEnvironment, RenderPath::Single,
                           {EnvironmentMethod::Dominant, 1}},
                          {"single-environment-stochastic-16", &preparedEnvironment, RenderPath::Single,
                           {EnvironmentMethod::Stochastic, 16}}};
    std::vector<Samples> samples(std::size(kinds));
    interleaved(options.runs, [&](bool keep) {
        for (size_t k = 0; k < std::size(kinds); ++k) {
            RenderSettings s = settings;
            s.path = kinds[k].path;
            s.environment = kinds[k].shading;
            timeFrame(renderer, *kinds[k].scene, s, keep ? &samples[k] : nullptr);
        }
    });
    for (size_t k = 0; k < std::size(kinds); ++k) {
        result.scaleRows.push_back(
            {"environment", settings.width, settings.height, result.triangles, samples[k].medians(), kinds[k].name, 1});
    }
}

// Making a 1024 x 512 HDRI ready to light with (decode, prefilter, irradiance map, the disk
// cache written), then again from the disk cache alone, each in a cache folder of its own
// (PATINA_CACHE_DIR): Blender's studio.exr when installed, else an image of the built-in
// studio at that size as a Radiance file.
void measurePrefilter(const RenderBenchOptions& options, RenderBenchResult& result) {
    const TemporaryFolder folder("patina-bench-prefilter");
    std::filesystem::path source = "/usr/share/blender/datafiles/studiolights/world/studio.exr";
    if (!std::filesystem::is_regular_file(source)) {
        source = folder.path() / "studio.hdr";
        const HdrImage studio = *builtinEnvironment("studio");
        HdrImage large{1024, 512, std::vector<float>(size_t(1024) * 512 * 3)};
        for (int y = 0; y < large.height; ++y) {
            for (int x = 0; x < large.width; ++x) {
                const glm::vec3 d = shader::equirectToDirection(
                    glm::vec2((float(x) + 0.5f) / float(large.width), (float(y) + 0.5f) / float(large.height)));
                const glm::vec3 v = sampleEquirect(studio, d);
                std::copy(&v.x, &v.x + 3, &large.rgb[(size_t(y) * size_t(large.width) + size_t(x)) * 3]);
            }
        }
        writeFileAtomic(source, encodeRadianceHdr(large));
    }
    result.prefilterSource = source.string();
    const char* previous = std::getenv("PATINA_CACHE_DIR");
    const std::string kept = previous ? previous : "";
    std::vector<double> cold, warm;
    for (int run = 0; run < (options.quick ? 1 : 3); ++run) {
        const std::filesystem::path cache = folder.path() / ("cache" + std::to_string(run));
        setenv("PATINA_CACHE_DIR", cache.c_str(), 1);
        std::vector<std::string> warnings;
        for (std::vector<double>* times : {&cold, &warm}) {
            const Clock::time_point start = Clock::now();
            // A cache of its own each time: the second load reads the disk cache, not memory.
            const std::shared_ptr<const Environment> environment = AssetCache().environment(source.string(), warnings, {}, {}, prefilterCubeOnGpu);
            times->push_back(std::chrono::duration<double>(Clock::now() - start).count());
            result.prefilterFaceSize = environment->prefiltered.front().size;
        }
    }
    if (previous) {
        setenv("PATINA_CACHE_DIR", kept.c_str(), 1);
    } else {
        unsetenv("PATINA_CACHE_DIR");
    }
    result.prefilterColdSeconds = median(cold);
    result.prefilterWarmSeconds = median(warm);
}

RenderBenchResult runRenderBench(const RenderBenchOptions& options) {
    RenderBenchResult result;
    result.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    BenchRenderer renderer;
    result.flatLightSlots = renderer.flatLightSlots();
    RenderSettings settings;   // the defaults a render gets, at the bench's size
    settings.width = result.width = options.quick ? 480 : options.width;
    settings.height = result.height = options.quick ? 270 : options.height;
    settings.samples = result.samples = options.samples;
    settings.readHdr = false;   // as `patina render` without --hdr and the editor's viewport
    const Mesh& mesh = *builtinMesh(defaultScene().mesh);
    result.triangles = triangleCount(mesh);
    measureLightCounts(renderer, options, settings, result);
    measureCulling(renderer, options, settings, result);
    measureEnvironment(renderer, options, settings, result);
    measureBrdfModels(renderer, options, settings, result);
    measureLayers(renderer, options, settings, result);
    measureShadows(renderer, options, settings, result);
    measureAmbientOcclusion(renderer, options, settings, result);
    measureScale(renderer, mesh, options, settings, result);
    measureTextured(renderer, options, settings, result);
    measureGltfLoad(options, result);
    measureTexturedLoad(options, result);
    measurePrefilter(options, result);
    return result;
}

std::vector<TargetCheck> renderBenchTargets(const RenderBenchResult& result) {
    std::vector<TargetCheck> targets;
    // Wall time to glFinish, what a user waits for; the timer queries' GPU time is in the CSV
    // beside it (on llvmpipe 83-100% of it, as the rasteriser is the "GPU").
    auto gpu = [&](BenchPath path, int lights, AddedLights added = AddedLights::Points) {
        const FrameTiming* t = findLights(result, path, added, lights);
        return t ? t->frame : std::nan("");
    };
    auto add = [&](std::string name, double value, double bound) {
        targets.push_back({std::move(name), value, bound, value <= bound});
    };
    add("single / multi at 8 lights", gpu(BenchPath::Single, 8) / gpu(BenchPath::Multi, 8), 0.35);
    add("specialised / single, default scene (3 lights)", gpu(BenchPath::Specialised, 3) / gpu(BenchPath::Single, 3), 0.9);
    // Cost per added light from 8 lights to the most measured, against the floor's.
    int most = 8;
    for (const LightCountRow& row : result.lightRows) {
        most = std::max(most, row.lights);
    }
    auto perLight = [&](BenchPath path, AddedLights added) {
        return (gpu(path, most, added) - gpu(path, 8, added)) / double(most - 8);
    };
    // The floor's own cost per light from 3 lights to as many as take flat inputs (14 on
    // llvmpipe), where every one of its lights is flat when the renderer uses them; past the
    // slots the floor would pay the uniform gathers it is meant to leave out. 3 to 8 where the
    // GL has fewer slots or the floor was not measured at them.
    int floorTop = 8;
    for (const LightCountRow& row : result.lightRows) {
        if (row.path == BenchPath::BrdfFloor && row.lights > floorTop && row.lights <= int(result.flatLightSlots)) {
            floorTop = row.lights;
        }
    }
    const double floor = (gpu(BenchPath::BrdfFloor, floorTop, AddedLights::Points) -
                          gpu(BenchPath::BrdfFloor, 3, AddedLights::Points)) /
                         double(floorTop - 3);
    const std::string range =
        " (8 to " + std::to_string(most) + " lights; floor 3 to " + std::to_string(floorTop) + ")";
    add("single's cost per added directional light / the BRDF floor's" + range,
        perLight(BenchPath::Single, AddedLights::Directionals) / floor, 1.3);
    add("single's cost per added point light / the BRDF floor's" + range,
        perLight(BenchPath::Single, AddedLights::Points) / floor, 1.3);
    add("single's cost per added point light with other coefficients / the BRDF floor's" + range,
        perLight(BenchPath::Single, AddedLights::PointsOtherCoefficients) / floor, 1.3);
    add("specialised's cost per added point light / the BRDF floor's" + range,
        perLight(BenchPath::Specialised, AddedLights::Points) / floor, 1.3);
    add("specialised's cost per added point light with other coefficients / the BRDF floor's" + range,
        perLight(BenchPath::Specialised, AddedLights::PointsOtherCoefficients) / floor, 1.3);
    // glTF's BRDF against the seed's on the specialised path (issue 35: within 10%); the gltf
    // material without a layer, drawn beside the layered ones, against its brdf-model frame
    // (issue 36: a material without a layer costs what it did).
    for (const char* shown : {"", "-default-scene"}) {
        auto frame = [&](const char* axis, const std::string& name) {
            for (const ScaleRow& row : result.scaleRows) {
                if (row.axis == axis && row.path == "specialised-" + name + shown) {
                    return row.time.frame;
                }
            }
            return std::nan("");
        };
        const std::string scene = *shown ? "the default scene with its environment" : "8 lights";
        if (!std::isnan(frame("brdf-model", "epic"))) {
            add("specialised gltf / epic, " + scene, frame("brdf-model", "gltf") / frame("brdf-model", "epic"), 1.1);
        }
        if (!std::isnan(frame("layers", "gltf"))) {
            add("specialised gltf without layers, beside the layered frames / the brdf-model row's, " + scene,
                frame("layers", "gltf") / frame("brdf-model", "gltf"), 1.1);
        }
    }
    // Area lights against point lights, path by path (issue 19: "a small multiple").
    for (BenchPath path : {BenchPath::Single, BenchPath::Specialised}) {
        for (AddedLights added : {AddedLights::Spheres, AddedLights::Tubes}) {
            if (findLights(result, path, added, most)) {
                add(std::string(benchPathName(path)) + "'s cost per added " + std::string(addedLightsName(added)) +
                        " light / per added point light (8 to " + std::to_string(most) + " lights)",
                    perLight(path, added) / perLight(path, AddedLights::Points), 4.0);
            }
        }
    }
    return targets;
}

namespace {
constexpr const char* kRenderBenchHeader =
    "section,path,added,lights,width,height,triangles,gpu_ms,cpu_ms,frame_ms,read_back_ms";

// The enumerator whose name is `name`, by the names the CSV writes.
template <typename Enum, size_t N>
Enum named(const Enum (&values)[N], std::string_view (*nameOf)(Enum), const CsvLine& line, size_t column,
           const std::string& source) {
    for (const Enum value : values) {
        if (nameOf(value) == line.cells[column]) {
            return value;
        }
    }
    throw InputError(source + ":" + std::to_string(line.number) + ": unknown '" + line.cells[column] + "' in column " +
                     std::to_string(column + 1));
}
}  // namespace

std::string renderBenchCsv(const RenderBenchResult& result) {
    std::string csv = std::string(kRenderBenchHeader) + "\n";
    char line[256];
    for (const LightCountRow& row : result.lightRows) {
        std::snprintf(line, sizeof line, "lights,%s,%s,%d,%d,%d,%zu,%.4f,%.4f,%.4f,%.4f\n",
                      std::string(benchPathName(row.path)).c_str(), std::string(addedLightsName(row.added)).c_str(),
                      row.lights, result.width, result.height,
                      result.triangles, row.time.gpu, row.time.cpu, row.time.frame, row.time.readBack);
        csv += line;
    }
    for (const ScaleRow& row : result.scaleRows) {
        std::snprintf(line, sizeof line, "%s,%s,,%d,%d,%d,%zu,%.4f,%.4f,%.4f,%.4f\n", row.axis.c_str(),
                      row.path.c_str(), row.lights, row.width, row.height, row.triangles, row.time.gpu, row.time.cpu,
                      row.time.frame, row.time.readBack);
        csv += line;
    }
    return csv;
}

RenderBenchResult parseRenderBenchCsv(const CsvFile& csv, int samples) {
    constexpr BenchPath kPaths[] = {BenchPath::Single, BenchPath::Multi, BenchPath::Specialised, BenchPath::BrdfFloor};
    constexpr AddedLights kAdded[] = {AddedLights::Points, AddedLights::PointsOtherCoefficients,
                                      AddedLights::Directionals, AddedLights::Spheres, AddedLights::Tubes};
    RenderBenchResult result;
    result.samples = samples;
    for (const CsvLine& line : csvBody(csv, kRenderBenchHeader)) {
        expectCells(line, 11, csv.source);
        auto number = [&](size_t column) { return csvNumber(line, column, csv.source); };
        const FrameTiming time{number(7), number(8), number(9), number(10)};
        const int lights = int(number(3)), width = int(number(4)), height = int(number(5));
        const size_t triangles = size_t(number(6));
        if (line.cells[0] == "lights") {
            result.lightRows.push_back({named(kPaths, benchPathName, line, 1, csv.source),
                                        named(kAdded, addedLightsName, line, 2, csv.source), lights, time});
            result.width = width;   // every light row draws the same frame and mesh
            result.height = height;
            result.triangles = triangles;
        } else {
            result.scaleRows.push_back({line.cells[0], width, height, triangles, time, line.cells[1], lights});
        }
    }
    return result;
}

std::string targetsCsv(const std::vector<TargetCheck>& targets) {
    std::string csv = "target,value,bound,met\n";
    char line[320];
    for (const TargetCheck& t : targets) {
        std::snprintf(line, sizeof line, "\"%s\",%.4f,%.2f,%s\n", t.name.c_str(), t.value, t.bound,
                      t.met ? "yes" : "no");
        csv += line;
    }
    return csv;
}

Chart renderBenchLightChart(const RenderBenchResult& result) {
    char title[128];
    std::snprintf(title, sizeof title, "Frame time against lights, %dx%d, %dx MSAA", result.width, result.height,
                  result.samples);
    ChartPanel panel{title, "enabled lights (point lights added unless named)", "frame time to glFinish (ms, median)",
                     false, false, {}};
    size_t colour = 0;
    for (const auto& [path, added] : kLightSeries) {
        // Short enough for the legend: the axis says that point lights are added.
        std::string label = path == BenchPath::BrdfFloor ? "BRDF floor" : std::string(benchPathName(path));
        if (added != AddedLights::Points) {
            label = (path == BenchPath::Specialised ? "spec." : label) +
                    (added == AddedLights::Directionals ? ", directionals"
                     : added == AddedLights::Spheres    ? ", spheres"
                     : added == AddedLights::Tubes      ? ", tubes"
                                                        : ", other coeffs");
        }
        ChartSeries series{label, {}, colour++, true, true, path == BenchPath::BrdfFloor, {}, {}};
        for (const LightCountRow& row : result.lightRows) {
            if (row.path == path && row.added == added) {
                series.points.emplace_back(row.lights, row.time.frame);
            }
        }
        if (!series.points.empty()) {   // a run from before a series existed: no legend entry for nothing
            panel.series.push_back(series);
        }
    }
    return Chart{{panel}};
}

Chart renderBenchScaleChart(const RenderBenchResult& result) {
    Chart chart;
    for (const char* axis : {"resolution", "triangles"}) {
        const bool pixels = std::string(axis) == "resolution";
        ChartPanel panel{pixels ? "Frame time against resolution (3 lights, single)"
                                : "Frame time against triangles (3 lights, single)",
                         pixels ? "megapixels" : "triangles", "frame time to glFinish (ms, median)", !pixels, !pixels, {}};
        ChartSeries series{"single", {}, 1, true, true, false, {}, {}};
        for (const ScaleRow& row : result.scaleRows) {
            if (row.axis == axis) {
                series.points.emplace_back(pixels ? double(row.width) * row.height * 1e-6 : double(row.triangles),
                                           row.time.frame);
                series.pointLabels.push_back(pixels ? std::to_string(row.width) + "x" + std::to_string(row.height)
                                                    : std::to_string(row.triangles));
            }
        }
        panel.series.push_back(series);
        chart.panels.push_back(panel);
    }
    return chart;
}

}  // namespace patina
