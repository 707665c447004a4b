#include "scene/prepared_scene.h"

#include <set>
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "model/placement.h"

namespace patina {

namespace {
[[noreturn]] void missing(size_t item, const char* what, int index, size_t count) {
    throw std::invalid_argument("draw item " + std::to_string(item) + " names " + what + " " + std::to_string(index) +
                                " of " + std::to_string(count));
}

// glTF's default material (section 3.9.6) as a model's: one for every draw that names none, so
// that a draw's `maps` may point at it.
const ModelMaterial& defaultMaterial() {
    static const ModelMaterial material = [] {
        ModelMaterial defaults;
        defaults.factors = defaultModelMaterial();
        return defaults;
    }();
    return material;
}

// Item `i` of `model` as drawn, or nothing when its MASK cutoff hides it whole.
std::optional<SceneDraw> modelDraw(const Scene& scene, const Model& model, size_t i) {
    const DrawItem& item = model.draws[i];
    if (item.primitive < 0 || size_t(item.primitive) >= model.primitives.size()) {
        missing(i, "primitive", item.primitive, model.primitives.size());
    }
    if (item.material >= 0 && size_t(item.material) >= model.materials.size()) {
        missing(i, "material", item.material, model.materials.size());
    }
    const ModelMaterial& material = item.material >= 0 ? model.materials[size_t(item.material)] : defaultMaterial();
    if (material.alphaMode == AlphaMode::Mask && !(material.baseAlpha >= material.alphaCutoff)) {
        return std::nullopt;
    }
    SceneDraw draw;
    draw.mesh = &model.primitives[size_t(item.primitive)];
    draw.primitive = item.primitive;
    draw.item = int(i);
    draw.transform = item.transform;
    draw.normalTransform = normalTransform(item.transform);
    const ModelMaterialEdit* edit = item.material >= 0 ? editOf(scene, item.material, material) : nullptr;
    draw.material = edit ? edit->material : material.factors;
    draw.material.model = scene.modelBrdf.value_or(draw.material.model);
    draw.doubleSided = material.doubleSided;
    draw.reverseBackNormals = material.doubleSided;
    draw.blend = material.alphaMode == AlphaMode::Blend;
    draw.alpha = draw.blend ? material.baseAlpha : 1.0f;
    if (edit && !edit->mapsOff.empty()) {
        draw.tunedMaps = std::make_shared<const ModelMaterial>(tunedMaterial(scene, item.material, material));
    }
    const ModelMaterial& maps = draw.tunedMaps ? *draw.tunedMaps : material;
    // Vertex colours multiply the base colour per pixel as a map does, so an item with them is
    // shaded with its maps, also under the default material.
    draw.maps = hasMaps(maps) || !draw.mesh->colors.empty() ? &maps : nullptr;
    draw.alphaCutoff = material.alphaMode == AlphaMode::Mask ? material.alphaCutoff : -1.0f;
    return draw;
}
}  // namespace

const ModelMaterialEdit* editOf(const Scene& scene, int index, const ModelMaterial& material) {
    for (const ModelMaterialEdit& edit : scene.modelMaterials) {
        if (edit.index == index && edit.material.name == material.name) {
            return &edit;
        }
    }
    return nullptr;
}

std::vector<std::string> unmatchedEdits(const Scene& scene, const Model& model) {
    std::vector<std::string> lines;
    for (const ModelMaterialEdit& edit : scene.modelMaterials) {
        const std::string entry = "modelMaterials: the tuning of material " + std::to_string(edit.index) + " \"" +
                                  edit.material.name + "\" is not drawn: ";
        if (edit.index < 0 || size_t(edit.index) >= model.materials.size()) {
            lines.push_back(entry + "the model has " + std::to_string(model.materials.size()) + " materials");
        } else if (const std::string& name = model.materials[size_t(edit.index)].name; name != edit.material.name) {
            lines.push_back(entry + "the model's material " + std::to_string(edit.index) + " is \"" + name + "\"");
        }
    }
    return lines;
}

ModelMaterial tunedMaterial(const Scene& scene, int index, const ModelMaterial& material) {
    ModelMaterial tuned = material;
    if (const ModelMaterialEdit* edit = editOf(scene, index, material)) {
        tuned.factors = edit->material;
        for (const auto& map : mapsOf(tuned)) {
            if (std::find(edit->mapsOff.begin(), edit->mapsOff.end(), map.key) != edit->mapsOff.end()) {
                *map.slot = TextureSlot{};
            }
        }
    }
    return tuned;
}

Model tunedModel(const Model& model, const Scene& scene) {
    Model tuned = model;
    for (size_t i = 0; i < tuned.materials.size(); ++i) {
        tuned.materials[i] = tunedMaterial(scene, int(i), model.materials[i]);
    }
    return tuned;
}

void setPartMaterials(Scene& scene, const Model& model, const Material& material, const std::string& part) {
    bool found = false;
    std::string names;   // each name once, in the file's order: several materials may share one
    std::set<std::string> named;
    for (size_t i = 0; i < model.materials.size(); ++i) {
        const std::string& name = model.materials[i].name;
        if (named.insert(name).second) {
            names += (names.empty() ? "\"" : ", \"") + name + "\"";
        }
        if (!part.empty() && name != part) {
            continue;
        }
        found = true;
        Material named = material;
        named.name = name;
        // An edit there keeps its maps left out and replaced, and the part its BRDF model: the
        // factors are what is named.
        const auto same = std::find_if(scene.modelMaterials.begin(), scene.modelMaterials.end(),
                                       [&](const ModelMaterialEdit& old) { return old.index == int(i); });
        const bool edited = same != scene.modelMaterials.end() && same->material.name == name;
        named.model = edited ? same->material.model : model.materials[i].factors.model;
        if (edited) {
            same->material = std::move(named);
            continue;
        }
        std::erase_if(scene.modelMaterials, [&](const ModelMaterialEdit& old) { return old.index == int(i); });
        scene.modelMaterials.push_back({int(i), std::move(named), Json::object()});
    }
    if (!found && !model.materials.empty()) {
        throw std::invalid_argument("the model has no part \"" + part + "\" (its parts: " + names + ")");
    }
}

bool hasMaps(const ModelMaterial& material) {
    return material.baseColor.present() || material.metallicRoughness.present() || material.normal.present() ||
           material.occlusion.present() || material.emissive.present() || material.emissiveFactor != glm::vec3(0.0f) ||
           material.clearcoat.present() || material.clearcoatRoughness.present() || material.clearcoatNormal.present() ||
           material.sheenColor.present() || material.sheenRoughness.present() || material.transmissionMap.present() ||
           material.thicknessMap.present() || material.specularColor.present() || material.specular.present() ||
           material.iridescenceMap.present() || material.iridescenceThickness.present() ||
           material.anisotropyMap.present();
}

int mapSetOf(const ModelMaterial& material) {
    int set = 0;
    int bit = 1;
    for (const auto& map : mapsOf(material)) {
        set |= map.slot->present() ? bit : 0;
        bit <<= 1;
    }
    return set;
}

MaterialParameters defaultModelMaterial() {
    MaterialParameters material;
    material.baseColor = glm::vec3(1.0f);
    material.metallic = 1.0f;
    material.roughness = 1.0f;
    material.specular = 0.5f;
    material.model = BrdfModelId::Gltf;
    return material;
}

std::vector<SceneDraw> sceneDraws(const PreparedScene& prepared) {
    if (!prepared.model) {
        if (!prepared.mesh) {
            throw std::invalid_argument("the scene's mesh was not prepared (assets/)");
        }
        SceneDraw draw;
        draw.mesh = prepared.mesh.get();
        draw.material = prepared.scene.material;
        draw.occlusion = prepared.occlusion ? itemOcclusion(*prepared.occlusion, -1, draw.mesh->positions.size()) : nullptr;
        return {draw};
    }
    std::vector<SceneDraw> draws;
    draws.reserve(prepared.model->draws.size());
    for (size_t i = 0; i < prepared.model->draws.size(); ++i) {
        if (std::optional<SceneDraw> draw = modelDraw(prepared.scene, *prepared.model, i)) {
            if (prepared.occlusion) {
                draw->occlusion = itemOcclusion(*prepared.occlusion, int(i), draw->mesh->positions.size());
            }
            draws.push_back(*draw);
        }
    }
    return draws;
}

}  // namespace patina
