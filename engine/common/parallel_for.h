#pragma once
// body(i) for every i in [0, count), on every core (at most 64 threads), each index once, in
// no particular order: for independent estimates (ground-truth rows, accuracy grids).
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace patina {

template <typename Body>
void parallelFor(size_t count, Body&& body) {
    std::atomic<size_t> next{0};
    auto work = [&] {
        for (size_t i; (i = next++) < count;) {
            body(i);
        }
    };
    std::vector<std::thread> pool;
    const unsigned threads = std::max(1u, std::min(std::thread::hardware_concurrency(), 64u));
    for (unsigned t = 1; t < threads; ++t) {
        pool.emplace_back(work);
    }
    work();
    for (std::thread& thread : pool) {
        thread.join();
    }
}

}  // namespace patina
