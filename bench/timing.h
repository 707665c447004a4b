#pragma once
// Medians of repeated measurements: this machine's absolute times are noisy, so benchmarks
// report the median of several runs after warm-up.
#include <algorithm>
#include <vector>

namespace patina {

inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

// Two warm-up calls (shader compilation, caches), then the median of `runs` calls.
template <typename Measure>
double medianOf(int runs, Measure measure) {
    measure();
    measure();
    std::vector<double> times;
    for (int i = 0; i < runs; ++i) {
        times.push_back(measure());
    }
    return median(times);
}

}  // namespace patina
