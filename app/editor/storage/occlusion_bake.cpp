#include "storage/occlusion_bake.h"

namespace patina::editor {

// The worker holds what it reads (the cache, the shape, a copy of the scene): the document may
// change or close while it runs.
OcclusionBake::OcclusionBake(std::shared_ptr<AssetCache> assets, const Scene& scene, AssetCache::Shape shape)
    : mesh_(shape.mesh),
      ground_(scene.display.ground != Ground::None),
      result_([assets = std::move(assets), scene, shape = std::move(shape)] {
          return assets->ambientOcclusion(scene, shape);
      }) {}

}  // namespace patina::editor
