#include "storage/occlusion_bake.h"

namespace patina::editor {

OcclusionBake::OcclusionBake(std::shared_ptr<AssetCache> assets, const Scene& scene, AssetCache::Shape shape)
    : mesh_(shape.mesh), ground_(scene.display.ground != Ground::None) {
    // The worker holds what it reads (the cache, the shape, a copy of the scene): the document
    // may change or close while it runs.
    result_ = std::async(std::launch::async, [assets = std::move(assets), scene, shape = std::move(shape)] {
        return assets->ambientOcclusion(scene, shape);
    });
}

OcclusionBake::~OcclusionBake() {
    if (result_.valid()) {
        result_.wait();
    }
}

double OcclusionBake::seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool OcclusionBake::ready() const {
    return result_.valid() && result_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

std::shared_ptr<const AmbientOcclusion> OcclusionBake::take() {
    return result_.get();
}

}  // namespace patina::editor
