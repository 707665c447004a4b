#pragma once
// The views the toolbar's Camera list offers: model-viewer's framing of the shape shown, then
// each of the glTF model's own cameras (engine scene/camera_placement.h).
#include <string>
#include <vector>

#include "state/document.h"
#include "state/interaction.h"
#include "state/prompts.h"

namespace patina::editor {

// The name the list gives model-viewer's framing.
inline constexpr const char* kFrontCamera = "front (model-viewer)";

struct CameraChoice {
    std::string name;     // kFrontCamera, or the file's camera's name
    std::string detail;   // what it is: for the tooltip
    bool usable = true;   // false: an orthographic camera, which Patina does not draw
    int fileCamera = -1;  // its place in the model's cameras; -1: the front
};

// The choices for `document`'s shape, the front first. Names only: nothing is measured, so the
// list costs nothing a frame; the view is made when one is chosen.
std::vector<CameraChoice> cameraChoices(const Document& document);
// The name of the view last chosen (or given a model just opened) while the scene's camera is
// still on it, else "the scene's" where it is the camera of the scene as opened or saved, else
// "free" (orbited, panned, zoomed, undone, ...).
std::string currentCameraName(const Document& document, const Interaction& interaction);
// Looks through `choice` (a view, not an undoable edit, as orbiting is): the front at the
// scene's field of view, a file's camera with its own; the status says which, and the roll of a
// rolled camera, which is not shown. An unusable choice changes nothing and says why.
void chooseCamera(Document& document, Interaction& interaction, Prompts& prompts, const CameraChoice& choice);
// Camera bookmarks (Scene::bookmarks), listed after the choices. Saving the camera under a name
// (trimmed; an empty one is refused, the status says so) is an undoable step, as is deleting
// one; a name saved again takes the camera as it is now. Going to one is a view, as a choice
// is; the list names it while the camera stays there. An index out of range changes nothing.
void saveBookmark(Document& document, Interaction& interaction, Prompts& prompts, const std::string& name);
void goToBookmark(Document& document, Interaction& interaction, Prompts& prompts, size_t index);
void deleteBookmark(Document& document, Prompts& prompts, size_t index);
// The scene's camera is now `camera`, the view named `name` (a model opened and framed): the list
// names it.
void rememberCamera(Interaction& interaction, const Camera& camera, const std::string& name);

}  // namespace patina::editor
