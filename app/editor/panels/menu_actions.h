#pragma once
// What the File menu does, shared with the shortcuts and the unsaved-changes prompt.
#include "window/editor_services.h"
#include "state/editor_state.h"

namespace patina::editor {

// Ctrl+Shift+S: the material under a new path (the dialog first).
void saveAs(const Document& document, Prompts& prompts);
void saveSceneAs(const Document& document, Prompts& prompts);
// The scene to its file, or Save scene as when it has none.
void saveSceneDocument(Document& document, Preferences& preferences, Prompts& prompts);
// Ctrl+S: the document: the scene when one is open, else the material's file; with neither, a
// model's document asks where to save its scene, anything else where to save the material.
void save(Document& document, Preferences& preferences, Prompts& prompts);
// F12: asks for a screenshot at the size the View menu sets (else the viewport's) and says "Rendering...";
// takeRequestedScreenshot (panels.h) writes it at the start of the next frame.
void screenshot(const Preferences& preferences, Jobs& jobs, Prompts& prompts, const EditorServices& services);
void openScreenshotFolder(const Preferences& preferences, Jobs& jobs, Prompts& prompts);
// The user's presets folder, the edited material's name as the file's.
void saveAsPresetDialog(const Document& document, const Interaction& interaction, const Preferences& preferences,
                        Prompts& prompts);
// Ctrl+O: the dialog in the material's folder.
void openDialog(const Document& document, Prompts& prompts);

}  // namespace patina::editor
