#include "bench/csv_read.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "files/input_error.h"

namespace patina {

namespace {
std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (const char c : line) {
        if (c == '"') {
            quoted = !quoted;
        } else if (c == ',' && !quoted) {
            cells.emplace_back();
        } else {
            cells.back() += c;
        }
    }
    return cells;
}

[[noreturn]] void fail(const std::string& source, size_t line, const std::string& what) {
    throw InputError(source + ":" + std::to_string(line) + ": " + what);
}
}  // namespace

std::vector<CsvLine> csvBody(const CsvFile& file, const std::string& header) {
    std::istringstream stream(file.text);
    std::string line;
    if (!std::getline(stream, line) || !line.starts_with(header)) {
        fail(file.source, 1, "expected a header beginning '" + header + "'");
    }
    std::vector<CsvLine> lines;
    for (size_t number = 2; std::getline(stream, line); ++number) {
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();   // written on Windows
        }
        if (!line.empty()) {
            lines.push_back({number, splitCsvLine(line)});
        }
    }
    return lines;
}

double csvNumber(const CsvLine& line, size_t column, const std::string& source) {
    if (column >= line.cells.size()) {
        fail(source, line.number, "no column " + std::to_string(column + 1));
    }
    const std::string& cell = line.cells[column];
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(cell.c_str(), &end);
    if (cell.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(value)) {
        fail(source, line.number, "column " + std::to_string(column + 1) + " ('" + cell + "') is not a finite number");
    }
    return value;
}

void expectCells(const CsvLine& line, size_t count, const std::string& source) {
    if (line.cells.size() != count) {
        fail(source, line.number, std::to_string(line.cells.size()) + " columns, expected " + std::to_string(count));
    }
}

}  // namespace patina
