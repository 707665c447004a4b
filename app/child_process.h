#pragma once
// Running this program again as a child, for benchmarks that must count process start-up
// (24 separate renders against one sheet) or a whole process's peak memory.
#include <string>
#include <vector>

namespace patina::cli {

struct ChildRun {
    double seconds = 0.0;    // wall clock, fork to exit
    double peakRssMb = 0.0;  // the child's maximum resident set (wait4's ru_maxrss)
};

// Runs this executable (/proc/self/exe) with `arguments`, its stdout and stderr discarded.
// Throws std::runtime_error if it cannot start or exits with a status other than 0.
ChildRun runSelf(const std::vector<std::string>& arguments);

}  // namespace patina::cli
