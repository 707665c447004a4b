// bench, stability, furnace and bench-render: their outputs exist, parse and have one row per
// model (or path and light count), and the shipped models are finite and non-negative
// everywhere in the stability grid.
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "shading/brdf_models.h"
#include "shading/half.h"
#include "cli_runner.h"
#include "image/image.h"
#include "scene/light_packing.h"
#include "bench/brdf_floor.h"
#include "bench/render_bench.h"
#include "scratch_test.h"
#include "accuracy/split_sum_accuracy.h"
#include "accuracy/stability.h"
#include "environment/environment.h"
#include "test_support.h"
#include "files/file_bytes.h"

namespace patina {
namespace {

// Rows of a CSV file split at commas, header first.
std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& path) {
    std::ifstream file(path);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(file, line)) {
        std::vector<std::string> cells;
        std::stringstream stream(line);
        std::string cell;
        while (std::getline(stream, cell, ',')) {
            cells.push_back(cell);
        }
        rows.push_back(cells);
    }
    return rows;
}

class AccuracyCommands : public test::ScratchTest {};

// area-accuracy: every light, lobe and method has rows, the ground truth is tight enough to
// tell them apart, and across the horizon Frostbite's exact illuminance beats Karis's centre
// (the reason it is offered). The outputs exist; a missing folder is bad input.
TEST_F(AccuracyCommands, AreaAccuracyMeasuresEveryMethodAgainstTheGroundTruth) {
    const test::CliRun run = test::runPatina("area-accuracy --quick --out-dir " + dir_.string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const auto rows = readCsv(path("area_accuracy.csv"));
    ASSERT_GT(rows.size(), 1u);
    ASSERT_EQ(rows[0].size(), 10u);
    std::map<std::string, int> perMethod;
    double karisAcross = 0.0, frostbiteAcross = 0.0;
    for (size_t i = 1; i < rows.size(); ++i) {
        ASSERT_EQ(rows[i].size(), rows[0].size());
        perMethod[rows[i][0] + " " + rows[i][1] + " " + rows[i][2]] += 1;
        const double error = std::stod(rows[i][7]), truthError = std::stod(rows[i][9]);
        EXPECT_TRUE(std::isfinite(error) && error >= 0.0) << "row " << i;
        EXPECT_LT(truthError, 0.1) << "row " << i;   // --quick: 256 iterations (the full run: below 0.01)
        if (rows[i][0] == "sphere" && rows[i][1] == "diffuse" && rows[i][6] == "1") {
            (rows[i][2] == "karis" ? karisAcross : frostbiteAcross) += error;
        }
    }
    for (const char* series : {"sphere specular karis-s/2d", "sphere specular karis-s/3d", "tube specular karis-s/2d",
                               "tube specular karis-s/3d", "sphere diffuse karis", "sphere diffuse frostbite",
                               "tube diffuse karis"}) {
        EXPECT_GT(perMethod[series], 0) << series;
    }
    EXPECT_GT(karisAcross, 0.0);
    EXPECT_LT(frostbiteAcross, 0.5 * karisAcross);
    EXPECT_EQ(readCsv(path("area_cost.csv")).size(), 5u);   // header, point, two spheres, tube
    for (const char* file : {"area_accuracy.svg", "area_accuracy.png", "area_spheres.png"}) {
        EXPECT_TRUE(std::filesystem::exists(path(file))) << file;
    }
    EXPECT_GT(decodePng(readFileBytes(path("area_spheres.png"))).width, 0);
    // A file where the folder should be fails at once, before the measurement.
    std::ofstream(path("a-file")) << "x";
    const test::CliRun file = test::runPatina("area-accuracy --quick --out-dir " + path("a-file").string(), dir_);
    EXPECT_EQ(file.exitCode, 3);
    EXPECT_NE(file.stderrText.find("not a folder"), std::string::npos) << file.stderrText;
}

// shadow-accuracy (issue 37 item 5): a row per light, map size and bias, the CSV and the charts.
TEST_F(AccuracyCommands, ShadowAccuracyWritesItsTableAndChart) {
    // A folder that is not there yet is made (a run of minutes used to end on it).
    const test::CliRun run = test::runPatina("shadow-accuracy --quick --out-dir " + path("new/folder").string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const auto rows = readCsv(path("new/folder/shadow_accuracy.csv"));
    ASSERT_EQ(rows.size(), 1u + 3u * 3u * 3u);   // --quick: the sun and two spheres, 3 sizes, 3 biases
    ASSERT_EQ(rows[0].size(), 14u);
    EXPECT_EQ(rows[0][5], "floor_rmse");
    for (size_t i = 1; i < rows.size(); ++i) {
        ASSERT_EQ(rows[i].size(), rows[0].size());
        EXPECT_TRUE(std::isfinite(std::stod(rows[i][5])) && std::stod(rows[i][5]) > 0.0) << "row " << i;
    }
    for (const char* file : {"shadow_accuracy.svg", "shadow_accuracy.pdf", "shadow_accuracy.png"}) {
        EXPECT_TRUE(std::filesystem::exists(path("new/folder") / file)) << file;
    }
}

// Every path at every light count, both scale axes, every target with a finite value, the
// charts. Times are not checked: benchmarks, not timed tests.
TEST_F(AccuracyCommands, BenchRenderWritesEveryPathTargetAndChart) {
    const test::CliRun run = test::runPatina("bench-render --quick --out-dir " + dir_.string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const auto rows = readCsv(path("render_bench.csv"));
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(rows[0][0], "section");
    std::map<std::string, int> perSeries;
    for (size_t i = 1; i < rows.size(); ++i) {
        ASSERT_EQ(rows[i].size(), rows[0].size());
        perSeries[rows[i][0] + " " + rows[i][1] + " " + rows[i][2]] += 1;
        for (size_t c = 7; c < rows[i].size(); ++c) {
            EXPECT_GT(std::stod(rows[i][c]), 0.0) << rows[0][c] << " in row " << i;
        }
    }
    for (const char* series : {"lights multi point", "lights single point", "lights specialised point",
                               "lights single directional", "lights single point-other-coefficients",
                               "lights specialised point-other-coefficients", "lights single sphere",
                               "lights specialised sphere", "lights single tube", "lights specialised tube"}) {
        EXPECT_EQ(perSeries[series], 4) << series;   // --quick: 1, 3, 8 and 16 lights
    }
    // The floor also at the flat-light slots, where they fall between (14 on llvmpipe).
    test::glContext();
    const int slots = int(Renderer().flatLightSlots());
    const bool between = slots > 3 && slots < 16 && slots != 8;
    EXPECT_EQ(perSeries["lights brdf-floor point"], between ? 5 : 4) << slots << " slots";
    EXPECT_EQ(perSeries["resolution single "], 2);
    EXPECT_EQ(perSeries["triangles single "], 2);
    EXPECT_EQ(perSeries["flat-lights specialised-flat "], 2);
    EXPECT_EQ(perSeries["flat-lights specialised-block "], 2);
    for (const char* series : {"culling single ", "culling single-every-face ", "culling multi ",
                               "culling multi-every-face ", "environment single-directional ",
                               "environment specialised-directional ", "environment single-environment ",
                               "environment specialised-environment ", "environment single-environment-dominant ",
                               "environment single-environment-stochastic-16 "}) {
        EXPECT_EQ(perSeries[series], 1) << series;
    }
    for (const char* path : {"single", "multi", "specialised"}) {   // a textured asset against itself untextured
        EXPECT_EQ(perSeries[std::string("textured ") + path + " "], 1) << path;
        EXPECT_EQ(perSeries[std::string("untextured ") + path + " "], 1) << path;
    }
    for (const char* series : {"brdf-model specialised-epic ", "brdf-model specialised-gltf ",
                               "brdf-model specialised-epic-default-scene ", "brdf-model specialised-gltf-default-scene "}) {
        EXPECT_EQ(perSeries[series], 1) << series;   // glTF's BRDF against the seed's, one row each
    }
    // Issue 36: each layer against the bare gltf.
    for (const char* layer : {"", "-clearcoat", "-sheen", "-transmission", "-anisotropy", "-specular", "-iridescence"}) {
        for (const char* shown : {"", "-default-scene"}) {
            const std::string series = std::string("layers specialised-gltf") + layer + shown + " ";
            EXPECT_EQ(perSeries[series], 1) << series;
        }
    }
    // Issue 37: each light type's frame with its shadow map and without, over the floor, path by path.
    for (const char* path : {"single-", "specialised-"}) {
        for (const char* light : {"directional", "point", "sphere", "tube"}) {
            for (const char* shadowed : {"", "-shadowed"}) {
                const std::string series = std::string("shadows ") + path + light + shadowed + " ";
                EXPECT_EQ(perSeries[series], 1) << series;
            }
        }
    }
    const std::string targets = read("render_targets.csv");
    for (const char* target : {"single / multi at 8 lights", "specialised / single", "per added directional light",
                               "single's cost per added point light /",
                               "single's cost per added point light with other coefficients",
                               "specialised's cost per added point light with other coefficients",
                               "single's cost per added sphere light / per added point light",
                               "specialised's cost per added tube light / per added point light", "separate renders",
                               "specialised gltf / epic, 8 lights", "specialised gltf / epic, the default scene",
                               "specialised gltf without layers, beside the layered frames / the brdf-model row's, 8 lights",
                               "specialised gltf without layers, beside the layered frames / the brdf-model row's, the default scene",
                               "peak RSS"}) {
        EXPECT_NE(targets.find(target), std::string::npos) << target;
    }
    EXPECT_EQ(targets.find("nan"), std::string::npos) << targets;
    EXPECT_GT(decodePng(readFileBytes(path("render_lights.png"))).width, 100);
    EXPECT_GT(decodePng(readFileBytes(path("render_scale.png"))).width, 100);
}

TEST(RenderBench, ScenesHaveTheAskedLightCountAndTheFloorOnlyDirections) {
    for (int count : {0, 1, 3, 8, 32}) {
        const Scene scene = renderBenchScene(count, AddedLights::Directionals);
        ASSERT_EQ(int(scene.lights.size()), count);
        for (const Light& light : brdfFloorScene(scene).lights) {
            EXPECT_EQ(light.type, LightType::Directional);
            EXPECT_GT(glm::length(light.direction), 0.0f);
        }
    }
    const Scene points = renderBenchScene(8);
    EXPECT_EQ(points.lights.back().type, LightType::Point);
    EXPECT_TRUE(hasKarisAttenuation(packLight(points.lights.back())));
    const Scene others = renderBenchScene(8, AddedLights::PointsOtherCoefficients);
    EXPECT_EQ(others.lights.back().type, LightType::Point);
    EXPECT_FALSE(hasKarisAttenuation(packLight(others.lights.back())));
    // Area lights with a size, so they pack as themselves, not as points.
    EXPECT_EQ(packLight(renderBenchScene(8, AddedLights::Spheres).lights.back()).type, shader::LIGHT_SPHERE);
    EXPECT_EQ(packLight(renderBenchScene(8, AddedLights::Tubes).lights.back()).type, shader::LIGHT_TUBE);
    EXPECT_EQ(points.lights[1].type, defaultScene().lights[1].type);   // the default scene's first
}

TEST(RenderBench, TargetsAreRatiosOfTheMedians) {
    RenderBenchResult result;
    result.flatLightSlots = 14;
    auto add = [&](BenchPath path, AddedLights added, int lights, double frame) {
        result.lightRows.push_back({path, added, lights, {0.0, 0.0, frame}});
    };
    add(BenchPath::Multi, AddedLights::Points, 8, 100.0);
    add(BenchPath::Single, AddedLights::Points, 8, 30.0);
    add(BenchPath::Single, AddedLights::Points, 3, 20.0);
    add(BenchPath::Specialised, AddedLights::Points, 3, 16.0);
    add(BenchPath::Single, AddedLights::Points, 16, 30.0 + 8 * 3.0);
    // The floor's cost per light is taken from 3 lights to the flat slots (14, all flat inputs),
    // 2 here; past them it grows faster (lights from the block), which the targets leave out.
    add(BenchPath::BrdfFloor, AddedLights::Points, 3, 4.0);
    add(BenchPath::BrdfFloor, AddedLights::Points, 8, 4.0 + 5 * 2.5);   // not a point of the slope
    add(BenchPath::BrdfFloor, AddedLights::Points, 14, 4.0 + 11 * 2.0);
    add(BenchPath::BrdfFloor, AddedLights::Points, 16, 26.0 + 2 * 3.0);
    add(BenchPath::Single, AddedLights::Directionals, 8, 20.0);
    add(BenchPath::Single, AddedLights::Directionals, 16, 20.0 + 8 * 2.4);
    add(BenchPath::Specialised, AddedLights::Points, 8, 20.0);
    add(BenchPath::Specialised, AddedLights::Points, 16, 20.0 + 8 * 2.8);
    add(BenchPath::Single, AddedLights::PointsOtherCoefficients, 8, 40.0);
    add(BenchPath::Single, AddedLights::PointsOtherCoefficients, 16, 40.0 + 8 * 4.4);
    add(BenchPath::Specialised, AddedLights::PointsOtherCoefficients, 8, 32.0);
    add(BenchPath::Specialised, AddedLights::PointsOtherCoefficients, 16, 32.0 + 8 * 3.6);
    std::vector<TargetCheck> targets = renderBenchTargets(result);
    ASSERT_EQ(targets.size(), 7u);   // no area lights measured: no area-light targets
    EXPECT_DOUBLE_EQ(targets[0].value, 0.3);
    EXPECT_TRUE(targets[0].met);
    EXPECT_DOUBLE_EQ(targets[1].value, 0.8);
    EXPECT_NEAR(targets[2].value, 1.2, 1e-12);   // directional: 2.4 / 2
    EXPECT_TRUE(targets[2].met);
    EXPECT_NEAR(targets[3].value, 1.5, 1e-12);   // point: 3 / 2
    EXPECT_FALSE(targets[3].met);
    EXPECT_NEAR(targets[4].value, 2.2, 1e-12);   // single, points with other coefficients
    EXPECT_NE(targets[4].name.find("single's cost per added point light with other"), std::string::npos);
    EXPECT_NEAR(targets[5].value, 1.4, 1e-12);
    EXPECT_NEAR(targets[6].value, 1.8, 1e-12);   // specialised, other coefficients: 3.6 / 2
    EXPECT_NE(targets[6].name.find("specialised's cost per added point light with other"), std::string::npos);
    // With spheres measured on single: their cost per added light over the point light's.
    add(BenchPath::Single, AddedLights::Spheres, 8, 35.0);
    add(BenchPath::Single, AddedLights::Spheres, 16, 35.0 + 8 * 7.5);
    targets = renderBenchTargets(result);
    ASSERT_EQ(targets.size(), 8u);
    EXPECT_NEAR(targets[7].value, 2.5, 1e-12);   // 7.5 / 3
    EXPECT_TRUE(targets[7].met);
}

TEST_F(AccuracyCommands, BenchWritesOneRowPerModelAndTheChart) {
    const test::CliRun run = test::runPatina("bench --quick --out-dir " + dir_.string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const auto rows = readCsv(path("bench.csv"));
    ASSERT_EQ(rows.size(), brdfModelCount() + 1);
    EXPECT_EQ(rows[0][0], "model");
    for (size_t i = 1; i < rows.size(); ++i) {
        ASSERT_EQ(rows[i].size(), rows[0].size());
        EXPECT_TRUE(brdfModelFromName(rows[i][0]).has_value()) << rows[i][0];
        for (size_t c = 1; c < rows[i].size(); ++c) {
            EXPECT_TRUE(std::isfinite(std::stod(rows[i][c]))) << rows[i][0] << " " << rows[0][c];
        }
    }
    // The reference has no physical error; every other model some.
    for (size_t i = 1; i < rows.size(); ++i) {
        const double physical = std::stod(rows[i][7]);
        EXPECT_EQ(physical == 0.0, rows[i][0] == "reference") << rows[i][0];
    }
    EXPECT_NE(read("speed_accuracy.svg").find("<svg"), std::string::npos);
    EXPECT_GT(decodePng(readFileBytes(path("speed_accuracy.png"))).width, 100);
}

TEST_F(AccuracyCommands, StabilityWritesTheTableAndAHeatMapPerModel) {
    const test::CliRun run = test::runPatina("stability --quick --out-dir " + dir_.string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const auto rows = readCsv(path("stability.csv"));
    ASSERT_EQ(rows.size(), 4 * brdfModelCount() + 1);   // fp64, fp32 CPU, fp16 CPU, fp32 GPU
    for (const BrdfModelInfo& model : brdfModels()) {
        EXPECT_TRUE(std::filesystem::exists(path("stability_" + std::string(model.name) + ".png"))) << model.name;
    }
}

// A white glass's row of material_furnace.csv: reflected + transmitted at or under 1 (the truth
// within its noise), the transmitted share there in both and most of it at normal incidence; up
// to roughness 0.25 the split sum's total within the truth's noise of it, and at mu = 1 its
// transmitted share too (rougher, the split sum keeps the multiple scattering the
// single-scattering BTDF loses; at mu = 0.25 its grazing reflection takes more than the truth's,
// as a bare dielectric's does: docs/SHADING.md S7).
void expectGlassFurnaceRow(const std::vector<std::string>& row, double splitSum, double truth, double se) {
    const double mu = std::stod(row[2]), roughness = std::stod(row[3]);
    const double splitThrough = std::stod(row[7]), truthThrough = std::stod(row[8]);
    const std::string where = "glass mu " + row[2] + " r " + row[3];
    EXPECT_LE(splitSum, 1.005) << where;
    EXPECT_LE(truth, 1.0 + 4.0 * se + 1e-3) << where;
    EXPECT_GT(splitThrough, 0.0) << where;
    EXPECT_GT(truthThrough, 0.0) << where;
    EXPECT_LE(splitThrough, splitSum) << where;
    EXPECT_LE(truthThrough, truth + 4.0 * se) << where;
    if (mu == 1.0) {
        EXPECT_GT(truthThrough, 0.5 * truth) << where;
    }
    if (roughness <= 0.25) {
        EXPECT_NEAR(splitSum, truth, 4.0 * se + 0.02) << where;
        if (mu == 1.0) {
            EXPECT_NEAR(splitThrough, truthThrough, 4.0 * se + 0.02) << where;
        }
    }
}

TEST_F(AccuracyCommands, FurnaceWritesCurvesForEveryModel) {
    const test::CliRun run = test::runPatina("furnace --quick --out-dir " + dir_.string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const auto rows = readCsv(path("furnace.csv"));
    EXPECT_EQ(rows.size(), brdfModelCount() * 2 * 11 + 1);   // two mu, 11 roughness steps
    EXPECT_TRUE(std::filesystem::exists(path("furnace.png")));
    // The whole material: glTF's BRDF at or under 1 in its split sum, and a white metal's truth;
    // the seed's epic over 1 for a white dielectric (its Lambert takes nothing for the specular).
    // A white thin-walled glass (issue 36): reflected + transmitted at or under 1 in both, most
    // of it through the wall, and the split sum on the truth where the wall is smooth.
    double epicDielectric = 0.0;
    size_t gltfRows = 0, glassRows = 0;
    for (const auto& row : readCsv(path("material_furnace.csv"))) {
        if (row[0] == "model") {
            continue;
        }
        const double splitSum = std::stod(row[4]), truth = std::stod(row[5]), se = std::stod(row[6]);
        if (row[0] == "gltf") {
            ++gltfRows;
            EXPECT_LE(splitSum, 1.005) << row[1] << " mu " << row[2] << " r " << row[3];
            if (row[1] == "white metal") {
                EXPECT_LE(truth, 1.0 + 4.0 * se + 1e-3) << row[1] << " mu " << row[2] << " r " << row[3];
            }
            if (row[1] == "white glass") {
                ++glassRows;
                expectGlassFurnaceRow(row, splitSum, truth, se);
            }
        }
        if (row[0] == "epic" && row[1] == "white dielectric") {
            epicDielectric = std::max(epicDielectric, splitSum);
        }
    }
    EXPECT_EQ(gltfRows, 3u * 2u * 5u);   // three materials, two mu, 5 roughness steps
    EXPECT_EQ(glassRows, 2u * 5u);
    EXPECT_GT(epicDielectric, 1.02);
    std::ofstream(path("not-a-folder")) << "x";   // a missing folder is made; a file is refused
    EXPECT_EQ(test::runPatina("furnace --out-dir " + path("not-a-folder").string(), dir_).exitCode, 3);
}

TEST(Stability, ShippedModelsAreFiniteAndNonNegativeEverywhere) {
    // What ships runs in fp32 (GPU) and fp64; fp16 is the study of where precision runs out.
    test::glContext();
    for (const StabilityRow& row : runStability(false)) {
        if (row.precision == Precision::Fp16Cpu) {
            continue;
        }
        EXPECT_EQ(row.grid.nan, 0u) << row.model << " " << precisionName(row.precision);
        EXPECT_EQ(row.grid.inf, 0u) << row.model << " " << precisionName(row.precision);
        EXPECT_EQ(row.grid.negative, 0u) << row.model << " " << precisionName(row.precision);
        EXPECT_EQ(row.specialCases.nan + row.specialCases.inf + row.specialCases.negative, 0u) << row.model;
    }
}

TEST(HalfPrecision, RoundsLikeBinary16) {
    EXPECT_EQ(roundToHalf(65504.0f), 65504.0f);                    // the largest half
    EXPECT_TRUE(std::isinf(roundToHalf(65520.0f)));                // halfway past it: infinity
    EXPECT_EQ(roundToHalf(1.0f + 1.0f / 1024.0f), 1.0f + 1.0f / 1024.0f);   // 10 fraction bits
    EXPECT_EQ(roundToHalf(1.0f + 1.0f / 2048.0f), 1.0f);          // a tie goes to even
    EXPECT_EQ(roundToHalf(1.0f + 3.0f / 2048.0f), 1.0f + 2.0f / 1024.0f);
    EXPECT_EQ(roundToHalf(std::ldexp(1.0f, -24)), std::ldexp(1.0f, -24));   // smallest subnormal
    EXPECT_EQ(roundToHalf(std::ldexp(1.0f, -26)), 0.0f);
    EXPECT_EQ(float(Half(0.1f) + Half(0.2f)), roundToHalf(roundToHalf(0.1f) + roundToHalf(0.2f)));
}

TEST(HalfPrecision, FloorsAndErrorsShowInTheStabilityTable) {
    test::glContext();
    double halfError = 0.0, floatError = 0.0;
    for (const StabilityRow& row : runStability(true)) {
        if (row.model == "epic" && row.precision == Precision::Fp16Cpu) {
            halfError = row.grid.maxRelativeError;
        }
        if (row.model == "epic" && row.precision == Precision::Fp32Cpu) {
            floatError = row.grid.maxRelativeError;
        }
    }
    // Half has 11 significant bits to float's 24: its error is orders of magnitude larger.
    EXPECT_GT(halfError, 100.0 * floatError);
    EXPECT_GT(halfError, 1e-3);
}

}  // namespace
}  // namespace patina

namespace patina {
namespace {

class LightingAccuracy : public test::ScratchTest {};

TEST(SplitSumAccuracy, AUniformEnvironmentIsWhereTheSplitSumIsExact) {
    // Under radiance 1 everywhere LD is 1 at every mip and every direction: what is left is the
    // table against the integral, so every error source but the LUT's is ~0 and the split sum's
    // total is small; under the studio N = V costs far more. The measurement tells them apart.
    SplitSumAccuracyOptions options;
    options.quick = true;
    options.referenceSamples = 8192;   // the truth's own noise well below what is measured
    const SplitSumAccuracy white =
        measureSplitSum({{"white", test::madeEnvironment("builtin:white")}}, options);
    EXPECT_LT(meanError(white.rows, "split sum"), 0.01);
    EXPECT_LT(meanError(white.rows, "mip quantisation (chain against exact LD)"), 1e-4);
    EXPECT_LT(meanError(white.rows, "N = V and the split (exact LD and AB)"), 0.01);
    const SplitSumAccuracy studio =
        measureSplitSum({{"studio", test::madeEnvironment("builtin:studio")}}, options);
    EXPECT_GT(meanError(studio.rows, "N = V and the split (exact LD and AB)"),
              10.0 * meanError(white.rows, "N = V and the split (exact LD and AB)"));
}

TEST_F(LightingAccuracy, WritesTheTablesTheChartAndTheGrid) {
    const test::CliRun run =
        test::runPatina("lighting-accuracy --quick --environment builtin:white --out-dir " + dir_.string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    for (const char* file : {"split_sum.csv", "lighting_cost.csv", "lighting_accuracy.svg",
                             "lighting_accuracy.png", "grid_white.png", "area_accuracy.csv", "area_spheres.png"}) {
        EXPECT_TRUE(std::filesystem::is_regular_file(path(file))) << file;
    }
    const auto costs = readCsv(path("lighting_cost.csv"));
    ASSERT_GE(costs.size(), 4u);
    EXPECT_EQ(costs[0][0], "method");
    EXPECT_EQ(costs[1][0], "\"split sum\"");
    EXPECT_GT(std::stod(costs[1][1]), 0.0);   // a frame time
    EXPECT_LT(std::stod(costs[1][2]), 0.05);  // the error under white (a noisy truth in --quick)
    const LdrImage grid = decodePng(readFileBytes(path("grid_white.png")));
    EXPECT_GT(grid.width, 5 * 48 - 1);
    // Whole materials by model: under a uniform white environment the split sum of glTF's BRDF
    // without multiple scattering is its ground truth but for the tables; with it, a rough
    // metal is brighter than its single-scattering truth (the energy Fdez-Aguera adds back).
    std::map<std::string, double> worst;
    double roughMetal = 0.0;
    for (const auto& row : readCsv(path("model_split_sum.csv"))) {
        if (row[0] == "environment") {
            continue;
        }
        ASSERT_EQ(row.size(), 7u);
        worst[row[1]] = std::max(worst[row[1]], std::stod(row[5]));
        if (row[1] == "gltf" && row[2] == "white metal" && row[3] == "1") {
            roughMetal = std::stod(row[4]);
        }
    }
    EXPECT_EQ(worst.size(), 3u);   // epic, gltf, gltf-single
    EXPECT_LT(worst["gltf-single"], 0.05);
    EXPECT_GT(roughMetal, 0.5);
}

TEST_F(LightingAccuracy, DiffuseAccuracyWritesTheIrradianceAndTheMatteObjects) {
    const test::CliRun run =
        test::runPatina("diffuse-accuracy --quick --environment builtin:white --out-dir " + dir_.string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const auto irradiance = readCsv(path("irradiance.csv"));
    ASSERT_EQ(irradiance.size(), 9u);   // the header, the map as shipped and at 4 other sizes, SH twice, the reference
    EXPECT_EQ(irradiance[0][1], "method");
    EXPECT_EQ(irradiance[1][1], "\"irradiance map 32 cells 16 (as shipped)\"");
    // A uniform environment: the map is exact but for the cells a horizon cuts, and so is SH band 0.
    EXPECT_LT(std::stod(irradiance[1][2]), 3e-3);
    EXPECT_LT(std::stod(irradiance[6][2]), 1e-3);
    const auto matte = readCsv(path("matte.csv"));
    ASSERT_EQ(matte.size(), 5u);   // the header, the cube and the sphere by the split sum and the dominant direction
    EXPECT_EQ(matte[0][3], "pixels");
    for (size_t row = 1; row < matte.size(); ++row) {
        EXPECT_EQ(matte[row][0], "built-in white");
        EXPECT_NEAR(std::stod(matte[row][13]), 1.0, 3e-3) << row;   // the diffuse light's mean ratio
    }
    EXPECT_EQ(matte[1][1], "cube");
    EXPECT_EQ(matte[2][2], "split-sum");
    EXPECT_EQ(matte[4][2], "dominant");
}

}  // namespace
}  // namespace patina
