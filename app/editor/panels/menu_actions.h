#pragma once
// What the File menu does, shared with the shortcuts and the unsaved-changes prompt.
#include "editor_services.h"
#include "editor_state.h"

namespace patina::editor {

// Ctrl+Shift+S: the material under a new path (the dialog first).
void saveAs(EditorState& state);
void saveSceneAs(EditorState& state);
// The scene to its file, or Save scene as when it has none.
void saveSceneDocument(EditorState& state);
// Ctrl+S: the document: the scene when one is open, else the material's file; with neither, a
// model's document asks where to save its scene, anything else where to save the material.
void save(EditorState& state);
// F12: asks for a screenshot at the size the View menu sets (else the viewport's) and says "Rendering...";
// takeRequestedScreenshot (panels.h) writes it at the start of the next frame.
void screenshot(EditorState& state, const EditorServices& services);
void openScreenshotFolder(EditorState& state);
// The user's presets folder, the material's name as the file's.
void saveAsPresetDialog(EditorState& state);
// Ctrl+O: the dialog in the material's folder.
void openDialog(EditorState& state);

}  // namespace patina::editor
