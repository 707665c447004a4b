#include "storage/model_load.h"

namespace patina::editor {

ModelLoad::ModelLoad(std::filesystem::path path, std::shared_ptr<AssetCache> assets) : path_(std::move(path)) {
    // The worker holds the cache too: it may outlive the state that started it. Cancel stops the
    // decoding at the next image; the UI drops the load and never asks for the result.
    result_ = std::async(std::launch::async, [path = path_, assets = std::move(assets), shared = shared_] {
        return assets->model(path, [&](float fraction) {
            shared->fraction = fraction;
            return !shared->cancelled;
        });
    });
}

ModelLoad::~ModelLoad() {
    if (result_.valid()) {
        result_.wait();
    }
}

double ModelLoad::seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool ModelLoad::ready() const {
    return result_.valid() && result_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

std::shared_ptr<const LoadedModel> ModelLoad::take() {
    return result_.get();
}

}  // namespace patina::editor
