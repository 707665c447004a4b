#include "accuracy/probe_csv.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "files/input_error.h"

namespace patina {

namespace {
constexpr const char* kProbeHeader = "px,py,pz,nx,ny,nz,vx,vy,vz";

std::string trimLineEnd(std::string line) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) {
        line.pop_back();
    }
    return line;
}
}  // namespace

std::vector<ProbeSample> parseProbeCsv(const std::string& text, const std::string& source) {
    std::istringstream stream(text);
    std::string line;
    size_t lineNumber = 0;
    auto fail = [&](const std::string& what) {
        throw InputError(source + ":" + std::to_string(lineNumber) + ": " + what);
    };
    ++lineNumber;
    if (!std::getline(stream, line) || trimLineEnd(line) != kProbeHeader) {
        fail(std::string("expected the header '") + kProbeHeader + "'");
    }
    std::vector<ProbeSample> samples;
    while (std::getline(stream, line)) {
        ++lineNumber;
        line = trimLineEnd(line);
        if (line.empty()) {
            continue;
        }
        float values[9];
        const char* cursor = line.c_str();
        for (int column = 0; column < 9; ++column) {
            char* end = nullptr;
            errno = 0;
            const double value = std::strtod(cursor, &end);
            const char expected = column < 8 ? ',' : '\0';
            if (end == cursor || *end != expected) {
                fail("column " + std::to_string(column + 1) + " is not a number followed by " +
                     (column < 8 ? "','" : "the end of the line"));
            }
            if (!std::isfinite(value) || !std::isfinite(float(value))) {
                fail("column " + std::to_string(column + 1) + " is not a finite number");
            }
            values[column] = float(value);
            cursor = end + (column < 8 ? 1 : 0);
        }
        samples.push_back({{values[0], values[1], values[2]},
                           {values[3], values[4], values[5]},
                           {values[6], values[7], values[8]}});
    }
    return samples;
}

std::string formatRadianceCsv(const std::vector<glm::vec3>& radiance) {
    std::string out = "r,g,b\n";
    char row[128];
    for (const glm::vec3& value : radiance) {
        std::snprintf(row, sizeof row, "%.9g,%.9g,%.9g\n", double(value.r), double(value.g),
                      double(value.b));
        out += row;
    }
    return out;
}

std::string formatReferenceCsv(const std::vector<ReferenceRow>& rows) {
    std::string out = "r,g,b,se_r,se_g,se_b\n";
    char line[256];
    for (const ReferenceRow& row : rows) {
        std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", double(row.value.r), double(row.value.g),
                      double(row.value.b), double(row.standardError.r), double(row.standardError.g),
                      double(row.standardError.b));
        out += line;
    }
    return out;
}

}  // namespace patina
