#include "model_load.h"

namespace patina::editor {

ModelLoad::ModelLoad(std::filesystem::path path, std::shared_ptr<AssetCache> assets) : path_(std::move(path)) {
    // The worker holds the cache too: it may outlive the state that started it. The import has
    // no point to stop at, so Cancel drops the result instead (ready() then is never asked).
    result_ = std::async(std::launch::async, [path = path_, assets = std::move(assets)] {
        return Result{assets->model(path), assets->drawnModel(path)};
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

ModelLoad::Result ModelLoad::take() {
    return result_.get();
}

}  // namespace patina::editor
