#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "io/json_reader.h"
#include "scene/scene.h"

namespace patina {

// Loaders throw InputError and append non-fatal notes (unknown keys) to `warnings`.
// docs/FORMATS.md describes both formats.
constexpr int kMaterialFormatVersion = 1;
// 2: a point light's attenuation window is "range" (version 1 called it "radius", which sphere
// lights need for their size). Version 1 files still load.
// 3: a glTF model's parts are shaded each with its own BRDF model (the file's are `gltf`) unless
// "modelBrdf" names one for all; a version 1 or 2 scene shaded them all with its material's
// model, so reading one sets "modelBrdf" to that and it keeps its look. Saving writes version 3.
constexpr int kSceneFormatVersion = 3;

Material materialFromJson(const Json& json, const std::string& pointer, const std::string& source,
                          bool requireHeader, std::vector<std::string>& warnings);
Material loadMaterialFile(const std::filesystem::path& path, std::vector<std::string>& warnings);
// The .json files directly in `folder` (a preset library), sorted by path; none for a folder
// that is missing or cannot be read.
std::vector<std::filesystem::path> materialFilesIn(const std::filesystem::path& folder);

// A scene's "material" may be a path, resolved relative to `baseDirectory`.
Scene sceneFromJson(const Json& json, const std::string& source,
                    const std::filesystem::path& baseDirectory, std::vector<std::string>& warnings);
Scene loadSceneFile(const std::filesystem::path& path, std::vector<std::string>& warnings);

// Unknown keys the material was read with (Material::extras) come back after the known ones.
Json materialToJson(const Material& material);
Json sceneToJson(const Scene& scene);   // the material inline

// Saves a material file atomically and keeps the file it replaces as PATH.bak. Throws
// std::runtime_error naming the path on failure; the previous file is then left as it was.
void saveMaterialFile(const std::filesystem::path& path, const Material& material);
// The same for a scene file (sceneToJson: the material inline, the mesh file by its path).
void saveSceneFile(const std::filesystem::path& path, const Scene& scene);

}  // namespace patina
