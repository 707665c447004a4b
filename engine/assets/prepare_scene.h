#pragma once
#include <string>
#include <vector>

#include "assets/asset_cache.h"
#include "scene/prepared_scene.h"

namespace patina {

// `scene` with what it names loaded through `cache`: its mesh (and for a glTF file the model
// it draws), and its enabled environment light's environment (none without one). Throws
// InputError naming the file for a mesh or an environment that cannot be read; notes (replaced
// pixels, what the model's file left out, a replaced map that cannot be used) go to
// `warnings`. An environment made afresh is prefiltered by `prefilter` (AssetCache::environment).
// The result refers to `scene`, which must outlive it.
PreparedScene prepareScene(const Scene& scene, AssetCache& cache, std::vector<std::string>& warnings,
                           PrefilterFunction prefilter = prefilterCube);
PreparedScene prepareScene(Scene&& scene, AssetCache& cache, std::vector<std::string>& warnings,
                           PrefilterFunction prefilter = prefilterCube) = delete;
// The same with `shape`, cache.shape(scene)'s, loaded already (the editor keeps its file model).
PreparedScene prepareScene(const Scene& scene, const AssetCache::Shape& shape, AssetCache& cache,
                           std::vector<std::string>& warnings, PrefilterFunction prefilter = prefilterCube);

}  // namespace patina
