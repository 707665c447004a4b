#include "environment_load.h"

#include <chrono>

#include "image/environment_source.h"

namespace patina::editor {

EnvironmentLoad::EnvironmentLoad(std::string source) : source_(std::move(source)) {
    result_ = std::async(std::launch::async, [source = source_, progress = progress_, cancelled = cancelled_] {
        Result result;
        result.environment = loadEnvironment(source, result.warnings, {}, [&](float done) {
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
