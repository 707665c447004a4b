#pragma once
// The Khronos glTF-Validator (tests/gltf/validate.js, installed by scripts/setup.sh) as the
// export tests run it.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "scene/json_value.h"

namespace patina::test {

// The validator's report on `file`, its output kept in `scratch`; fails the test when it
// cannot run.
inline Json validateGltf(const std::filesystem::path& file, const std::filesystem::path& scratch) {
    namespace fs = std::filesystem;
    const fs::path modules = fs::path(PATINA_SOURCE_DIR) / "third_party/gltf-validator/node_modules";
    const fs::path script = fs::path(PATINA_SOURCE_DIR) / "tests/gltf/validate.js";
    const fs::path report = scratch / "report.json", errors = scratch / "validator-errors.txt";
    const std::string command = "node '" + script.string() + "' '" + modules.string() + "' '" + file.string() +
                                "' > '" + report.string() + "' 2> '" + errors.string() + "'";
    const int status = std::system(command.c_str());
    auto text = [](const fs::path& path) {
        std::ostringstream out;
        out << std::ifstream(path).rdbuf();
        return out.str();
    };
    EXPECT_EQ(status, 0) << "the glTF validator did not run: " << text(errors);
    // Parsed directly: the report lists every info message and outgrows the limit on
    // Patina's own JSON files (readJsonFile).
    return status == 0 ? Json::parse(text(report)) : Json::object();
}

// No error and no warning in the validator's report on `file`.
inline void expectValidGltf(const std::filesystem::path& file, const std::filesystem::path& scratch) {
    const Json report = validateGltf(file, scratch);
    ASSERT_TRUE(report.contains("issues")) << file;
    EXPECT_EQ(report["issues"]["numErrors"], 0) << file << "\n" << report["issues"].dump(2);
    EXPECT_EQ(report["issues"]["numWarnings"], 0) << file << "\n" << report["issues"].dump(2);
}

}  // namespace patina::test
