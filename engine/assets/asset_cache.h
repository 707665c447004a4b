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
#include "assets/loaded_model.h"
#include "model/model.h"
#include "scene/ambient_occlusion.h"
#include "scene/scene.h"

namespace patina {

// What scenes name, loaded once and shared: glTF models and environments. The caller owns
// the cache (a CLI command one for its run, the editor one for its session, each test its
// own); nothing is cached process-wide, and the renderer never loads.
//
// A file is known by its path and its contents (a hash of its bytes, read once on every call,
// and for a model not held, imported from those same bytes), an environment also by its
// settings: the same file asked again is the same object, a file rewritten is loaded again. A .gltf's external buffers count through the .gltf itself only.
// Files are shared while someone holds them (a weak entry each); built-in environments, few
// and costly to make, are kept for the cache's life. Safe to use from several threads (the
// editor's environment worker): loading runs outside the lock.
class AssetCache {
public:
    AssetCache() = default;
    AssetCache(const AssetCache&) = delete;
    AssetCache& operator=(const AssetCache&) = delete;

    // The one door to a glTF model: the file at `path` read and hashed once, and when the cache
    // does not hold those contents, imported as the model it draws and that model flattened
    // (loaded_model.h). InputError naming the file when it cannot be loaded. A model loaded
    // afresh tells `progress` how many of its images are decoded; null when it stops it.
    std::shared_ptr<const LoadedModel> model(const std::filesystem::path& path, const Progress& progress = {});
    // The shape `scene` shows, through model() for a glTF file: the triangles (its file's,
    // flattened into world space, else the built-in kind's), what it draws (null for a built-in
    // mesh) and the file's model as loaded (null for a built-in mesh), each keeping the others'
    // entry. Where the scene replaces maps (ModelMaterialEdit::mapsReplaced), `model` is the
    // file's with those images in their place (retextured, below).
    struct Shape {
        std::shared_ptr<const Mesh> mesh;
        std::shared_ptr<const Model> model;
        std::shared_ptr<const LoadedModel> fileModel;
    };
    Shape shape(const Scene& scene);
    std::shared_ptr<const Mesh> mesh(const Scene& scene) { return shape(scene).mesh; }
    // An image file put in place of a map (gltf/images.h readImageFile), decoded once while
    // someone holds it; InputError naming the file when it cannot be had.
    std::shared_ptr<const ModelImage> image(const std::filesystem::path& path);
    // The model of `file` (model()'s) with the images `scene` puts in place of its maps, each
    // edit matched by index and name as sceneDraws matches them: the image is added and the map
    // points at it, keeping its UV set, sampler and transform. The file's model itself where the
    // scene replaces none. A replacement that cannot be used (a map the material lacks, an image
    // that cannot be read, one past kGltfMaxImageBytes) leaves the file's map drawn, with a note
    // in the result's notes. Known by the file's key and each replacement's map, path and image
    // contents: the same replacements give the same object while it is held.
    std::shared_ptr<const Model> retextured(const std::shared_ptr<const LoadedModel>& file, const Scene& scene);
    // The ambient occlusion of `shape` (shape(scene)'s, or one the caller loaded through it) with
    // or without a ground under it (scene/ambient_occlusion.h), baked once while someone holds
    // it: known by the file model's key (a retextured model has its file's triangles, so it
    // shares its file's occlusion) or the built-in kind, and whether a ground lies under it.
    // Null for a shape without its mesh.
    std::shared_ptr<const AmbientOcclusion> ambientOcclusion(const Scene& scene, const Shape& shape);
    // That occlusion where it is baked and held already, without baking it: null otherwise (the
    // editor bakes on a worker and draws without it meanwhile).
    std::shared_ptr<const AmbientOcclusion> heldAmbientOcclusion(const Scene& scene, const Shape& shape);
    // An environment light's source ("builtin:NAME", an .hdr or .exr path) made ready, through
    // the disk cache of environment/environment_source.h; one made afresh is prefiltered by
    // `prefilter` (the GPU's pass only where the caller's thread has a GL context). A note about
    // replaced pixels goes to `warnings` each time. InputError naming the file when it cannot be
    // read or decoded; null when `progress` stopped it.
    std::shared_ptr<const Environment> environment(const std::string& source, std::vector<std::string>& warnings,
                                                   const EnvironmentSettings& settings = {},
                                                   const Progress& progress = {},
                                                   PrefilterFunction prefilter = prefilterCube);

private:
    using Key = std::pair<std::string, uint64_t>;   // the path or source, the contents' hash
    // An image file's contents' key and the image, decoded once while someone holds it.
    std::pair<Key, std::shared_ptr<const ModelImage>> keyedImage(const std::filesystem::path& path);
    // What ambientOcclusion knows a bake by: the shape's key and whether a ground lies under it.
    static std::pair<Key, bool> occlusionKey(const Scene& scene, const Shape& shape);
    std::mutex mutex_;
    std::map<Key, std::weak_ptr<const LoadedModel>> models_;
    std::map<Key, std::weak_ptr<const Environment>> environments_;
    std::map<Key, std::shared_ptr<const Environment>> builtins_;
    std::map<Key, std::weak_ptr<const ModelImage>> images_;
    // By the shape's key (a file's, or "builtin:" and the kind) and whether a ground lies under it.
    std::map<std::pair<Key, bool>, std::weak_ptr<const AmbientOcclusion>> occlusions_;
    struct RetexturedModel;   // a retextured copy, holding the model it was made from
    std::map<std::string, std::weak_ptr<const RetexturedModel>> retextured_;   // by file and replacements
};

}  // namespace patina
