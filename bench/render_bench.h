#pragma once
// `patina bench-render`: what a frame costs the renderer, per path, against light count,
// resolution and triangle count (issue 6). Needs a current GL context. Times are medians of
// interleaved runs in one process; compare ratios, not absolute times, across machines.
#include <string>
#include <string_view>
#include <vector>

#include "image/chart.h"
#include "bench/csv_read.h"
#include "gl/renderer.h"
#include "scene/scene.h"

namespace patina {

struct RenderBenchOptions {
    bool quick = false;   // smaller frames, fewer lights and triangles (for CI)
    int runs = 7;         // timed runs per measurement after 2 warm-ups
    int width = 1920, height = 1080;
    int samples = 4;      // MSAA, as `patina render` draws
};

// Medians over the runs, in milliseconds.
struct FrameTiming {
    double gpu = 0.0;     // two GL_TIMESTAMP queries around the frame (Renderer::lastGpuMilliseconds)
    double cpu = 0.0;     // CPU time of the calling thread inside Renderer::draw (submission)
    double frame = 0.0;   // wall clock from draw to glFinish
    double readBack = 0.0;   // then reading the display image back as bytes (Renderer::readBack)
};

// The lights past the default scene's first 3: a ring in front of the sphere.
enum class AddedLights {
    Points,                  // windowed points with Karis's coefficients (1, 0, 1), the default
    PointsOtherCoefficients,  // the same with other coefficients, which a shader must read
    Directionals,
    Spheres,                 // sphere lights (Karis 2013's representative point), source radius 0.3
    Tubes,                   // tube lights of length 0.8 across the ring, source radius 0.05
};
// "point", "point-other-coefficients", "directional", "sphere", "tube" (the CSV's `added` column).
std::string_view addedLightsName(AddedLights added);

// What a light-count row measured: one of the renderer's paths, or the BRDF-only floor
// (bench/brdf_floor.h: the specialised path with the bench's own light code).
enum class BenchPath { Single, Multi, Specialised, BrdfFloor };
// "single", "multi", "specialised", "brdf-floor" (the CSV's `path` column).
std::string_view benchPathName(BenchPath path);
// The renderer's path that draws it (the floor is specialised).
RenderPath renderPathOf(BenchPath path);

struct LightCountRow {
    BenchPath path = BenchPath::Single;
    AddedLights added = AddedLights::Points;
    int lights = 0;
    FrameTiming time;
};

struct ScaleRow {
    // "resolution", "triangles", "flat-lights", "culling", "environment", "ambient-occlusion"
    // (the default scene over a floor without and with it), or "textured" and
    // "untextured" (a sphere with five maps, and without, as a model; path by path), and "base
    // colour map" between them (its base colour map alone); "layers" (the gltf sphere bare and
    // with each layer); "shadows" (the sphere over the floor under one light of each type, path
    // by path: "single-point" and "single-point-shadowed", ...)
    std::string axis;
    int width = 0, height = 0;
    size_t triangles = 0;
    FrameTiming time;     // the default scene's three lights
    // "single"; on the flat-lights axis "specialised-flat" or "specialised-block" (specialised
    // with its lights as flat inputs or from the block: what flatLightsPay weighs); on the
    // culling axis "single", "multi" and the same drawing every face ("single-every-face"); on
    // the environment axis the studio alone or one directional light alone, by path and method.
    std::string path = "single";
    int lights = 3;       // the environment axis: 1
};

// Loading a model with `maps` PNG maps of side x side (medians, seconds).
struct TexturedLoadRow {
    int maps = 0, side = 0;
    double pngBytes = 0.0;        // the image files' size
    double coldSeconds = 0.0;     // through a new AssetCache
    double cachedSeconds = 0.0;   // through the same one again
};

struct RenderBenchResult {
    std::vector<LightCountRow> lightRows;
    std::vector<ScaleRow> scaleRows;
    int width = 0, height = 0, samples = 0;
    size_t triangles = 0;   // of the default scene's mesh, which the light rows draw
    size_t gltfTriangles = 0;
    double gltfBytes = 0.0, gltfLoadSeconds = 0.0;   // a GLB of gltfTriangles, imported
    // Finding that mesh's hidden faces (hiddenFaces, as Renderer::setMesh does), and whether
    // it is closed.
    double hiddenFacesSeconds = 0.0;
    bool gltfClosed = false;
    // A 1024 x 512 HDRI made ready to light with: decoded and prefiltered with an empty disk
    // cache (cold), then decoded and read from that cache (warm); medians.
    std::string prefilterSource;
    int prefilterFaceSize = 0;
    double prefilterColdSeconds = 0.0, prefilterWarmSeconds = 0.0;
    std::vector<TexturedLoadRow> texturedLoads;   // one map, then eight
    std::string renderer;   // GL_RENDERER
    size_t flatLightSlots = 0;   // lights specialised takes as flat inputs (Renderer::flatLightSlots)
};

// The default scene's analytic lights (point, directional, hemisphere: its environment is
// measured on its own, the "environment" axis).
Scene analyticDefaultScene();
// That scene with `lights` lights: its first `lights` for up to 3, then the ring.
Scene renderBenchScene(int lights, AddedLights added = AddedLights::Points);

// `scene` with the `gltf` model and the layers rows' `layer`: "clearcoat", a car paint's coat
// (factor 1, roughness 0.1), "sheen", a velvet's sheen (colour 0.8, 0.2, 0.4, roughness 0.5),
// "transmission", a clear glass's (factor 1), "anisotropy", a brushed finish (strength 0.8,
// rotation 0.5), "specular", a tinted F0 (tint 2, 1, 0.5, weight 0.8), "iridescence", a thin film
// (strength 1, ior 1.3, 400 nm), or "" none.
Scene withBenchLayer(Scene scene, std::string_view layer);

RenderBenchResult runRenderBench(const RenderBenchOptions& options);

struct TargetCheck {
    std::string name;       // what is compared, e.g. "single / multi at 8 lights"
    double value = 0.0, bound = 0.0;
    bool met = false;       // value <= bound
};
// Issue 6's targets as ratios of this run's frame times; where the run measured area lights,
// their cost per added light against a point light's (issue 19: a small multiple of it).
std::vector<TargetCheck> renderBenchTargets(const RenderBenchResult& result);

std::string renderBenchCsv(const RenderBenchResult& result);
// renderBenchCsv's rows back, with the frame size and triangles of its light rows: what
// `patina chart render` redraws the two charts from. The CSV does not record the MSAA samples:
// the caller says them. Throws InputError naming the file.
RenderBenchResult parseRenderBenchCsv(const CsvFile& csv, int samples);
std::string targetsCsv(const std::vector<TargetCheck>& targets);
// Frame time against light count, a line per path and the floor dashed.
Chart renderBenchLightChart(const RenderBenchResult& result);
// Frame time against pixels and against triangles.
Chart renderBenchScaleChart(const RenderBenchResult& result);

}  // namespace patina
