#pragma once
// A model's parts in the viewport: a click selects the part under the pointer for the Material
// panel, and the selected part is outlined.
#include <memory>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace patina::editor {

struct Document;
struct Interaction;
struct Prompts;
using Segment = std::pair<glm::vec3, glm::vec3>;   // world space

// The part under `ndc` (-1..1 each way, +y up) of a picture of `aspect` that the scene's camera
// sees: its material becomes the edited one (Interaction::selectedModelMaterial) and the status
// names it. False, with the selection as it was, where no part of the shown model is there or
// the part has glTF's default material (the status says so).
bool pickPart(const Document& document, Interaction& interaction, Prompts& prompts, glm::vec2 ndc, float aspect);

// The outline of the edited part (every draw of its material) as the scene's camera sees it;
// empty without a model. The faces beside each edge are found once a model and part, the
// outline again only when the eye moves.
const std::vector<Segment>& partOutline(const Document& document, Interaction& interaction);

// What partOutline keeps between frames (Interaction::partOutline).
struct PartOutlineCache;
using PartOutlineCachePtr = std::shared_ptr<PartOutlineCache>;

}  // namespace patina::editor
