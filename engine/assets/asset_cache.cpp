#include "assets/asset_cache.h"

#include <cstdio>

#include "common/content_hash.h"
#include "environment/builtin_environments.h"
#include "files/input_error.h"
#include "gltf/files.h"
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

// A file known by its path and contents (its size bounded as a model's files are).
std::pair<std::string, uint64_t> fileKey(const std::filesystem::path& path) {
    const std::vector<uint8_t> bytes = gltf::readModelFile(path);
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

struct AssetCache::LoadedModel {
    GltfImport imported;
    Model model;
};

std::shared_ptr<const AssetCache::LoadedModel> AssetCache::loaded(const std::filesystem::path& path,
                                                                   const Progress& progress) {
    const Key key = fileKey(path);
    {
        std::lock_guard lock(mutex_);
        if (std::shared_ptr<const LoadedModel> model = heldEntry(models_, key)) {
            return model;
        }
    }
    std::optional<Model> drawn = importGltfModel(path, progress);
    if (!drawn) {
        return nullptr;   // stopped: nothing kept
    }
    GltfImport imported = flattenedImport(*drawn, path);
    auto model = std::make_shared<const LoadedModel>(LoadedModel{std::move(imported), std::move(*drawn)});
    std::lock_guard lock(mutex_);
    keepEntry(models_, key, model);
    return model;
}

// Each part of a loaded model shares its owner, so any one held keeps the cache entry alive.
std::shared_ptr<const GltfImport> AssetCache::model(const std::filesystem::path& path, const Progress& progress) {
    std::shared_ptr<const LoadedModel> model = loaded(path, progress);
    return model ? std::shared_ptr<const GltfImport>(model, &model->imported) : nullptr;
}

std::shared_ptr<const Model> AssetCache::drawnModel(const std::filesystem::path& path) {
    std::shared_ptr<const LoadedModel> model = loaded(path);
    return {model, &model->model};
}

AssetCache::Shape AssetCache::shape(const Scene& scene) {
    if (scene.meshFile.empty()) {
        return {builtinMesh(scene.mesh), nullptr};
    }
    std::shared_ptr<const LoadedModel> model = loaded(scene.meshFile);
    return {{model, &model->imported.mesh}, retextured({model, &model->model}, scene)};
}

std::shared_ptr<const ModelImage> AssetCache::image(const std::filesystem::path& path) {
    const Key key = fileKey(path);
    {
        std::lock_guard lock(mutex_);
        if (std::shared_ptr<const ModelImage> image = heldEntry(images_, key)) {
            return image;
        }
    }
    auto image = std::make_shared<const ModelImage>(gltf::readImageFile(path));
    std::lock_guard lock(mutex_);
    keepEntry(images_, key, image);
    return image;
}

namespace {
// One map of the model's material `material` the scene puts an image in place of: the image,
// or why it cannot be used.
struct Replacement {
    int material = 0;
    const char* key = nullptr;
    std::string path;
    std::shared_ptr<const ModelImage> image;
    std::string problem;
};

// Each replacement `scene` makes on `model` (an edit matched by index and name), its image read
// through `read`, in the materials' order and each material's maps' order.
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
            Replacement replacement{int(i), map.key, path->second, nullptr, ""};
            if (!map.slot->present()) {
                replacement.problem = "the material has no " + std::string(map.key) + " to replace";
            } else {
                try {
                    replacement.image = read(path->second);
                } catch (const InputError& error) {
                    replacement.problem = error.what();
                }
            }
            found.push_back(std::move(replacement));
        }
    }
    return found;
}

// What tells two sets of replacements on one model apart: each map, file and image.
std::string replacementsKey(const Model& model, const std::vector<Replacement>& replacements) {
    char address[32];
    std::snprintf(address, sizeof address, "%p", static_cast<const void*>(&model));
    std::string key = address;
    for (const Replacement& replacement : replacements) {
        std::snprintf(address, sizeof address, "%p", static_cast<const void*>(replacement.image.get()));
        key.append("|").append(std::to_string(replacement.material)).append(":").append(replacement.key);
        key.append(":").append(replacement.path).append(":").append(address);
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

// The model and images it was made from are held: their addresses are part of its key, and the
// images' cache entries (made again each call otherwise) keep theirs.
struct AssetCache::RetexturedModel {
    std::shared_ptr<const Model> from;
    std::vector<std::shared_ptr<const ModelImage>> images;
    Model model;
};

std::shared_ptr<const Model> AssetCache::retextured(std::shared_ptr<const Model> model, const Scene& scene) {
    {
        std::lock_guard lock(mutex_);   // one this made: from the file's model again
        for (const auto& [key, entry] : retextured_) {
            const std::shared_ptr<const RetexturedModel> made = entry.lock();
            if (made && &made->model == model.get()) {
                model = made->from;
                break;
            }
        }
    }
    const std::vector<Replacement> replacements =
        replacementsOf(*model, scene, [&](const std::string& path) { return image(path); });
    if (replacements.empty()) {
        return model;
    }
    const std::string key = replacementsKey(*model, replacements);
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
        RetexturedModel{model, std::move(images), withReplacements(*model, replacements)});
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
