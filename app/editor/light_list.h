#pragma once
#include <string>

#include "scene/light.h"

namespace patina::editor {

struct Document;
struct EditorState;

// The light list's edits: each an undoable step of the document, the selection and solo
// following the light they were on.
void addLight(EditorState& state, LightType type);
void duplicateLight(EditorState& state, int index);
void deleteLight(EditorState& state, int index);
void moveLight(EditorState& state, int index, int delta);
// The scene's environment light, or null.
Light* editedEnvironment(Document& document);
// "studio" for builtin:studio, a file's stem.
std::string environmentName(const std::string& source);

}  // namespace patina::editor
