#pragma once
// A glTF model opened from the window (Open, Recent, a dropped file), read and decoded off the
// UI thread: a model with several 4K maps takes seconds, and the editor keeps drawing the mesh
// it has and can cancel meanwhile. Destroying it waits for the worker.
#include <atomic>
#include <filesystem>
#include <memory>

#include "assets/asset_cache.h"
#include "assets/loaded_model.h"
#include "storage/worker_result.h"

namespace patina::editor {

class ModelLoad {
public:
    ModelLoad(std::filesystem::path path, std::shared_ptr<AssetCache> assets);

    const std::filesystem::path& path() const { return path_; }
    double seconds() const { return result_.seconds(); }   // since it started
    // The share of its images decoded (0 until the decoding starts, and for a model without).
    float fraction() const { return shared_->fraction; }
    bool ready() const { return result_.ready(); }
    // Stops the decoding at the next image: the worker ends soon, and take() gives nothing.
    void cancel() { shared_->cancelled = true; }

    // Once ready (waits otherwise): the model as the cache loaded it (AssetCache::model, its
    // file read once), or the import's error rethrown (InputError for a file that cannot be
    // read); null when cancelled. Once only.
    std::shared_ptr<const LoadedModel> take() { return result_.take(); }

private:
    std::filesystem::path path_;
    struct Shared {   // with the worker, which may outlive nothing here: the destructor waits
        std::atomic<float> fraction{0.0f};
        std::atomic<bool> cancelled{false};
    };
    std::shared_ptr<Shared> shared_ = std::make_shared<Shared>();
    WorkerResult<std::shared_ptr<const LoadedModel>> result_;
};

}  // namespace patina::editor
