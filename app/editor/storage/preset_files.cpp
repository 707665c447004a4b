#include "storage/preset_files.h"

#include <stdexcept>
#include <system_error>

#include "io/scene_file.h"
#include "views/text_match.h"
#include "storage/save_errors.h"

namespace patina::editor {

namespace {
std::filesystem::path withBak(const std::filesystem::path& file) {
    return std::filesystem::path(file) += ".bak";
}
}  // namespace

bool presetMatches(const std::string& filter, const std::string& name, const std::filesystem::path& file) {
    return containsAnyCase(name, filter) || containsAnyCase(file.stem().string(), filter);
}

std::filesystem::path renamePreset(const std::filesystem::path& file, const std::string& name) {
    if (name.empty() || name.front() == '.' || name.find('/') != std::string::npos) {
        throw std::runtime_error("\"" + name + "\" cannot be a file's name: give a name without '/' that does not "
                                 "start with '.'");
    }
    const std::filesystem::path renamed = file.parent_path() / (name + ".json");
    std::error_code error;
    if (renamed != file && std::filesystem::exists(renamed, error)) {
        throw std::runtime_error("A preset named " + name + " is already there: choose another name");
    }
    std::vector<std::string> warnings;
    Material material = loadMaterialFile(file, warnings);   // a broken file says so, naming it
    material.name = name;
    try {
        saveMaterialFile(renamed, material);
    } catch (const std::exception& failure) {
        throw std::runtime_error(couldNot("rename " + file.stem().string() + " to", renamed, failure));
    }
    // The old file goes last: should that fail, the new one goes again and nothing changed.
    if (renamed != file && !std::filesystem::remove(file, error)) {
        std::error_code ignored;
        std::filesystem::remove(renamed, ignored);
        throw std::runtime_error(couldNot("rename", file, std::system_error(error)));
    }
    return renamed;
}

void deletePreset(const std::filesystem::path& file) {
    std::error_code error;
    std::filesystem::rename(file, withBak(file), error);
    if (error) {
        throw std::runtime_error(couldNot("delete", file, std::system_error(error)));
    }
}

void confirmPresetRename(Document& document, Prompts& prompts) {
    Prompts::PresetBrowser& presets = prompts.presets;
    const std::filesystem::path old = presets.renaming;
    const std::string name = trimmed(presets.newName);
    if (name == old.stem().string()) {   // nothing to do
        presets.renaming.clear();
        presets.problem.clear();
        return;
    }
    try {
        const std::filesystem::path renamed = renamePreset(old, name);
        if (document.materialPath == old) {   // saved as this preset: the document follows its file
            if (document.scene.material.name == document.savedMaterial.name) {
                applyEdit(document, [&](Document& d) { d.scene.material.name = name; });
            }
            document.materialPath = renamed;
            document.savedMaterial.name = name;
        }
        prompts.status = "Renamed the preset " + old.stem().string() + " to " + name;
        presets.renaming.clear();
        presets.problem.clear();
    } catch (const std::exception& error) {
        presets.problem = error.what();
    }
}

void confirmPresetDelete(Document& document, Prompts& prompts) {
    Prompts::PresetBrowser& presets = prompts.presets;
    const std::filesystem::path file = presets.deleting;
    try {
        deletePreset(file);
        if (document.materialPath == file) {
            document.materialPath.clear();   // its file is gone: Save asks where
        }
        prompts.status =
            "Deleted the preset " + file.stem().string() + " (kept as " + withBak(file).filename().string() + ")";
        presets.deleting.clear();
        presets.problem.clear();
    } catch (const std::exception& error) {
        presets.problem = error.what();
    }
}

}  // namespace patina::editor
