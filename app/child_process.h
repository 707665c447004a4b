#pragma once
// Running this program again as a child, for benchmarks that must count process start-up
// (24 separate renders against one sheet) or a whole process's peak memory.
#include <string>
#include <vector>

namespace patina::cli {

struct ChildRun {
    double seconds = 0.0;    // wall clock, fork to exit
    // The child's maximum resident set (wait4's ru_maxrss). Linux counts in it what this
    // process had resident when it forked (the copy's high-water mark survives exec), so call
    // this from a process that is still small.
    double peakRssMb = 0.0;
};

// Runs this executable (/proc/self/exe) with `arguments`, its stdout discarded. Throws
// std::runtime_error if it cannot start or does not exit with 0, with the start of its stderr.
ChildRun runSelf(const std::vector<std::string>& arguments);

}  // namespace patina::cli
