#pragma once
// `patina shadow-accuracy` (issue 37 item 5, docs/LIGHTING.md section 6): the shadow-mapped
// render (gl/shadow_maps.h) against the ground truth with visibility (reference/reference_render.h,
// Embree's shadow rays) by the light's size, the map's resolution and its bias. The scene: the
// built-in unit sphere over the floor (display.ground "floor"), seen from above, lit by one
// shadowed light alone (a directional light, or a sphere light of each radius at the same
// direction and distance 5 from the sphere's centre), no environment, so that every pixel's
// light is the shadowed light's. Both images are taken at the same pixel centres (the GPU with
// one sample a pixel), and only pixels where the ground truth's rasteriser sees the floor or
// the sphere count, split into the two.
#include <string>
#include <vector>

#include "image/chart.h"

namespace patina {

struct ShadowAccuracyOptions {
    int width = 320, height = 240;
    int referenceSamples = 128;   // the truth's iterations a pixel for a sphere light (a directional one is exact)
    std::vector<int> mapSizes{256, 512, 1024, 2048, 4096};
    std::vector<float> biasScales{0.0f, 0.5f, 1.0f, 2.0f, 4.0f};
    std::vector<float> sphereRadii{0.1f, 0.25f, 0.5f, 1.0f};   // 0 entries: the directional light alone
    bool directional = true;
};
// `quick`: a small image, three map sizes and biases, two sphere lights (for CI).
ShadowAccuracyOptions shadowAccuracyOptions(bool quick);

// The error of one region's radiance (luminance): sqrt(mean (render - truth)^2) and
// mean(render - truth), each over the truth's mean there (relative).
struct RegionError {
    int pixels = 0;
    double rmse = 0.0, meanError = 0.0;
};

struct ShadowAccuracyRow {
    std::string light;           // "directional" or "sphere"
    double sourceRadius = 0.0;   // a sphere light's radius (0: directional)
    int mapSize = 0;
    double biasScale = 0.0;
    RegionError floor, model;    // the shadowed render against the truth with visibility
    // The same render without shadows against the truth without visibility: the shading's own
    // error (a sphere light's representative point, docs/LIGHTING.md section 4), which the
    // shadows do not cause. The same in every row of a light.
    RegionError floorUnshadowed, modelUnshadowed;
    // The penumbra's width on the floor in world units, render and truth: along the line across
    // the shadow's middle at right angles to the light's way, from where the light's visibility
    // (the shadowed radiance over the unshadowed, each image's own) first exceeds 0.1 to where
    // it first reaches 0.9, the mean of the two sides. Resolved to about a pixel's footprint.
    double penumbraWidth = 0.0, truthPenumbraWidth = 0.0;
};

struct ShadowAccuracyResult {
    std::vector<ShadowAccuracyRow> rows;
    int width = 0, height = 0, referenceSamples = 0;
    double pixelFootprint = 0.0;   // a floor pixel's width in world units at the shadow's middle
};

// Needs a current GL context.
ShadowAccuracyResult measureShadowAccuracy(const ShadowAccuracyOptions& options);

// CSV: light,source_radius,map_size,bias_scale,floor_pixels,floor_rmse,floor_mean_error,
// model_pixels,model_rmse,model_mean_error,floor_rmse_unshadowed,model_rmse_unshadowed,
// penumbra_width,truth_penumbra_width
std::string shadowAccuracyCsv(const ShadowAccuracyResult& result);

// Four panels: the floor's error by map size (bias 1), the sphere's and the floor's by bias
// scale (the default map size), and the penumbra's width by the light's radius, render and truth.
Chart shadowAccuracyChart(const ShadowAccuracyResult& result);

}  // namespace patina
