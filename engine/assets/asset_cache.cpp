#include "assets/asset_cache.h"

#include "common/content_hash.h"
#include "environment/builtin_environments.h"
#include "files/input_error.h"
#include "gltf/files.h"
#include "gltf/flatten.h"
#include "gltf/images.h"
#include "gltf/model_import.h"
#include "scene/prepared_scene.h"
#include "environment/environment_source.h"

namespace patina {

namespace {
// Entries whose object nobody holds any more, dropped when another is added.
template <typename Map>
void dropExpired(Map& entries) {
    std::erase_if(entries, [](const auto& entry) { return entry.second.expired(); });
}

// The absolute, normal path and the hash of `bytes`: what the cache knows a file by.
std::pair<std::string, uint64_t> fileKey(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
    return {std::filesystem::absolute(path).lexically_normal().string(), hashBytes(bytes.data(), bytes.size())};
}

// The object `entries` has under `key` while someone still holds it, else null.
template <typename Map>
auto heldEntry(const Map& entries, const typename Map::key_type& key) {
    const auto found = entries.find(key);
    return found != entries.end() ? found->second.lock() : decltype(found->second.lock())();
}

// `object` entered under `key`, the entries nobody holds dropped.
template <typename Map, typename Object>
void keepEntry(Map& entries, const typename Map::key_type& key, const Object& object) {
    dropExpired(entries);
    entries[key] = object;
}
}  // namespace

// The file is read once (its size bounded as a model's files are), hashed, and imported from
// those bytes only when the cache does not hold its contents.
std::shared_ptr<const LoadedModel> AssetCache::model(const std::filesystem::path& path, const Progress& progress) {
    const std::vector<uint8_t> bytes = gltf::readModelFile(path);
    const Key key = fileKey(path, bytes);
    {
        std::lock_guard lock(mutex_);
        if (std::shared_ptr<const LoadedModel> model = heldEntry(models_, key)) {
            return model;
        }
    }
    std::optional<Model> drawn = importGltfModel(path, bytes, progress);
    if (!drawn) {
        return nullptr;   // stopped: nothing kept
    }
    Mesh mesh = gltf::flattenDraws(*drawn, path.string());
    auto model =
        std::make_shared<const LoadedModel>(LoadedModel{std::move(*drawn), std::move(mesh), key.first, key.second});
    std::lock_guard lock(mutex_);
    keepEntry(models_, key, model);
    return model;
}

// Each part of the loaded model shares its owner, so any one held keeps the cache entry alive.
AssetCache::Shape AssetCache::shape(const Scene& scene) {
    if (scene.meshFile.empty()) {
        return {builtinMesh(scene.mesh), nullptr, nullptr};
    }
    std::shared_ptr<const LoadedModel> file = model(scene.meshFile);
    return {{file, &file->mesh}, retextured(file, scene), file};
}

std::pair<AssetCache::Key, bool> AssetCache::occlusionKey(const Scene& scene, const Shape& shape) {
    const Key shapeKey = shape.fileModel ? Key{shape.fileModel->path, shape.fileModel->hash}
                                         : Key{"builtin:" + std::string(meshKindName(scene.mesh)), 0};
    return {shapeKey, scene.display.ground != Ground::None};
}

std::shared_ptr<const AmbientOcclusion> AssetCache::heldAmbientOcclusion(const Scene& scene, const Shape& shape) {
    if (!shape.mesh) {
        return nullptr;
    }
    std::lock_guard lock(mutex_);
    return heldEntry(occlusions_, occlusionKey(scene, shape));
}

std::shared_ptr<const AmbientOcclusion> AssetCache::ambientOcclusion(const Scene& scene, const Shape& shape) {
    if (std::shared_ptr<const AmbientOcclusion> held = heldAmbientOcclusion(scene, shape); held || !shape.mesh) {
        return held;
    }
    const std::pair<Key, bool> key = occlusionKey(scene, shape);
    auto occlusion = std::make_shared<const AmbientOcclusion>(
        bakeAmbientOcclusion(*shape.mesh, shape.fileModel ? &shape.fileModel->model : nullptr, key.second));
    std::lock_guard lock(mutex_);
    keepEntry(occlusions_, key, occlusion);
    return occlusion;
}

std::shared_ptr<const ModelImage> AssetCache::image(const std::filesystem::path& path) {
    return keyedImage(path).second;
}

std::pair<AssetCache::Key, std::shared_ptr<const ModelImage>> AssetCache::keyedImage(
    const std::filesystem::path& path) {
    const std::vector<uint8_t> bytes = gltf::readModelFile(path);
    const Key key = fileKey(path, bytes);
    {
        std::lock_guard lock(mutex_);
        if (std::shared_ptr<const ModelImage> image = heldEntry(images_, key)) {
            return {key, image};
        }
    }
    auto image = std::make_shared<const ModelImage>(gltf::readImageFile(path, bytes));
    std::lock_guard lock(mutex_);
    keepEntry(images_, key, image);
    return {key, image};
}

namespace {
// One map of the model's material `material` the scene puts an image in place of: the image and
// the hash of its file's contents, or why it cannot be used.
struct Replacement {
    int material = 0;
    const char* key = nullptr;
    std::string path;
    std::shared_ptr<const ModelImage> image;
    uint64_t hash = 0;
    std::string problem;
};

// Each replacement `scene` makes on `model` (an edit matched by index and name), its image read
// through `read` (its contents' key and the image), in the materials' order and each material's
// maps' order.
template <typename Read>
std::vector<Replacement> replacementsOf(const Model& model, const Scene& scene, Read&& read) {
    std::vector<Replacement> found;
    for (size_t i = 0; i < model.materials.size(); ++i) {
        const ModelMaterial& material = model.materials[i];
        const ModelMaterialEdit* edit = editOf(scene, int(i), material);
        for (const auto& map : mapsOf(material)) {
            const auto path = edit ? edit->mapsReplaced.find(map.key) : decltype(edit->mapsReplaced.end()){};
            if (!edit || path == edit->mapsReplaced.end()) {
                continue;
            }
            Replacement replacement{int(i), map.key, path->second, nullptr, 0, ""};
            if (!map.slot->present()) {
                replacement.problem = "the material has no " + std::string(map.key) + " to replace";
            } else {
                try {
                    auto [key, image] = read(path->second);
                    replacement.hash = key.second;
                    replacement.image = std::move(image);
                } catch (const InputError& error) {
                    replacement.problem = error.what();
                }
            }
            found.push_back(std::move(replacement));
        }
    }
    return found;
}

// What tells two sets of replacements on one file apart, by contents: the file's key, then each
// replacement's material, map, path and image contents (0: an image that could not be read).
std::string replacementsKey(const LoadedModel& file, const std::vector<Replacement>& replacements) {
    std::string key = file.path + "\n" + std::to_string(file.hash);
    for (const Replacement& replacement : replacements) {
        key.append("\n").append(std::to_string(replacement.material)).append("\n").append(replacement.key);
        key.append("\n").append(replacement.path).append("\n").append(std::to_string(replacement.hash));
    }
    return key;
}

// `model` with each usable replacement's image added and its map pointing at it.
Model withReplacements(const Model& model, const std::vector<Replacement>& replacements) {
    Model retextured = model;
    uint64_t decoded = 0;
    for (const ModelImage& image : model.images) {
        decoded += image.rgba.size();
    }
    for (const Replacement& replacement : replacements) {
        const std::string what = "material " + std::to_string(replacement.material) + " (\"" +
                                 model.materials[size_t(replacement.material)].name + "\"): the image for its " +
                                 replacement.key;
        std::string problem = replacement.problem;
        if (problem.empty() && replacement.image->rgba.size() > gltf::kGltfMaxImageBytes - decoded) {
            problem = replacement.path + " would take the model's decoded images past Patina's limit of " +
                      std::to_string(gltf::kGltfMaxImageBytes >> 20) + " MiB";
        }
        if (!problem.empty()) {
            retextured.notes.push_back(what + " is not used: " + problem + "; the file's map is drawn");
            continue;
        }
        decoded += replacement.image->rgba.size();
        mapWithKey(retextured.materials[size_t(replacement.material)], replacement.key)->slot->image =
            int(retextured.images.size());
        retextured.images.push_back(*replacement.image);
    }
    return retextured;
}
}  // namespace

// The file and the images it was made from are held: the images' cache entries (made again each
// call otherwise) keep theirs.
struct AssetCache::RetexturedModel {
    std::shared_ptr<const LoadedModel> from;
    std::vector<std::shared_ptr<const ModelImage>> images;
    Model model;
};

std::shared_ptr<const Model> AssetCache::retextured(const std::shared_ptr<const LoadedModel>& file,
                                                    const Scene& scene) {
    const std::vector<Replacement> replacements =
        replacementsOf(file->model, scene, [&](const std::string& path) { return keyedImage(path); });
    if (replacements.empty()) {
        return {file, &file->model};
    }
    const std::string key = replacementsKey(*file, replacements);
    {
        std::lock_guard lock(mutex_);
        if (std::shared_ptr<const RetexturedModel> made = heldEntry(retextured_, key)) {
            return {made, &made->model};
        }
    }
    std::vector<std::shared_ptr<const ModelImage>> images;
    for (const Replacement& replacement : replacements) {
        images.push_back(replacement.image);
    }
    auto made = std::make_shared<const RetexturedModel>(
        RetexturedModel{file, std::move(images), withReplacements(file->model, replacements)});
    std::lock_guard lock(mutex_);
    keepEntry(retextured_, key, made);
    return {made, &made->model};
}

std::shared_ptr<const Environment> AssetCache::environment(const std::string& source,
                                                           std::vector<std::string>& warnings,
                                                           const EnvironmentSettings& settings,
                                                           const Progress& progress,
                                                           PrefilterFunction prefilter) {
    const EnvironmentSource read = readEnvironmentSource(source, settings);
    const Key key{source, read.key};
    const bool builtin = builtinName(source).has_value();
    std::shared_ptr<const Environment> environment;
    {
        std::lock_guard lock(mutex_);
        if (builtin) {
            if (const auto found = builtins_.find(key); found != builtins_.end()) {
                environment = found->second;
            }
        } else {
            environment = heldEntry(environments_, key);
        }
    }
    if (!environment) {
        environment = makeEnvironment(read, settings, progress, prefilter);
        if (!environment) {
            return nullptr;   // stopped
        }
        std::lock_guard lock(mutex_);
        if (builtin) {
            builtins_.try_emplace(key, environment);
        } else {
            keepEntry(environments_, key, environment);
        }
    }
    if (environment->replacedPixels > 0) {
        warnings.push_back(source + ": " + std::to_string(environment->replacedPixels) +
                           " pixels were NaN, infinite or negative and were set to 0");
    }
    return environment;
}

}  // namespace patina
