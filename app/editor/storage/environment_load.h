#pragma once
#include <atomic>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "assets/asset_cache.h"
#include "environment/environment.h"

namespace patina::editor {

// An environment file made ready off the UI thread, through the editor's asset cache: decoding
// and prefiltering a large HDRI takes seconds on a software rasteriser's machine, and the
// editor keeps drawing (with the environment it has) and can cancel meanwhile. Destroying it
// cancels and waits.
class EnvironmentLoad {
public:
    EnvironmentLoad(std::string source, std::shared_ptr<AssetCache> assets);
    ~EnvironmentLoad();
    EnvironmentLoad(const EnvironmentLoad&) = delete;
    EnvironmentLoad& operator=(const EnvironmentLoad&) = delete;

    const std::string& source() const { return source_; }
    float progress() const { return progress_->load(); }   // 0 to 1
    bool ready() const;
    void cancel() { cancelled_->store(true); }

    struct Result {
        std::shared_ptr<const Environment> environment;   // null when cancelled
        std::vector<std::string> warnings;
    };
    // Once ready (waits otherwise): the result, or the load's error rethrown (InputError for a
    // file that cannot be read). Once only.
    Result take();

private:
    std::string source_;
    std::shared_ptr<std::atomic<float>> progress_ = std::make_shared<std::atomic<float>>(0.0f);
    std::shared_ptr<std::atomic<bool>> cancelled_ = std::make_shared<std::atomic<bool>>(false);
    std::future<Result> result_;
};

}  // namespace patina::editor
