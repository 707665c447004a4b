// The benchmarks' CSVs read back into the results their charts are built from (`patina chart`):
// what a run wrote parses back to the same text and the same chart, the CSVs in docs/ read back
// to themselves, bad rows are bad input naming file and line, and the command writes the charts.
#include <algorithm>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "bench/bench.h"
#include "bench/lighting_accuracy.h"
#include "bench/render_bench.h"
#include "bench/renderer_comparison.h"
#include "cli_runner.h"
#include "files/input_error.h"
#include "image/image.h"
#include "files/file_bytes.h"
#include "scratch_test.h"

namespace patina {
namespace {

std::string readText(const std::filesystem::path& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

// The same drawing, compared pixel by pixel (an SVG numbers its surfaces process-wide).
void expectSameChart(const Chart& a, const Chart& b) {
    const LdrImage imageA = chartToImage(a), imageB = chartToImage(b);
    EXPECT_EQ(imageA.width, imageB.width);
    EXPECT_EQ(imageA.height, imageB.height);
    EXPECT_TRUE(imageA.rgba == imageB.rgba);
}

BenchResult sampleBench() {
    BenchResult result;
    result.rows.push_back({"epic", 15.26, 18.98, {5.975e-07, 4.243e-06}, {6.852e-07, 1.746e-05}, {0.2891, 0.9311}, 0.01448});
    result.rows.push_back({"reference", 26.04, 41.7, {1e-07, 2e-06}, {3e-07, 4e-06}, {0.0, 0.0}, 0.0});
    return result;
}

LightingAccuracyResult sampleLighting() {
    LightingAccuracyResult result;
    result.width = result.height = lightingFrameSize(false);
    for (const char* environment : {"studio", "sunrise"}) {
        for (const char* method : {"split sum", "stochastic, 16 samples", "LUT 32x32 fp16"}) {
            for (float roughness : {0.05f, 0.5f}) {
                result.accuracy.rows.push_back({environment, method, 0.1f, roughness, 0.04f, 0.0168134 + roughness, 0.0013047});
            }
        }
    }
    result.costs = {{"split sum", {EnvironmentMethod::SplitSum, 1}, 13.711},
                    {"stochastic, 16 samples", {EnvironmentMethod::Stochastic, 16}, 48.747}};
    result.directionalFrameMs = 2.8943;
    return result;
}

RenderBenchResult sampleRenderBench() {
    RenderBenchResult result;
    result.width = 1920;
    result.height = 1080;
    result.samples = 4;
    result.triangles = 16384;
    result.lightRows = {{BenchPath::Multi, AddedLights::Points, 1, {48.1501, 2.568, 50.5923, 2.2808}},
                        {BenchPath::BrdfFloor, AddedLights::Points, 14, {35.1345, 2.3627, 35.4239, 2.0291}},
                        {BenchPath::Specialised, AddedLights::Tubes, 8, {29.1871, 1.9997, 29.99, 2.1714}}};
    result.scaleRows = {{"resolution", 512, 512, 16384, {17.8795, 1.4308, 18.6593, 0.2363}, "single", 3},
                        {"triangles", 1920, 1080, 99856, {94.116, 6.6623, 94.6135, 1.9185}, "single", 3},
                        {"flat-lights", 1920, 1080, 10000, {53.0071, 1.3748, 54.7352, 1.9985}, "specialised-flat", 3}};
    return result;
}

TEST(BenchCsv, BenchReadsBackToTheSameCsvAndChart) {
    const BenchResult written = sampleBench();
    const BenchResult read = parseBenchCsv({benchCsv(written), "bench.csv"});
    ASSERT_EQ(read.rows.size(), written.rows.size());
    EXPECT_EQ(read.rows[0].model, "epic");
    EXPECT_EQ(read.rows[0].physical.relativeRmse, 0.2891);
    EXPECT_EQ(benchCsv(read), benchCsv(written));
    expectSameChart(benchChart(read), benchChart(written));
}

TEST(BenchCsv, LightingReadsBackToTheSameCsvAndChart) {
    const LightingAccuracyResult written = sampleLighting();
    const LightingAccuracyResult read = parseLightingAccuracy({splitSumCsv(written.accuracy.rows), "split_sum.csv"},
                                                              {lightingCostCsv(written), "lighting_cost.csv"}, false);
    ASSERT_EQ(read.costs.size(), 2u);
    EXPECT_EQ(read.costs[1].shading.samples, 16);
    EXPECT_EQ(read.directionalFrameMs, 2.8943);
    EXPECT_EQ(splitSumCsv(read.accuracy.rows), splitSumCsv(written.accuracy.rows));
    EXPECT_EQ(lightingCostCsv(read), lightingCostCsv(written));
    expectSameChart(lightingAccuracyChart(read), lightingAccuracyChart(written));
}

TEST(BenchCsv, RenderBenchReadsBackToTheSameCsvAndCharts) {
    const RenderBenchResult written = sampleRenderBench();
    const RenderBenchResult read = parseRenderBenchCsv({renderBenchCsv(written), "render_bench.csv"}, 4);
    ASSERT_EQ(read.lightRows.size(), 3u);
    EXPECT_EQ(read.lightRows[2].added, AddedLights::Tubes);
    EXPECT_EQ(read.lightRows[1].path, BenchPath::BrdfFloor);
    EXPECT_EQ(read.width, 1920);
    EXPECT_EQ(read.scaleRows[2].path, "specialised-flat");
    EXPECT_EQ(renderBenchCsv(read), renderBenchCsv(written));
    expectSameChart(renderBenchLightChart(read), renderBenchLightChart(written));
    expectSameChart(renderBenchScaleChart(read), renderBenchScaleChart(written));
}

// compare_cycles.sh's rows: two scenes, each model held to the truth and to Cycles, and the
// noise rows (an image held to itself at fewer samples), which are no series.
std::vector<RendererDifference> sampleComparison() {
    std::vector<RendererDifference> rows;
    for (const char* scene : {"spheres", "BoxTextured"}) {
        const double s = scene[0] == 's' ? 1.0 : 2.0;
        rows.push_back({scene, "gltf", "reference", 3.25 * s, 1.5, 21120});
        rows.push_back({scene, "epic", "reference", 6.5 * s, 4.125, 21120});
        rows.push_back({scene, "cycles", "reference", 9.0, -7.75, 21120});
        rows.push_back({scene, "reference-quarter", "reference", 2.236, 0.0, 21120});
        rows.push_back({scene, "gltf", "cycles", 10.0 * s, 8.0, 21120});
        rows.push_back({scene, "epic", "cycles", 12.0 * s, 9.5, 21120});
        rows.push_back({scene, "cycles-quarter", "cycles", 1.5, 0.001, 21120});
    }
    return rows;
}

TEST(BenchCsv, RendererComparisonReadsBackToTheSameCsvAndChart) {
    const std::vector<RendererDifference> written = sampleComparison();
    const std::string csv = rendererComparisonCsv(written);
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "scene,image,against,mean_abs_srgb,mean_signed_srgb,pixels");
    const std::vector<RendererDifference> read = parseRendererComparison({csv, "cycles.csv"});
    ASSERT_EQ(read.size(), written.size());
    EXPECT_EQ(read[1].image, "epic");
    EXPECT_EQ(read[1].meanSigned, 4.125);
    EXPECT_EQ(read[13].pixels, 21120u);
    EXPECT_EQ(rendererComparisonCsv(read), csv);
    const Chart chart = rendererComparisonChart(read, "reference");
    expectSameChart(chart, rendererComparisonChart(written, "reference"));
    // One panel, held to Cycles: gltf and epic (cycles is held to the truth alone, the quarters
    // to their own image), then the diagonal from 0 to the largest distance.
    ASSERT_EQ(chart.panels.size(), 1u);
    const ChartPanel& panel = chart.panels[0];
    ASSERT_EQ(panel.series.size(), 3u);
    EXPECT_EQ(panel.series[0].label, "gltf");
    EXPECT_EQ(panel.series[1].label, "epic");
    ASSERT_EQ(panel.series[1].points.size(), 2u);
    EXPECT_EQ(panel.series[1].points[1], glm::dvec2(13.0, 24.0));   // BoxTextured: to the truth, to Cycles
    EXPECT_EQ(panel.series[1].pointLabels[1], "BoxTextured");
    EXPECT_EQ(panel.series[2].points.back(), glm::dvec2(24.0, 24.0));
    std::vector<RendererDifference> truthOnly(written.begin(), written.begin() + 4);
    EXPECT_THROW(rendererComparisonChart(truthOnly, "reference"), InputError);
}

// What the docs' charts are redrawn from: each CSV the writer wrote reads back to itself.
TEST(BenchCsv, TheDocsCsvsReadBackToThemselves) {
    const std::filesystem::path docs = std::filesystem::path(PATINA_SOURCE_DIR) / "docs";
    const std::string bench = readText(docs / "accuracy/bench.csv");
    EXPECT_EQ(benchCsv(parseBenchCsv({bench, "bench.csv"})), bench);
    for (const char* folder : {"performance/msaa1", "performance/msaa4"}) {
        const std::string render = readText(docs / folder / "render_bench.csv");
        EXPECT_EQ(renderBenchCsv(parseRenderBenchCsv({render, folder}, 1)), render) << folder;
    }
    const std::string splitSum = readText(docs / "lighting/split_sum.csv");
    const std::string cost = readText(docs / "lighting/lighting_cost.csv");
    const LightingAccuracyResult lighting = parseLightingAccuracy({splitSum, "split_sum.csv"}, {cost, "lighting_cost.csv"}, false);
    EXPECT_EQ(splitSumCsv(lighting.accuracy.rows), splitSum);
    EXPECT_EQ(lighting.costs.size() + 2, size_t(std::count(cost.begin(), cost.end(), '\n')));   // header, directional
    // scripts/compare_cycles.sh's, which docs/LIGHTING.md quotes and its chart is drawn from.
    const std::string cycles = readText(docs / "lighting/cycles/cycles.csv");
    const std::vector<RendererDifference> comparison = parseRendererComparison({cycles, "cycles.csv"});
    EXPECT_EQ(rendererComparisonCsv(comparison), cycles);
    EXPECT_FALSE(rendererComparisonChart(comparison, "reference").panels.empty());
}

TEST(BenchCsv, BadRowsAreBadInputNamingFileAndLine) {
    const std::string header = benchCsv({});
    try {
        parseBenchCsv({header + "epic,1,2,3,4,5,6,x,8,9\n", "bench.csv"});
        FAIL() << "a word where a number goes";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("bench.csv:2:"), std::string::npos) << error.what();
    }
    EXPECT_THROW(parseBenchCsv({"model,gpu\n", "bench.csv"}), InputError);
    EXPECT_THROW(parseBenchCsv({header + "epic,1,2\n", "bench.csv"}), InputError);
    const std::string render = renderBenchCsv({});
    EXPECT_THROW(parseRenderBenchCsv({render + "lights,single,laser,3,1,1,1,1,1,1,1\n", "r.csv"}, 1), InputError);
    const std::string comparison = rendererComparisonCsv({});
    try {
        parseRendererComparison({comparison + "spheres,gltf,reference,1.5,0.5,12\nspheres,epic,,1,1,1\n", "cycles.csv"});
        FAIL() << "an empty name";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("cycles.csv:3:"), std::string::npos) << error.what();
    }
    EXPECT_THROW(parseRendererComparison({comparison + "spheres,gltf,reference,1.5,0.5,12.5\n", "c.csv"}), InputError);
    EXPECT_THROW(parseRendererComparison({comparison + "spheres,gltf,reference,1.5,0.5\n", "c.csv"}), InputError);
}

class ChartCommand : public test::ScratchTest {};

TEST_F(ChartCommand, RedrawsTheChartsFromTheCsvsBesideThem) {
    write("bench.csv", benchCsv(sampleBench()));
    write("render_bench.csv", renderBenchCsv(sampleRenderBench()));
    test::CliRun run = test::runPatina("chart bench " + dir_.string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_GT(decodePng(readFileBytes(path("speed_accuracy.png"))).width, 0);
    EXPECT_TRUE(std::filesystem::exists(path("speed_accuracy.svg")));
    EXPECT_TRUE(std::filesystem::exists(path("speed_accuracy.pdf")));
    run = test::runPatina("chart render " + dir_.string() + " --msaa 4", dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    for (const char* file : {"render_lights.png", "render_scale.png"}) {
        EXPECT_GT(decodePng(readFileBytes(path(file))).width, 0) << file;
    }
    write("cycles.csv", rendererComparisonCsv(sampleComparison()));
    run = test::runPatina("chart cycles " + dir_.string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_GT(decodePng(readFileBytes(path("cycles.png"))).width, 0);
    EXPECT_TRUE(std::filesystem::exists(path("cycles.svg")));
    // The samples are not in the CSV, and a folder without the CSVs has nothing to draw.
    EXPECT_EQ(test::runPatina("chart render " + dir_.string(), dir_).exitCode, 3);
    EXPECT_EQ(test::runPatina("chart lighting " + dir_.string(), dir_).exitCode, 3);
}

}  // namespace
}  // namespace patina
