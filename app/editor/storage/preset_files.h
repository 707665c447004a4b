#pragma once
// The user's presets as files: searched, renamed and deleted from the preset browser. Nothing
// here is fatal: what goes wrong (a name taken, a folder that cannot be written) is said in
// words in the prompt that asked.
#include <filesystem>
#include <string>

#include "state/document.h"
#include "state/prompts.h"

namespace patina::editor {

// Whether a preset shows under the search box's `filter`: its material's name or its file's
// contains it, in any case; everything shows under an empty filter.
bool presetMatches(const std::string& filter, const std::string& name, const std::filesystem::path& file);

// Renames a preset's file to `name`.json in its folder, the material inside renamed with it (as
// Save as preset names it, so the caption and the file agree). Returns the new file, or throws
// std::runtime_error saying why (a bad name, a name taken, a folder that cannot be written),
// leaving the preset as it was.
std::filesystem::path renamePreset(const std::filesystem::path& file, const std::string& name);
// Moves a preset out of the browser into `<file>.bak` beside it, so a deletion can be taken
// back by hand. Throws std::runtime_error saying why it could not.
void deletePreset(const std::filesystem::path& file);

// The prompts' actions: the preset prompts.presets names, renamed to prompts.presets.newName or
// deleted. On success the prompt closes and the status says so; the document follows its file
// when that was the preset. On failure the prompt stays, saying why (prompts.presets.problem).
void confirmPresetRename(Document& document, Prompts& prompts);
void confirmPresetDelete(Document& document, Prompts& prompts);

}  // namespace patina::editor
