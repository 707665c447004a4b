#include "storage/model_load.h"

namespace patina::editor {

// The worker holds the cache too: it may outlive the state that started it. Cancel stops the
// decoding at the next image; the UI drops the load and never asks for the result.
ModelLoad::ModelLoad(std::filesystem::path path, std::shared_ptr<AssetCache> assets)
    : path_(std::move(path)), result_([path = path_, assets = std::move(assets), shared = shared_] {
          return assets->model(path, [&](float fraction) {
              shared->fraction = fraction;
              return !shared->cancelled;
          });
      }) {}

}  // namespace patina::editor
