#include "io/scene_file.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>

#include "environment/builtin_environments.h"
#include "shading/brdf_models.h"
#include "io/file_kinds.h"
#include "files/file_bytes.h"
#include "io/json_writer.h"
#include "model/model.h"
#include "shading/shading.h"

namespace patina {

namespace {
constexpr Range kUnit{0.0, 1.0};
constexpr Range kNonNegative{0.0, 3.4e38};
// KHR_materials_volume's thickness and attenuation distance, in model units (0: none, infinite).
constexpr Range kThickness{0.0, 1.0e6};
// KHR_materials_anisotropy's rotation, in radians (gltf::kMaxAnisotropyRotation's bound).
constexpr Range kRotation{-1.0e4, 1.0e4};
// KHR_materials_specular's tint of 0.08 specular: F0 reaches 1 at 12.5 (shading/material_parameters.h).
constexpr Range kSpecularTint{0.0, 12.5};
// KHR_materials_iridescence's film: its ior (the schema's at least 1) and thicknesses in nm.
constexpr Range kFilmIor{1.0, 10.0};
constexpr Range kFilmThickness{0.0, 1.0e5};

// The shortest decimal that reads back as the same float, so files say 0.8, not
// 0.800000011920929.
double toJson(float value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text - 1, value);
    *result.ptr = '\0';
    return std::strtod(text, nullptr);
}

Json toJson(glm::vec3 v) {
    return Json::array({toJson(v.x), toJson(v.y), toJson(v.z)});
}

// Kept unknown keys go back after the known ones; a known key always wins over an extra.
Json withExtras(Json json, const Json& extras) {
    for (auto it = extras.begin(); it != extras.end(); ++it) {
        if (!json.contains(it.key())) {
            json[it.key()] = it.value();
        }
    }
    return json;
}

// Whether `value` has more than `levels` levels of arrays and objects; looks no deeper.
bool nestsDeeperThan(const Json& value, int levels) {
    if (!value.is_structured()) {
        return false;
    }
    if (levels == 0) {
        return true;
    }
    for (const Json& child : value) {
        if (nestsDeeperThan(child, levels - 1)) {
            return true;
        }
    }
    return false;
}

// "builtin:NAME" of a known built-in, or a path made absolute against the scene's folder.
std::string environmentSource(JsonObjectReader& reader, const std::filesystem::path& baseDirectory) {
    const std::string value = reader.string("source", builtinSource("studio"));
    if (const auto name = builtinName(value)) {
        std::string known;
        for (std::string_view builtin : builtinEnvironmentNames()) {
            if (builtin == *name) {
                return value;
            }
            known += (known.empty() ? "" : ", ") + builtinSource(builtin);
        }
        reader.fail("source", "unknown built-in environment " + shortJson(value) + " (known: " + known + ")");
    }
    if (value.empty()) {
        reader.fail("source", "an environment needs a source (\"builtin:studio\" or an .hdr or .exr file)");
    }
    return std::filesystem::absolute(baseDirectory / value).lexically_normal().string();
}

Light lightFromJson(const Json& json, int version, const std::string& pointer, const std::string& source,
                    const std::filesystem::path& baseDirectory, std::vector<std::string>& warnings) {
    JsonObjectReader reader(json, pointer, source);
    Light light;
    const Json& typeValue = reader.required("type");
    const auto type = typeValue.is_string() ? lightTypeFromName(typeValue.get<std::string>())
                                            : std::nullopt;
    if (!type) {
        reader.fail("type", "unknown light type " + shortJson(typeValue) +
                                " (expected \"point\", \"sphere\", \"tube\", \"directional\", \"hemisphere\" or \"environment\")");
    }
    light.type = *type;
    light.name = reader.string("name", std::string(lightTypeName(light.type)));
    light.enabled = reader.boolean("enabled", true);
    // An environment's colour is its image's: a "color" key there is another type's key, kept
    // as unknown (read, it would be lost on save, which writes none).
    if (light.type != LightType::Environment) {
        light.color = reader.vec3("color", light.color, kNonNegative);
    }
    light.intensity = reader.number("intensity", light.intensity, kNonNegative);
    light.shadows = reader.boolean("shadows", false);
    // A hemisphere or an environment has no position or direction to cast from: said, not drawn.
    if (light.shadows && !castsShadows(light.type)) {
        warnings.push_back(source + ": " + reader.pointerOf("shadows") + ": " + std::string(lightTypeName(light.type)) +
                           " lights cast no shadows (only point, sphere, tube and directional lights do); ignored");
        light.shadows = false;
    }
    switch (light.type) {
    case LightType::Point:
        light.position = reader.vec3("position", light.position);
        light.range = reader.number(version >= 2 ? "range" : "radius", light.range, kNonNegative);
        // In a version 1 file "range" means nothing; kept as an unknown key it would become the
        // window once saved as version 2 (or be lost under the written one), so it is dropped.
        if (version < 2 && reader.child("range")) {
            warnings.push_back(source + ": " + reader.pointerOf("range") +
                               ": 'range' is not a key of scene version 1 (there the window is 'radius'); ignored");
        }
        light.attenuation = reader.vec3("attenuation", light.attenuation, kNonNegative);
        break;
    // Area lights came with version 2, where the window is "range"; a size must be finite and
    // not negative (the reader names the key otherwise).
    case LightType::Sphere:
    case LightType::Tube:
        if (light.type == LightType::Sphere) {
            light.position = reader.vec3("position", light.position);
        } else {
            light.start = reader.vec3("start", light.start);
            light.end = reader.vec3("end", light.end);
        }
        light.sourceRadius = reader.number("sourceRadius", light.sourceRadius, kNonNegative);
        light.range = reader.number("range", light.range, kNonNegative);
        light.attenuation = reader.vec3("attenuation", light.attenuation, kNonNegative);
        break;
    case LightType::Directional:
        light.direction = reader.vec3("direction", light.direction);
        if (glm::dot(light.direction, light.direction) == 0.0f) {
            reader.fail("direction", "a directional light needs a non-zero direction");
        }
        break;
    case LightType::Hemisphere:
        light.sky = reader.vec3("sky", light.sky, kNonNegative);
        light.ground = reader.vec3("ground", light.ground, kNonNegative);
        break;
    case LightType::Environment:
        light.source = environmentSource(reader, baseDirectory);
        light.rotationDegrees = reader.number("rotationDegrees", light.rotationDegrees, {-3600.0, 3600.0});
        break;
    }
    light.extras = reader.keepUnknown(warnings);
    return light;
}

// The objects of the array at top-level `key`, each read in turn by read(reader, pointer,
// earlier) with `earlier` the ones read before it (to refuse a repeat); InputError "SOURCE: /KEY:
// expected an array of WHAT" for anything but an array.
template <typename T, typename Read>
std::vector<T> objectsFromJson(const Json& json, const std::string& key, const char* what, const std::string& source,
                               Read read) {
    if (!json.is_array()) {
        throw InputError(source + ": /" + key + ": expected an array of " + what);
    }
    std::vector<T> objects;
    for (size_t i = 0; i < json.size(); ++i) {
        const std::string pointer = "/" + key + "/" + std::to_string(i);
        JsonObjectReader reader(json[i], pointer, source);
        objects.push_back(read(reader, pointer, static_cast<const std::vector<T>&>(objects)));
    }
    return objects;
}

Camera cameraFromJson(const Json& json, const std::string& pointer, const std::string& source,
                      std::vector<std::string>& warnings) {
    JsonObjectReader reader(json, pointer, source);
    Camera camera;
    camera.position = reader.vec3("position", camera.position);
    camera.target = reader.vec3("target", camera.target);
    camera.fovYDegrees = reader.number("fovYDegrees", camera.fovYDegrees, {1.0, 179.0});
    if (camera.position == camera.target) {
        reader.fail("target", "the camera target equals its position");
    }
    camera.extras = reader.keepUnknown(warnings);
    return camera;
}

// "bookmarks": [{"name": "Front", "camera": {a camera, as "camera"}}, ...]: each named, no name
// twice.
std::vector<CameraBookmark> bookmarksFromJson(const Json& json, const std::string& source,
                                              std::vector<std::string>& warnings) {
    return objectsFromJson<CameraBookmark>(
        json, "bookmarks", "camera bookmarks", source,
        [&](JsonObjectReader& reader, const std::string&, const std::vector<CameraBookmark>& earlier) {
            CameraBookmark bookmark;
            reader.required("name");
            bookmark.name = reader.string("name", "");
            if (bookmark.name.empty()) {
                reader.fail("name", "a bookmark needs a name");
            }
            for (const CameraBookmark& before : earlier) {
                if (before.name == bookmark.name) {
                    reader.fail("name", "the name " + shortJson(bookmark.name) + " is used twice");
                }
            }
            bookmark.camera = cameraFromJson(reader.required("camera"), reader.pointerOf("camera"), source, warnings);
            bookmark.extras = reader.keepUnknown(warnings);
            return bookmark;
        });
}

DisplaySettings displayFromJson(const Json& json, const std::string& pointer,
                                const std::string& source, std::vector<std::string>& warnings) {
    JsonObjectReader reader(json, pointer, source);
    DisplaySettings display;
    display.exposure = reader.number("exposure", display.exposure, {-20.0, 20.0});
    const std::string tonemap = reader.string("tonemap", "none");
    const auto parsed = tonemapFromName(tonemap);
    if (!parsed) {
        reader.fail("tonemap", "unknown tone map " + shortJson(tonemap) + " (known: " + tonemapNames() + ")");
    }
    display.tonemap = *parsed;
    // The scene's environment itself behind the mesh, blurred to a roughness (the colour stays
    // for a scene without one). "background": "environment" says the same (issue 18's
    // spelling); it is written back as the boolean beside the default colour.
    const Json* background = reader.child("background");
    const bool environmentNamed = background && background->is_string() && *background == "environment";
    if (!environmentNamed) {
        display.background = reader.vec3("background", display.background, kNonNegative);
    }
    display.backgroundFromEnvironment = reader.boolean("backgroundEnvironment", environmentNamed);
    display.backgroundBlur = reader.number("backgroundBlur", display.backgroundBlur, kUnit);
    const std::string ground = reader.string("ground", "none");
    const auto groundParsed = groundFromName(ground);
    if (!groundParsed) {
        reader.fail("ground", "unknown ground " + shortJson(ground) + " (known: " + groundNames() + ")");
    }
    display.ground = *groundParsed;
    display.groundColor = reader.vec3("groundColor", display.groundColor, kNonNegative);
    display.groundRoughness = reader.number("groundRoughness", display.groundRoughness, kUnit);
    display.ambientOcclusion = reader.boolean("ambientOcclusion", false);
    display.extras = reader.keepUnknown(warnings);
    return display;
}

Json lightToJson(const Light& light) {
    Json json{{"type", lightTypeName(light.type)},
              {"name", light.name},
              {"enabled", light.enabled},
              {"color", toJson(light.color)},
              {"intensity", toJson(light.intensity)}};
    if (light.shadows) {
        json["shadows"] = true;
    }
    switch (light.type) {
    case LightType::Point:
        json["position"] = toJson(light.position);
        json["range"] = toJson(light.range);
        json["attenuation"] = toJson(light.attenuation);
        break;
    case LightType::Sphere:
    case LightType::Tube:
        if (light.type == LightType::Sphere) {
            json["position"] = toJson(light.position);
        } else {
            json["start"] = toJson(light.start);
            json["end"] = toJson(light.end);
        }
        json["sourceRadius"] = toJson(light.sourceRadius);
        json["range"] = toJson(light.range);
        json["attenuation"] = toJson(light.attenuation);
        break;
    case LightType::Directional: json["direction"] = toJson(light.direction); break;
    case LightType::Hemisphere:
        json["sky"] = toJson(light.sky);
        json["ground"] = toJson(light.ground);
        break;
    case LightType::Environment:
        json.erase("color");
        json["source"] = light.source;
        json["rotationDegrees"] = toJson(light.rotationDegrees);
        break;
    }
    return withExtras(json, light.extras);
}
}  // namespace

namespace {
// A BRDF model by its name (shading/brdf_models.h), the key required to be a known one.
BrdfModelId brdfModelFromJson(JsonObjectReader& reader, const char* key) {
    const std::string name = reader.string(key, "");
    const auto id = brdfModelFromName(name);
    if (!id) {
        reader.fail(key, "unknown BRDF model " + shortJson(name) + " (known: " + brdfModelNames() + ")");
    }
    return *id;
}
}  // namespace

Material materialFromJson(const Json& json, const std::string& pointer, const std::string& source,
                          bool requireHeader, std::vector<std::string>& warnings) {
    JsonObjectReader reader(json, pointer, source);
    if (requireHeader || reader.has("format") || reader.has("version")) {
        reader.checkFormatAndVersion("patina-material", kMaterialFormatVersion);
    }
    Material material;
    material.name = reader.string("name", material.name);
    material.baseColor = reader.vec3("baseColor", material.baseColor, kUnit);
    material.roughness = reader.number("roughness", material.roughness, kUnit);
    material.specular = reader.number("specular", material.specular, kUnit);
    material.metallic = reader.number("metallic", material.metallic, kUnit);
    material.clearcoat = reader.number("clearcoat", material.clearcoat, kUnit);
    material.clearcoatRoughness = reader.number("clearcoatRoughness", material.clearcoatRoughness, kUnit);
    material.sheenColor = reader.vec3("sheenColor", material.sheenColor, kUnit);
    material.sheenRoughness = reader.number("sheenRoughness", material.sheenRoughness, kUnit);
    material.transmission = reader.number("transmission", material.transmission, kUnit);
    material.thickness = reader.number("thickness", material.thickness, kThickness);
    material.attenuationColor = reader.vec3("attenuationColor", material.attenuationColor, kUnit);
    material.attenuationDistance = reader.number("attenuationDistance", material.attenuationDistance, kThickness);
    material.anisotropyStrength = reader.number("anisotropyStrength", material.anisotropyStrength, kUnit);
    material.anisotropyRotation = reader.number("anisotropyRotation", material.anisotropyRotation, kRotation);
    material.specularTint = reader.vec3("specularTint", material.specularTint, kSpecularTint);
    material.specularWeight = reader.number("specularWeight", material.specularWeight, kUnit);
    material.iridescence = reader.number("iridescence", material.iridescence, kUnit);
    material.iridescenceIor = reader.number("iridescenceIor", material.iridescenceIor, kFilmIor);
    material.iridescenceThicknessMinimum =
        reader.number("iridescenceThicknessMinimum", material.iridescenceThicknessMinimum, kFilmThickness);
    material.iridescenceThicknessMaximum =
        reader.number("iridescenceThicknessMaximum", material.iridescenceThicknessMaximum, kFilmThickness);
    if (reader.has("model")) {
        material.model = brdfModelFromJson(reader, "model");
    }
    material.notes = reader.string("notes", material.notes);
    material.extras = reader.keepUnknown(warnings);
    // Saved inline in a scene (a screenshot's), the material is one level down: it must still
    // fit in kMaxJsonNesting there, counting itself.
    for (auto it = material.extras.begin(); it != material.extras.end(); ++it) {
        if (nestsDeeperThan(it.value(), kMaxJsonNesting - 2)) {
            reader.fail(it.key().c_str(), "nested deeper than " + std::to_string(kMaxJsonNesting - 2) +
                                              " levels (a material must fit inside a scene)");
        }
    }
    return material;
}

std::vector<std::filesystem::path> materialFilesIn(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        if (entry.path().extension() == ".json") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

Material loadMaterialFile(const std::filesystem::path& path, std::vector<std::string>& warnings) {
    if (!gltfExtension(path).empty()) {
        throw InputError(path.string() + ": a glTF model, not a material (a model is a scene's \"mesh\", or --mesh)");
    }
    return materialFromJson(readJsonFile(path), "", path.string(), true, warnings);
}

namespace {
// Whether `name` is a map's key (model/model.h mapsOf), and the keys for a message.
bool isMapKey(const std::string& name) {
    const ModelMaterial none;
    return mapWithKey(none, name).has_value();
}
std::string mapKeys() {
    std::string keys;
    const ModelMaterial none;
    for (const auto& map : mapsOf(none)) {
        keys += (keys.empty() ? "" : ", ") + std::string(map.key);
    }
    return keys;
}

// "mapsOff": ["normalTexture", ...]: each a map's key, once.
std::vector<std::string> mapKeysFromJson(const Json& json, const std::string& pointer, const std::string& source) {
    if (!json.is_array()) {
        failAt(source, pointer, "expected an array of map names (" + mapKeys() + ")");
    }
    std::vector<std::string> names;
    for (size_t i = 0; i < json.size(); ++i) {
        const std::string at = pointer + "/" + std::to_string(i);
        const std::string name = json[i].is_string() ? json[i].get<std::string>() : "";
        if (!isMapKey(name)) {
            failAt(source, at, "expected the name of a map (" + mapKeys() + ")");
        }
        if (std::find(names.begin(), names.end(), name) != names.end()) {
            failAt(source, at, "\"" + name + "\" is named twice");
        }
        names.push_back(name);
    }
    return names;
}

// "mapsReplaced": {"baseColorTexture": "textures/worn.png", ...}: a map's key and the image put in
// its place, made absolute against the scene's folder. A key that names no map is warned about
// and kept in `extras`, as unknown keys are elsewhere.
std::map<std::string, std::string> replacedMapsFromJson(const Json& json, const std::string& pointer,
                                                        const std::string& source,
                                                        const std::filesystem::path& baseDirectory,
                                                        Json& extras, std::vector<std::string>& warnings) {
    if (!json.is_object()) {
        failAt(source, pointer, "expected an object from a map's name to an image file (\"baseColorTexture\": "
                                "\"worn.png\")");
    }
    std::map<std::string, std::string> replaced;
    for (const auto& [key, value] : json.items()) {
        if (!isMapKey(key)) {
            warnings.push_back(source + ": " + pointer + "/" + key + ": unknown key '" + key +
                               "' (kept, not used: it names no map)");
            extras[key] = value;
            continue;
        }
        if (!value.is_string() || value.get<std::string>().empty()) {
            failAt(source, pointer + "/" + key, "expected the path of a PNG or JPEG image");
        }
        replaced[key] = std::filesystem::absolute(baseDirectory / value.get<std::string>()).lexically_normal().string();
    }
    return replaced;
}

// "modelMaterials": [{"index": N, "material": {a material, its name the key}, "mapsOff": [...],
// "mapsReplaced": {...}}, ...], one per index.
std::vector<ModelMaterialEdit> modelMaterialsFromJson(const Json& json, const std::string& source,
                                                      const std::filesystem::path& baseDirectory,
                                                      std::vector<std::string>& warnings) {
    return objectsFromJson<ModelMaterialEdit>(
        json, "modelMaterials", "edited model materials", source,
        [&](JsonObjectReader& reader, const std::string& pointer, const std::vector<ModelMaterialEdit>& earlier) {
            ModelMaterialEdit edit;
            reader.required("index");
            edit.index = reader.integer("index", 0, {0.0, double(1 << 20)});
            edit.material =
                materialFromJson(reader.required("material"), pointer + "/material", source, false, warnings);
            if (const Json* off = reader.child("mapsOff")) {
                edit.mapsOff = mapKeysFromJson(*off, reader.pointerOf("mapsOff"), source);
            }
            if (const Json* replaced = reader.child("mapsReplaced")) {
                edit.mapsReplaced =
                    replacedMapsFromJson(*replaced, reader.pointerOf("mapsReplaced"), source, baseDirectory,
                                         edit.mapsReplacedExtras, warnings);
            }
            for (const ModelMaterialEdit& before : earlier) {
                if (before.index == edit.index) {
                    reader.fail("index", "material " + std::to_string(edit.index) + " is edited twice");
                }
            }
            edit.extras = reader.keepUnknown(warnings);
            return edit;
        });
}
}  // namespace

Scene sceneFromJson(const Json& json, const std::string& source,
                    const std::filesystem::path& baseDirectory, std::vector<std::string>& warnings) {
    JsonObjectReader reader(json, "", source);
    const int version = reader.checkFormatAndVersion("patina-scene", kSceneFormatVersion);
    Scene scene;
    const std::string mesh = reader.string("mesh", "sphere");
    if (const auto meshKind = meshKindFromName(mesh)) {
        scene.mesh = *meshKind;
    } else if (!gltfExtension(mesh).empty()) {
        // Absolute, so that the scene reads the same file wherever it is written back to.
        scene.meshFile = std::filesystem::absolute(baseDirectory / mesh).lexically_normal().string();
    } else {
        reader.fail("mesh", "unknown mesh " + shortJson(mesh) +
                                " (expected \"sphere\", \"torus\" or a .gltf or .glb file)");
    }
    if (const Json* material = reader.child("material")) {
        if (material->is_string()) {
            const std::filesystem::path materialPath = baseDirectory / material->get<std::string>();
            scene.material = loadMaterialFile(materialPath, warnings);
        } else {
            scene.material = materialFromJson(*material, "/material", source, false, warnings);
        }
    }
    if (const Json* edits = reader.child("modelMaterials")) {
        scene.modelMaterials = modelMaterialsFromJson(*edits, source, baseDirectory, warnings);
    }
    if (reader.has("modelBrdf")) {
        scene.modelBrdf = brdfModelFromJson(reader, "modelBrdf");
    } else if (version < 3 && !scene.meshFile.empty()) {
        scene.modelBrdf = scene.material.model;   // how versions 1 and 2 shaded a model (kSceneFormatVersion)
    }
    if (const Json* camera = reader.child("camera")) {
        scene.camera = cameraFromJson(*camera, "/camera", source, warnings);
    }
    if (const Json* bookmarks = reader.child("bookmarks")) {
        scene.bookmarks = bookmarksFromJson(*bookmarks, source, warnings);
    }
    if (const Json* lights = reader.child("lights")) {
        if (!lights->is_array()) {
            reader.fail("lights", "expected an array of lights");
        }
        if (lights->size() > size_t(shader::MAX_LIGHTS)) {
            reader.fail("lights", std::to_string(lights->size()) + " lights; at most " +
                                      std::to_string(shader::MAX_LIGHTS) + " are supported");
        }
        for (size_t i = 0; i < lights->size(); ++i) {
            const std::string pointer = "/lights/" + std::to_string(i);
            Light light = lightFromJson((*lights)[i], version, pointer, source, baseDirectory, warnings);
            if (light.type == LightType::Environment &&
                std::any_of(scene.lights.begin(), scene.lights.end(),
                            [](const Light& l) { return l.type == LightType::Environment; })) {
                throw InputError(source + ": " + pointer +
                                 ": a second environment light (a scene has at most one environment)");
            }
            scene.lights.push_back(std::move(light));
        }
    } else {
        scene.lights.clear();
    }
    if (const Json* display = reader.child("display")) {
        scene.display = displayFromJson(*display, "/display", source, warnings);
    }
    scene.extras = reader.keepUnknown(warnings);
    return scene;
}

Scene loadSceneFile(const std::filesystem::path& path, std::vector<std::string>& warnings) {
    return sceneFromJson(readJsonFile(path), path.string(), path.parent_path(), warnings);
}

Json materialToJson(const Material& material) {
    Json json{{"format", "patina-material"},
              {"version", kMaterialFormatVersion},
              {"name", material.name},
              {"baseColor", toJson(material.baseColor)},
              {"roughness", toJson(material.roughness)},
              {"specular", toJson(material.specular)},
              {"metallic", toJson(material.metallic)},
              {"model", brdfModel(material.model).name}};
    // KHR_materials_clearcoat's factors only where there is a coat: a material without one is
    // written as before it existed.
    if (material.clearcoat != 0.0f || material.clearcoatRoughness != 0.0f) {
        json["clearcoat"] = toJson(material.clearcoat);
        json["clearcoatRoughness"] = toJson(material.clearcoatRoughness);
    }
    // KHR_materials_sheen's the same way.
    if (material.sheenColor != glm::vec3(0.0f) || material.sheenRoughness != 0.0f) {
        json["sheenColor"] = toJson(material.sheenColor);
        json["sheenRoughness"] = toJson(material.sheenRoughness);
    }
    // KHR_materials_transmission's only where light passes.
    if (material.transmission != 0.0f) {
        json["transmission"] = toJson(material.transmission);
    }
    // KHR_materials_volume's wherever one is set, with or without a transmission: a file that
    // sets a volume first and the transmission later must not lose the volume when saved
    // between (the fuzzer's amber glass with its "transmission" key misspelt did).
    if (material.thickness != 0.0f || material.attenuationColor != glm::vec3(1.0f) ||
        material.attenuationDistance != 0.0f) {
        json["thickness"] = toJson(material.thickness);
        json["attenuationColor"] = toJson(material.attenuationColor);
        json["attenuationDistance"] = toJson(material.attenuationDistance);
    }
    // KHR_materials_anisotropy's, each only where it is not its default: a rotation kept without
    // a strength (it draws nothing) still comes back as it was read.
    if (material.anisotropyStrength != 0.0f) {
        json["anisotropyStrength"] = toJson(material.anisotropyStrength);
    }
    if (material.anisotropyRotation != 0.0f) {
        json["anisotropyRotation"] = toJson(material.anisotropyRotation);
    }
    // KHR_materials_specular's tint and weight, each only where it is not its default.
    if (material.specularTint != glm::vec3(1.0f)) {
        json["specularTint"] = toJson(material.specularTint);
    }
    if (material.specularWeight != 1.0f) {
        json["specularWeight"] = toJson(material.specularWeight);
    }
    // KHR_materials_iridescence's, all four wherever one is not its default.
    const MaterialParameters plain;
    if (material.iridescence != plain.iridescence || material.iridescenceIor != plain.iridescenceIor ||
        material.iridescenceThicknessMinimum != plain.iridescenceThicknessMinimum ||
        material.iridescenceThicknessMaximum != plain.iridescenceThicknessMaximum) {
        json["iridescence"] = toJson(material.iridescence);
        json["iridescenceIor"] = toJson(material.iridescenceIor);
        json["iridescenceThicknessMinimum"] = toJson(material.iridescenceThicknessMinimum);
        json["iridescenceThicknessMaximum"] = toJson(material.iridescenceThicknessMaximum);
    }
    if (!material.notes.empty()) {
        json["notes"] = material.notes;
    }
    return withExtras(json, material.extras);
}

namespace {
void saveWithBackup(const std::filesystem::path& path, const Json& json) {
    // The previous version goes to PATH.bak first, itself atomically: whenever this stops,
    // both files hold a complete version.
    std::error_code error;
    if (std::filesystem::is_regular_file(path, error)) {
        std::filesystem::path backup = path;
        backup += ".bak";
        writeFileAtomic(backup, readFileBytes(path));
    }
    const std::string text = prettyJson(json);
    writeFileAtomic(path, std::vector<uint8_t>(text.begin(), text.end()));
}
}  // namespace

void saveMaterialFile(const std::filesystem::path& path, const Material& material) {
    saveWithBackup(path, materialToJson(material));
}

namespace {
// `file` as the scene file in `folder` names it: relative where it lies in that folder or below
// it (so the folder can move or be shared whole), as it is elsewhere (absolute) or when empty.
std::string namedFrom(const std::filesystem::path& folder, const std::string& file) {
    if (file.empty()) {
        return file;
    }
    const std::filesystem::path whole = std::filesystem::absolute(file).lexically_normal();
    const std::filesystem::path base = folder.empty() ? std::filesystem::current_path() : std::filesystem::absolute(folder);
    const std::filesystem::path relative = whole.lexically_relative(base.lexically_normal());
    const bool inside = !relative.empty() && *relative.begin() != "..";
    return inside ? relative.generic_string() : file;
}

// The scene as a file at `path` writes it: the mesh, environment images and replaced maps it
// reads named relative to its folder where they lie in it or below (loading makes every path
// absolute against the file's folder, so either form reads back the same files).
Scene withPathsFrom(const std::filesystem::path& folder, Scene scene) {
    scene.meshFile = namedFrom(folder, scene.meshFile);
    for (Light& light : scene.lights) {
        if (light.type == LightType::Environment && !builtinName(light.source)) {
            light.source = namedFrom(folder, light.source);
        }
    }
    for (ModelMaterialEdit& edit : scene.modelMaterials) {
        for (auto& [key, image] : edit.mapsReplaced) {
            image = namedFrom(folder, image);
        }
    }
    return scene;
}
}  // namespace

void saveSceneFile(const std::filesystem::path& path, const Scene& scene) {
    saveWithBackup(path, sceneToJson(withPathsFrom(path.parent_path(), scene)));
}

namespace {
Json cameraToJson(const Camera& camera) {
    return withExtras({{"position", toJson(camera.position)},
                       {"target", toJson(camera.target)},
                       {"fovYDegrees", toJson(camera.fovYDegrees)}},
                      camera.extras);
}

Json displayToJson(const DisplaySettings& display) {
    Json json{{"exposure", toJson(display.exposure)},
              {"tonemap", tonemapName(display.tonemap)},
              {"background", toJson(display.background)}};
    if (display.backgroundFromEnvironment || display.backgroundBlur != 0.0f) {
        json["backgroundEnvironment"] = display.backgroundFromEnvironment;
        json["backgroundBlur"] = toJson(display.backgroundBlur);
    }
    // Written only where set, so that a scene without a ground saves as it always has.
    const DisplaySettings defaults;
    if (display.ground != Ground::None || display.groundColor != defaults.groundColor ||
        display.groundRoughness != defaults.groundRoughness) {
        json["ground"] = groundName(display.ground);
        json["groundColor"] = toJson(display.groundColor);
        json["groundRoughness"] = toJson(display.groundRoughness);
    }
    if (display.ambientOcclusion) {
        json["ambientOcclusion"] = true;   // only where on, as the ground
    }
    return json;
}
}  // namespace

Json sceneToJson(const Scene& scene) {
    Json lights = Json::array();
    for (const Light& light : scene.lights) {
        lights.push_back(lightToJson(light));
    }
    const DisplaySettings& display = scene.display;
    Json json =
        Json{{"format", "patina-scene"},
             {"version", kSceneFormatVersion},
             {"mesh", scene.meshFile.empty() ? std::string(meshKindName(scene.mesh)) : scene.meshFile},
             {"material", materialToJson(scene.material)},
             {"camera", cameraToJson(scene.camera)},
             {"lights", lights},
             {"display", withExtras(displayToJson(display), display.extras)}};
    if (scene.modelBrdf) {
        json["modelBrdf"] = brdfModel(*scene.modelBrdf).name;
    }
    if (!scene.bookmarks.empty()) {   // only a scene with bookmarks has the key
        Json bookmarks = Json::array();
        for (const CameraBookmark& bookmark : scene.bookmarks) {
            bookmarks.push_back(
                withExtras({{"name", bookmark.name}, {"camera", cameraToJson(bookmark.camera)}}, bookmark.extras));
        }
        json["bookmarks"] = bookmarks;
    }
    if (!scene.modelMaterials.empty()) {   // only a tuned model's scene has the key
        Json edits = Json::array();
        for (const ModelMaterialEdit& edit : scene.modelMaterials) {
            Json entry{{"index", edit.index}, {"material", materialToJson(edit.material)}};
            if (!edit.mapsOff.empty()) {   // written only where a map is left out
                entry["mapsOff"] = edit.mapsOff;
            }
            if (!edit.mapsReplaced.empty() || !edit.mapsReplacedExtras.empty()) {
                entry["mapsReplaced"] = withExtras(Json(edit.mapsReplaced), edit.mapsReplacedExtras);
            }
            edits.push_back(withExtras(entry, edit.extras));
        }
        json["modelMaterials"] = edits;
    }
    return withExtras(json, scene.extras);
}

}  // namespace patina
