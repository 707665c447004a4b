#include "assets/asset_cache.h"

#include "common/content_hash.h"
#include "gltf/files.h"
#include "gltf/model_import.h"
#include "environment/environment_source.h"

namespace patina {

namespace {
// Entries whose object nobody holds any more, dropped when another is added.
template <typename Map>
void dropExpired(Map& entries) {
    std::erase_if(entries, [](const auto& entry) { return entry.second.expired(); });
}
}  // namespace

struct AssetCache::LoadedModel {
    GltfImport imported;
    Model model;
};

std::shared_ptr<const AssetCache::LoadedModel> AssetCache::loaded(const std::filesystem::path& path,
                                                                   const Progress& progress) {
    const std::vector<uint8_t> bytes = gltf::readModelFile(path);
    const Key key{std::filesystem::absolute(path).lexically_normal().string(), hashBytes(bytes.data(), bytes.size())};
    {
        std::lock_guard lock(mutex_);
        if (const auto found = models_.find(key); found != models_.end()) {
            if (std::shared_ptr<const LoadedModel> model = found->second.lock()) {
                return model;
            }
        }
    }
    std::optional<Model> drawn = importGltfModel(path, progress);
    if (!drawn) {
        return nullptr;   // stopped: nothing kept
    }
    GltfImport imported = flattenedImport(*drawn, path);
    auto model = std::make_shared<const LoadedModel>(LoadedModel{std::move(imported), std::move(*drawn)});
    std::lock_guard lock(mutex_);
    dropExpired(models_);
    models_[key] = model;
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
    return {{model, &model->imported.mesh}, {model, &model->model}};
}

std::shared_ptr<const Environment> AssetCache::environment(const std::string& source,
                                                           std::vector<std::string>& warnings,
                                                           const EnvironmentSettings& settings,
                                                           const Progress& progress) {
    const EnvironmentSource read = readEnvironmentSource(source, settings);
    const Key key{source, read.key};
    const bool builtin = source.starts_with("builtin:");
    std::shared_ptr<const Environment> environment;
    {
        std::lock_guard lock(mutex_);
        if (builtin) {
            if (const auto found = builtins_.find(key); found != builtins_.end()) {
                environment = found->second;
            }
        } else if (const auto found = environments_.find(key); found != environments_.end()) {
            environment = found->second.lock();
        }
    }
    if (!environment) {
        environment = makeEnvironment(read, settings, progress);
        if (!environment) {
            return nullptr;   // stopped
        }
        std::lock_guard lock(mutex_);
        if (builtin) {
            builtins_.try_emplace(key, environment);
        } else {
            dropExpired(environments_);
            environments_[key] = environment;
        }
    }
    if (environment->replacedPixels > 0) {
        warnings.push_back(source + ": " + std::to_string(environment->replacedPixels) +
                           " pixels were NaN, infinite or negative and were set to 0");
    }
    return environment;
}

}  // namespace patina
