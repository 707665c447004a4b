// bench, stability and furnace: their outputs exist, parse and have one row per model, and the
// shipped models are finite and non-negative everywhere in the stability grid.
#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "brdf_models.h"
#include "half.h"
#include "cli_runner.h"
#include "image.h"
#include "scratch_test.h"
#include "stability.h"
#include "test_support.h"

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

TEST_F(AccuracyCommands, FurnaceWritesCurvesForEveryModel) {
    const test::CliRun run = test::runPatina("furnace --quick --out-dir " + dir_.string(), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const auto rows = readCsv(path("furnace.csv"));
    EXPECT_EQ(rows.size(), brdfModelCount() * 2 * 11 + 1);   // two mu, 11 roughness steps
    EXPECT_TRUE(std::filesystem::exists(path("furnace.png")));
    EXPECT_EQ(test::runPatina("furnace --out-dir " + path("missing").string(), dir_).exitCode, 3);
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
