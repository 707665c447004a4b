#include "storage/environment_load.h"

#include <chrono>

namespace patina::editor {

EnvironmentLoad::EnvironmentLoad(std::string source, std::shared_ptr<AssetCache> assets) : source_(std::move(source)) {
    // The worker holds the cache too: it may outlive the state that started it.
    result_ = std::async(std::launch::async, [source = source_, assets = std::move(assets), progress = progress_,
                                              cancelled = cancelled_] {
        Result result;
        result.environment = assets->environment(source, result.warnings, {}, [&](float done) {
            progress->store(done);
            return !cancelled->load();
        });
        progress->store(1.0f);
        return result;
    });
}

EnvironmentLoad::~EnvironmentLoad() {
    cancel();
    if (result_.valid()) {
        result_.wait();
    }
}

bool EnvironmentLoad::ready() const {
    return result_.valid() && result_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

EnvironmentLoad::Result EnvironmentLoad::take() {
    return result_.get();
}

}  // namespace patina::editor
