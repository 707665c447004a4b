#pragma once
// Everything the editor shows is a function of EditorState; panels read it, draw widgets and
// write it back. No ImGui or GL types here, so it is tested without a window. It is five parts
// that change for different reasons, each in a header of its own with the functions over it;
// a function takes the narrowest part it needs, or the whole where an action touches several
// (opening a file changes the document, the selection and the status).
#include "state/document.h"
#include "storage/document_files.h"
#include "state/interaction.h"
#include "state/jobs.h"
#include "state/light_list.h"
#include "state/preferences.h"
#include "state/prompts.h"

namespace patina::editor {

struct EditorState : Document, Interaction, Preferences, Jobs, Prompts {};

}  // namespace patina::editor
