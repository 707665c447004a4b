#include "assets/prepare_scene.h"

namespace patina {

PreparedScene prepareScene(const Scene& scene, AssetCache& cache, std::vector<std::string>& warnings,
                           PrefilterFunction prefilter) {
    const Light* light = enabledEnvironment(scene);
    std::shared_ptr<const Environment> environment =
        light ? cache.environment(light->source, warnings, {}, {}, prefilter) : nullptr;
    AssetCache::Shape shape = cache.shape(scene);
    if (shape.model) {   // what its file left out (a map whose image is missing, ...), and its replacements
        warnings.insert(warnings.end(), shape.model->notes.begin(), shape.model->notes.end());
    }
    return {scene, std::move(shape.mesh), std::move(environment), std::move(shape.model)};
}

}  // namespace patina
