#pragma once
#include <string>

#include "scene/light.h"

namespace patina::editor {

struct Document;
struct Interaction;
struct Prompts;

// The light list's edits: each an undoable step of the document, the selection and solo
// following the light they were on.
// A light the scene has no room for says so.
void addLight(Document& document, Interaction& interaction, Prompts& prompts, LightType type);
void duplicateLight(Document& document, Interaction& interaction, Prompts& prompts, int index);
void deleteLight(Document& document, Interaction& interaction, int index);
void moveLight(Document& document, Interaction& interaction, int index, int delta);
// The scene's environment light, or null.
Light* editedEnvironment(Document& document);

}  // namespace patina::editor
