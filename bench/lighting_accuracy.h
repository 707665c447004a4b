#pragma once
// `patina lighting-accuracy`: what each way of lighting with an environment costs, in error
// against the ground truth (engine/accuracy/split_sum_accuracy.h) and in frame time on this
// machine's GPU, on one chart; and pictures: a roughness by metallic grid of spheres under each
// environment, split sum and ground truth side by side with the error map. Needs a current GL
// context. docs/LIGHTING.md presents the results.
#include <filesystem>
#include <string>
#include <vector>

#include "image/chart.h"
#include "accuracy/split_sum_accuracy.h"
#include "bench/csv_read.h"
#include "gl/environment_method.h"
#include "image/image.h"

namespace patina {

struct LightingCostRow {
    std::string method;   // as the error rows name it
    EnvironmentShading shading;
    double frameMs = 0.0;   // median, the sphere under the environment alone
};

struct LightingAccuracyResult {
    SplitSumAccuracy accuracy;
    std::vector<LightingCostRow> costs;
    double directionalFrameMs = 0.0;   // the same sphere under one directional light instead
    int width = 0, height = 0;
    std::string renderer;
};

LightingAccuracyResult runLightingAccuracy(const std::vector<NamedEnvironment>& environments, bool quick);
// The side of the frames timed (smaller for --quick), which the chart's cost axis names.
int lightingFrameSize(bool quick);

// CSV: method,frame_ms,mean_relative_error (over every environment and grid point), then one
// column of mean error per environment.
std::string lightingCostCsv(const LightingAccuracyResult& result);
// Cost against error (each environment a series), and the split sum's error by source against
// roughness and against NoV.
Chart lightingAccuracyChart(const LightingAccuracyResult& result);
// What lightingAccuracyChart draws, back from split_sum.csv (splitSumCsv) and lighting_cost.csv
// (its methods' frame times; the per-environment means are recomputed from the rows): what
// `patina chart lighting` redraws it from. `quick`: the CSVs are from a
// --quick run (the frame size is not in them). Throws InputError naming the file.
LightingAccuracyResult parseLightingAccuracy(const CsvFile& splitSum, const CsvFile& cost, bool quick);

// The grid of spheres under `environment` (roughness across, metallic 0 then 1 down): the split
// sum, the ground truth, and |split - truth| / truth through the heat ramp (black 0, pale yellow
// 25% or more), side by side, captioned. `samples`: ground-truth iterations per pixel.
LdrImage roughnessMetallicGrid(const NamedEnvironment& environment, int cellSize, int samples);

}  // namespace patina
