#pragma once
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assets/loaded_model.h"
#include "model/model.h"
#include "scene/scene.h"

namespace patina::editor {

// The shape shown: a built-in kind or a glTF file, with what was loaded for it (held, so that
// an undo reloads nothing) and the camera that showed it. Two are the same shape when kind and
// file are: the camera is a view, not an edit to step back through, and is put back only with
// the shape it framed.
struct ShownShape {
    MeshKind kind = MeshKind::Sphere;
    std::string file;
    std::shared_ptr<const LoadedModel> fileModel;   // Document::fileModel
    std::shared_ptr<const Model> model;              // Document::model
    Camera camera;
    bool operator==(const ShownShape& other) const { return kind == other.kind && file == other.file; }
};

// What undo restores: the material, the light list and the display settings (exposure, tone
// map, background), each a choice an artist makes and may want back, the model's tuning, the
// shape shown (opening a model and fitting the lights to it is one step), and the camera
// bookmarks (saving one is a step; going to one is a view, as orbiting is).
struct EditSnapshot {
    Material material;
    std::vector<Light> lights;
    DisplaySettings display;
    std::vector<ModelMaterialEdit> modelMaterials;   // the scene's model's materials as tuned
    std::optional<BrdfModelId> modelBrdf;            // Scene::modelBrdf
    ShownShape shape;
    std::vector<CameraBookmark> bookmarks;           // Scene::bookmarks

    bool operator==(const EditSnapshot&) const = default;
};

// What an edit from `before` to `after` changed, in words for the status line ("Undid
// roughness", "Redid adding a light"): the fields when one or two changed, else the part
// ("the material", "the lights", "the display settings").
std::string describeChange(const EditSnapshot& before, const EditSnapshot& after);

// Linear undo/redo over snapshots. record() takes the state from before an edit; a new edit
// clears the redo side. The oldest steps fall off past `limit`.
class UndoHistory {
public:
    explicit UndoHistory(size_t limit = 256) : limit_(limit) {}

    void record(EditSnapshot before);
    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    size_t undoSteps() const { return undo_.size(); }
    // The snapshot to restore, given the current one (which moves to the other side).
    std::optional<EditSnapshot> undo(EditSnapshot current);
    std::optional<EditSnapshot> redo(EditSnapshot current);

private:
    size_t limit_;
    std::deque<EditSnapshot> undo_;
    std::vector<EditSnapshot> redo_;
};

}  // namespace patina::editor
