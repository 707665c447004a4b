#include "state/undo_history.h"

#include <algorithm>
#include <initializer_list>

namespace patina::editor {

namespace {
// "a", "a and b"; `whole` for more: a preset or a file changes many fields at once.
std::string fieldsOr(const std::vector<std::string>& fields, const std::string& whole) {
    if (fields.size() == 1) {
        return fields[0];
    }
    return fields.size() == 2 ? fields[0] + " and " + fields[1] : whole;
}

// A layer's step in words (KHR_materials_*): "adding the clear coat" where it was absent (`had`
// false) and is present, "removing ..." the other way; within it, the one field that changed
// ("the clear coat's roughness"), or the layer where more did. "" where nothing did.
struct LayerField {
    bool changed;
    const char* name;
};
std::string layerChange(bool had, bool has, const char* layer, std::initializer_list<LayerField> fields) {
    const auto changed = std::count_if(fields.begin(), fields.end(), [](const LayerField& f) { return f.changed; });
    if (changed == 0) {
        return "";
    }
    if (had != has) {
        return std::string(has ? "adding " : "removing ") + layer;
    }
    if (changed == 1) {
        return std::find_if(fields.begin(), fields.end(), [](const LayerField& f) { return f.changed; })->name;
    }
    return layer;
}

// The fields of the factors that differ, in words: the core four one by one, each layer as one
// step (added, removed, or its one field: layerChange), named as the material panel names them.
std::vector<std::string> parameterChanges(const MaterialParameters& a, const MaterialParameters& b) {
    const std::string checks[] = {
        a.baseColor != b.baseColor ? "base colour" : "",
        a.roughness != b.roughness ? "roughness" : "",
        a.specular != b.specular ? "specular" : "",
        a.metallic != b.metallic ? "metallic" : "",
        a.model != b.model ? "the BRDF model" : "",
        layerChange(a.clearcoat > 0.0f, b.clearcoat > 0.0f, "the clear coat",
                    {{a.clearcoat != b.clearcoat, "the clear coat's strength"},
                     {a.clearcoatRoughness != b.clearcoatRoughness, "the clear coat's roughness"}}),
        layerChange(a.sheenColor != glm::vec3(0.0f), b.sheenColor != glm::vec3(0.0f), "the sheen",
                    {{a.sheenColor != b.sheenColor, "the sheen colour"},
                     {a.sheenRoughness != b.sheenRoughness, "the sheen's roughness"}}),
        layerChange(a.transmission > 0.0f, b.transmission > 0.0f, "the transmission",
                    {{a.transmission != b.transmission, "the transmission factor"}}),
        layerChange(true, true, "the volume",
                    {{a.thickness != b.thickness, "the thickness"},
                     {a.attenuationColor != b.attenuationColor, "the attenuation colour"},
                     {a.attenuationDistance != b.attenuationDistance, "the attenuation distance"}}),
        layerChange(a.anisotropyStrength > 0.0f, b.anisotropyStrength > 0.0f, "the anisotropy",
                    {{a.anisotropyStrength != b.anisotropyStrength, "the anisotropy strength"},
                     {a.anisotropyRotation != b.anisotropyRotation, "the anisotropy rotation"}}),
        layerChange(true, true, "the specular colour",
                    {{a.specularTint != b.specularTint, "the specular tint"},
                     {a.specularWeight != b.specularWeight, "the specular weight"}}),
        layerChange(a.iridescence > 0.0f, b.iridescence > 0.0f, "the thin film",
                    {{a.iridescence != b.iridescence, "the thin film's strength"},
                     {a.iridescenceIor != b.iridescenceIor, "the thin film's ior"},
                     {a.iridescenceThicknessMinimum != b.iridescenceThicknessMinimum, "the film thickness minimum"},
                     {a.iridescenceThicknessMaximum != b.iridescenceThicknessMaximum, "the film thickness"}})};
    std::vector<std::string> fields;
    for (const std::string& words : checks) {
        if (!words.empty()) {
            fields.push_back(words);
        }
    }
    return fields;
}

std::string materialChange(const Material& a, const Material& b) {
    // Another name and other values: another material (a preset, a model's) took its place.
    if (a.name != b.name && static_cast<const MaterialParameters&>(a) != b) {
        return "the material " + b.name;
    }
    std::vector<std::string> fields = parameterChanges(a, b);
    if (a.name != b.name) {
        fields.insert(fields.begin(), "the material's name");
    }
    if (a.notes != b.notes) {
        fields.push_back("the notes");
    }
    if (a.extras != b.extras) {
        fields.push_back("the material");
    }
    return fieldsOr(fields, "the material");
}

std::string lightsChange(const std::vector<Light>& a, const std::vector<Light>& b) {
    if (b.size() == a.size() + 1) {
        return "adding a light";
    }
    if (a.size() == b.size() + 1) {
        return "deleting a light";
    }
    std::vector<std::string> fields;
    for (size_t i = 0; i < a.size() && a.size() == b.size(); ++i) {
        if (a[i] != b[i]) {
            fields.push_back("the light " + b[i].name);
        }
    }
    return fields.size() == 1 ? fields[0] : "the lights";
}

// "saving the bookmark Front", "deleting the bookmark Front", "the bookmarks".
std::string bookmarksChange(const std::vector<CameraBookmark>& a, const std::vector<CameraBookmark>& b) {
    auto missingFrom = [](const std::vector<CameraBookmark>& from, const std::vector<CameraBookmark>& other) {
        for (const CameraBookmark& bookmark : other) {
            if (std::none_of(from.begin(), from.end(),
                             [&](const CameraBookmark& kept) { return kept.name == bookmark.name; })) {
                return bookmark.name;
            }
        }
        return std::string();
    };
    if (b.size() == a.size() + 1) {
        return "saving the bookmark " + missingFrom(a, b);
    }
    if (a.size() == b.size() + 1) {
        return "deleting the bookmark " + missingFrom(b, a);
    }
    for (size_t i = 0; i < a.size() && a.size() == b.size(); ++i) {
        if (a[i] != b[i] && a[i].name == b[i].name) {
            return "saving the bookmark " + b[i].name;   // saved again over itself
        }
    }
    return "the bookmarks";
}

std::string displayChange(const DisplaySettings& a, const DisplaySettings& b) {
    std::vector<std::string> fields;
    const std::pair<bool, const char*> checks[] = {
        {a.exposure != b.exposure, "exposure"},
        {a.tonemap != b.tonemap, "the tone map"},
        {a.background != b.background, "the background colour"},
        {a.backgroundFromEnvironment != b.backgroundFromEnvironment, "the environment as background"},
        {a.backgroundBlur != b.backgroundBlur, "the background blur"},
        {a.extras != b.extras, "the display settings"}};
    for (const auto& [changed, name] : checks) {
        if (changed) {
            fields.push_back(name);
        }
    }
    return fieldsOr(fields, "the display settings");
}
// "roughness of Texture": the first model material whose edit differs (one is edited at a time);
// a part's first tuning (or its last, undone) against the file's factors (`file`: the model as
// loaded, null when there is none).
std::string modelMaterialsChange(const std::vector<ModelMaterialEdit>& a, const std::vector<ModelMaterialEdit>& b,
                                 const Model* file) {
    auto find = [](const std::vector<ModelMaterialEdit>& edits, int index) -> const ModelMaterialEdit* {
        for (const ModelMaterialEdit& edit : edits) {
            if (edit.index == index) {
                return &edit;
            }
        }
        return nullptr;
    };
    for (const std::vector<ModelMaterialEdit>* side : {&b, &a}) {
        for (const ModelMaterialEdit& edit : *side) {
            const ModelMaterialEdit* before = find(a, edit.index);
            const ModelMaterialEdit* after = find(b, edit.index);
            if (!before || !after || *before != *after) {
                if (!before || !after) {   // made or removed: by a map switch when it leaves maps out
                    if (!edit.mapsOff.empty() || !edit.mapsReplaced.empty()) {
                        return "the maps of " + edit.material.name;
                    }
                    const bool known = file && edit.index >= 0 && size_t(edit.index) < file->materials.size();
                    const std::vector<std::string> fields =
                        known ? (before ? parameterChanges(before->material, file->materials[size_t(edit.index)].factors)
                                        : parameterChanges(file->materials[size_t(edit.index)].factors, after->material))
                              : std::vector<std::string>{};
                    return fields.empty() ? "the tuning of " + edit.material.name
                                          : fieldsOr(fields, "the tuning") + " of " + edit.material.name;
                }
                if (before->mapsOff != after->mapsOff || before->mapsReplaced != after->mapsReplaced) {
                    return "the maps of " + edit.material.name;
                }
                return materialChange(before->material, after->material) + " of " + edit.material.name;
            }
        }
    }
    return "the model's materials";
}
}  // namespace

std::string describeChange(const EditSnapshot& before, const EditSnapshot& after) {
    std::vector<std::string> parts;
    if (before.material != after.material) {
        parts.push_back(materialChange(before.material, after.material));
    }
    if (before.lights != after.lights) {
        parts.push_back(lightsChange(before.lights, after.lights));
    }
    if (before.display != after.display) {
        parts.push_back(displayChange(before.display, after.display));
    }
    if (before.modelMaterials != after.modelMaterials) {
        const std::shared_ptr<const LoadedModel>& file = after.shape.fileModel ? after.shape.fileModel
                                                                               : before.shape.fileModel;
        parts.push_back(modelMaterialsChange(before.modelMaterials, after.modelMaterials,
                                             file ? &file->model : nullptr));
    }
    if (before.modelBrdf != after.modelBrdf) {
        parts.push_back("the BRDF model of every part");
    }
    if (before.bookmarks != after.bookmarks) {
        parts.push_back(bookmarksChange(before.bookmarks, after.bookmarks));
    }
    if (before.shape != after.shape) {
        const ShownShape& shown = after.shape.file.empty() && !before.shape.file.empty() ? before.shape : after.shape;
        parts.insert(parts.begin(), "the mesh (" +
                                        (shown.file.empty() ? std::string(meshKindName(shown.kind))
                                                            : std::filesystem::path(shown.file).filename().string()) +
                                        ")");
    }
    std::string text;
    for (size_t i = 0; i < parts.size(); ++i) {
        text += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
    }
    return text;
}

void UndoHistory::record(EditSnapshot before) {
    undo_.push_back(std::move(before));
    if (undo_.size() > limit_) {
        undo_.pop_front();
    }
    redo_.clear();
}

std::optional<EditSnapshot> UndoHistory::undo(EditSnapshot current) {
    if (undo_.empty()) {
        return std::nullopt;
    }
    EditSnapshot previous = std::move(undo_.back());
    undo_.pop_back();
    redo_.push_back(std::move(current));
    return previous;
}

std::optional<EditSnapshot> UndoHistory::redo(EditSnapshot current) {
    if (redo_.empty()) {
        return std::nullopt;
    }
    EditSnapshot next = std::move(redo_.back());
    redo_.pop_back();
    undo_.push_back(std::move(current));
    return next;
}

}  // namespace patina::editor
