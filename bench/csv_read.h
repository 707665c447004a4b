#pragma once
// Reading back the CSVs the benchmarks write, so that their charts can be redrawn from the
// numbers a run recorded without measuring again (`patina chart`).
#include <string>
#include <vector>

namespace patina {

// A file's text and its name for messages.
struct CsvFile {
    std::string text, source;
};

struct CsvLine {
    size_t number = 0;                // in the file, from 1 (for messages)
    std::vector<std::string> cells;   // split at commas outside double quotes, quotes dropped
};

// The lines after the header, which must begin with `header`; empty lines skipped. Throws
// InputError naming the file and the line.
std::vector<CsvLine> csvBody(const CsvFile& file, const std::string& header);

// Cell `column` of `line` as a finite number, or `line` as a whole has `count` cells; both throw
// InputError naming `source` and the line.
double csvNumber(const CsvLine& line, size_t column, const std::string& source);
void expectCells(const CsvLine& line, size_t count, const std::string& source);

}  // namespace patina
