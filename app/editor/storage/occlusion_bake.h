#pragma once
// A shape's ambient occlusion baked off the UI thread (Embree's rays at every vertex: about a
// second for 2CylinderEngine, which used to freeze the window once when the checkbox was
// ticked). The viewport draws without the occlusion meanwhile. Destroying it waits for the
// worker, so a bake no longer wanted is kept until it ends (Jobs::droppedOcclusionBakes).
#include <memory>

#include "assets/asset_cache.h"
#include "storage/worker_result.h"

namespace patina::editor {

class OcclusionBake {
public:
    OcclusionBake(std::shared_ptr<AssetCache> assets, const Scene& scene, AssetCache::Shape shape);

    // Whether it bakes `mesh`'s occlusion with (`ground`) or without a ground under it.
    bool bakes(const Mesh* mesh, bool ground) const { return mesh == mesh_.get() && ground == ground_; }
    double seconds() const { return result_.seconds(); }   // since it started
    bool ready() const { return result_.ready(); }
    // Once ready (waits otherwise): the occlusion, held by the cache from then on, or the bake's
    // error rethrown. Once only.
    std::shared_ptr<const AmbientOcclusion> take() { return result_.take(); }

private:
    std::shared_ptr<const Mesh> mesh_;
    bool ground_;
    WorkerResult<std::shared_ptr<const AmbientOcclusion>> result_;
};

}  // namespace patina::editor
