#include "assets/prepare_scene.h"

namespace patina {

namespace {
// The enabled environment light's environment, or null without one.
std::shared_ptr<const Environment> environmentOf(const Scene& scene, AssetCache& cache,
                                                 std::vector<std::string>& warnings, PrefilterFunction prefilter) {
    const Light* light = enabledEnvironment(scene);
    return light ? cache.environment(light->source, warnings, {}, {}, prefilter) : nullptr;
}

// `scene` with its shape and environment, and its ambient occlusion where the display has it
// on; the model's notes to `warnings`.
PreparedScene withLoaded(const Scene& scene, const AssetCache::Shape& shape, AssetCache& cache,
                         std::shared_ptr<const Environment> environment, std::vector<std::string>& warnings) {
    if (shape.model) {   // what its file left out (a map whose image is missing, ...), and its replacements
        warnings.insert(warnings.end(), shape.model->notes.begin(), shape.model->notes.end());
        const std::vector<std::string> unmatched = unmatchedEdits(scene, *shape.model);
        warnings.insert(warnings.end(), unmatched.begin(), unmatched.end());
    }
    return {scene, shape.mesh, std::move(environment), shape.model,
            scene.display.ambientOcclusion ? cache.ambientOcclusion(scene, shape) : nullptr};
}

}  // namespace

PreparedScene prepareScene(const Scene& scene, AssetCache& cache, std::vector<std::string>& warnings,
                           PrefilterFunction prefilter) {
    std::shared_ptr<const Environment> environment = environmentOf(scene, cache, warnings, prefilter);
    return withLoaded(scene, cache.shape(scene), cache, std::move(environment), warnings);
}

PreparedScene prepareScene(const Scene& scene, const AssetCache::Shape& shape, AssetCache& cache,
                           std::vector<std::string>& warnings, PrefilterFunction prefilter) {
    return withLoaded(scene, shape, cache, environmentOf(scene, cache, warnings, prefilter), warnings);
}

}  // namespace patina
