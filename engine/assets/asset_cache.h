#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "environment/environment.h"
#include "geometry/mesh.h"
#include "gltf/import.h"
#include "model/model.h"
#include "scene/scene.h"

namespace patina {

// What scenes name, loaded once and shared: glTF models and environments. The caller owns
// the cache (a CLI command one for its run, the editor one for its session, each test its
// own); nothing is cached process-wide, and the renderer never loads.
//
// A file is known by its path and its contents (a hash of its bytes, read on every call), an
// environment also by its settings: the same file asked again is the same object, a file
// rewritten is loaded again. A .gltf's external buffers count through the .gltf itself only.
// Files are shared while someone holds them (a weak entry each); built-in environments, few
// and costly to make, are kept for the cache's life. Safe to use from several threads (the
// editor's environment worker): loading runs outside the lock.
class AssetCache {
public:
    AssetCache() = default;
    AssetCache(const AssetCache&) = delete;
    AssetCache& operator=(const AssetCache&) = delete;

    // A glTF model (gltf/import.h); InputError naming the file when it cannot be loaded. A model
    // loaded afresh tells `progress` how many of its images are decoded; null when it stops it.
    std::shared_ptr<const GltfImport> model(const std::filesystem::path& path, const Progress& progress = {});
    // The shape `scene` shows, its file read once: the triangles (its glTF file's, flattened
    // into world space, else the built-in kind's) and what its glTF file draws
    // (gltf/model_import.h; null for a built-in mesh), each keeping the other's entry.
    struct Shape {
        std::shared_ptr<const Mesh> mesh;
        std::shared_ptr<const Model> model;
    };
    Shape shape(const Scene& scene);
    // The model the glTF file at `path` draws (shares its entry with model(path)).
    std::shared_ptr<const Model> drawnModel(const std::filesystem::path& path);
    std::shared_ptr<const Mesh> mesh(const Scene& scene) { return shape(scene).mesh; }
    // An environment light's source ("builtin:NAME", an .hdr or .exr path) made ready, through
    // the disk cache of environment/environment_source.h. A note about replaced pixels goes to
    // `warnings` each time. InputError naming the file when it cannot be read or decoded;
    // null when `progress` stopped it.
    std::shared_ptr<const Environment> environment(const std::string& source, std::vector<std::string>& warnings,
                                                   const EnvironmentSettings& settings = {},
                                                   const Progress& progress = {});

private:
    using Key = std::pair<std::string, uint64_t>;   // the path or source, the contents' hash
    struct LoadedModel;   // a file's import and its Model, loaded together
    std::shared_ptr<const LoadedModel> loaded(const std::filesystem::path& path, const Progress& progress = {});
    std::mutex mutex_;
    std::map<Key, std::weak_ptr<const LoadedModel>> models_;
    std::map<Key, std::weak_ptr<const Environment>> environments_;
    std::map<Key, std::shared_ptr<const Environment>> builtins_;
};

}  // namespace patina
