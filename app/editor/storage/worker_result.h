#pragma once
// A value made on a worker (std::async) that the UI polls once a frame: whether it is done, how
// long it has run, and the value once (or the worker's exception rethrown). Destroying it waits
// for the worker, which therefore holds what it reads and nothing of its owner's.
#include <chrono>
#include <future>
#include <utility>

namespace patina::editor {

template <typename T>
class WorkerResult {
public:
    template <typename Work>
    explicit WorkerResult(Work&& work) : result_(std::async(std::launch::async, std::forward<Work>(work))) {}
    ~WorkerResult() {
        if (result_.valid()) {
            result_.wait();
        }
    }
    WorkerResult(const WorkerResult&) = delete;
    WorkerResult& operator=(const WorkerResult&) = delete;

    double seconds() const {   // since it started
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    bool ready() const {
        return result_.valid() && result_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
    }
    T take() { return result_.get(); }   // once; waits until ready

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::future<T> result_;
};

}  // namespace patina::editor
