#pragma once
// `patina bench`: what each BRDF model costs (GPU and CPU) against how wrong it is
// (implementation and physical accuracy). Needs a current GL context.
#include <string>
#include <vector>

#include "accuracy/accuracy.h"
#include "image/chart.h"
#include "bench/csv_read.h"

namespace patina {

struct BenchOptions {
    bool quick = false;   // a smaller version for CI
    int runs = 9;         // timed runs per measurement (median), after 2 warm-up runs
};

struct BenchRow {
    std::string model;
    double gpuNsPerFragmentLight = 0.0;   // (t(16 lights) - t(0 lights)) / (pixels * 16)
    double cpuNsPerEvaluation = 0.0;      // fp32 evaluateBrdf, single thread
    ErrorStats cpuImplementation;         // fp32 CPU vs the model in fp64
    ErrorStats gpuImplementation;         // fp32 GPU vs the model in fp64
    ErrorStats physical;                  // the model in fp64 vs reference in fp64
    double imageRelativeRmse = 0.0;       // default scene HDR, GPU, vs reference
};

struct BenchResult {
    std::vector<BenchRow> rows;
    size_t samples = 0;
    std::string renderer;   // GL_RENDERER
};

BenchResult runBench(const BenchOptions& options);
std::string benchCsv(const BenchResult& result);
// benchCsv's rows back (samples and renderer are not in it): what `patina chart bench` redraws
// benchChart from. Throws InputError naming the file.
BenchResult parseBenchCsv(const CsvFile& csv);
// x = cost (GPU, and CPU in a second panel), y = physical relative RMSE, log scales, points
// labelled, the Pareto front drawn.
Chart benchChart(const BenchResult& result);

}  // namespace patina
