#include <algorithm>

#include <imgui.h>

#include "panels.h"
#include "io/scene_file.h"
#include "preset_files.h"
#include "shown_path.h"
#include "ui_scale.h"
#include "widgets.h"

namespace patina::editor {

namespace {
// Right-click on a preset: rename or delete it. Only the user's own: the built-in ones are
// part of the program (Save as preset makes an own copy to change).
void presetMenu(EditorState& state, const std::filesystem::path& file, bool own) {
    if (!ImGui::BeginPopupContextItem("preset menu")) {
        return;
    }
    if (ImGui::MenuItem("Rename...", nullptr, false, own)) {
        state.presets.renaming = file;
        state.presets.newName = file.stem().string();
        state.presets.problem.clear();
    }
    recordItem("preset:rename", "Give the preset another name (its file's and its material's)");
    if (ImGui::MenuItem("Delete...", nullptr, false, own)) {
        state.presets.deleting = file;
        state.presets.problem.clear();
    }
    recordItem("preset:delete", "Take the preset out of the browser (its file is kept as .bak)");
    if (!own) {
        ImGui::TextDisabled("A built-in preset: Save as preset makes your own to change.");
    }
    ImGui::EndPopup();
}

// One preset: its thumbnail in the fixed preview scene, a click applies it, a right-click
// offers to rename or delete it; its material's name under it.
void presetCell(EditorState& state, EditorServices& services, const std::filesystem::path& file, bool own,
                float thumb) {
    ImGui::PushID(file.string().c_str());
    const EditorServices::Preset* preset = services.preset(file);
    const std::string name = preset && !preset->name.empty() ? preset->name : file.stem().string();
    ImGui::BeginGroup();
    bool clicked;
    if (preset) {
        clicked = ImGui::ImageButton(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(preset->texture->id())),
                                     ImVec2(thumb, thumb), ImVec2(0, 0), ImVec2(1, 1), 0);
    } else {
        clicked = ImGui::Button("?", ImVec2(thumb, thumb));   // unreadable file
    }
    const std::string tooltip = name + "\n" + file.filename().string() + (preset ? "" : "\n(cannot be read)") +
                                (own ? "\nRight-click to rename or delete" : "");
    recordItem("preset:" + file.stem().string(), tooltip.c_str());
    presetMenu(state, file, own);
    ImGui::TextUnformatted(fittedText(name, thumb).c_str());
    recordItem("caption:" + file.stem().string());
    ImGui::EndGroup();
    if (clicked) {
        requestOpen(state, file);
    }
    ImGui::PopID();
}

// A modal prompt about a preset, open while `about` names it: `ask` draws the question (and
// returns true when Enter confirms it), then what went wrong if anything, then `verb`, which
// runs `act`, and Cancel (or Escape).
template <typename Ask, typename Act>
void presetPrompt(EditorState& state, const char* title, std::filesystem::path& about, const char* verb, Ask&& ask,
                  Act&& act) {
    if (!about.empty() && !ImGui::IsPopupOpen(title)) {
        ImGui::OpenPopup(title);
    }
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        return;
    }
    const bool entered = ask();
    if (!state.presets.problem.empty()) {
        ImGui::PushTextWrapPos(px(420));
        ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.45f, 1.0f), "%s", state.presets.problem.c_str());
        ImGui::PopTextWrapPos();
    }
    const bool confirmed = ImGui::Button(verb);
    recordItem("preset prompt:confirm", title);
    if (confirmed || entered) {
        act();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
        about.clear();
        state.presets.problem.clear();
    }
    recordItem("preset prompt:cancel", "Leave the preset as it is (Escape)");
    if (about.empty()) {
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void drawPresetPrompts(EditorState& state) {
    EditorState::PresetBrowser& presets = state.presets;
    presetPrompt(
        state, "Rename preset", presets.renaming, "Rename",
        [&] {
            ImGui::Text("New name for %s:", presets.renaming.filename().string().c_str());
            if (ImGui::IsWindowAppearing()) {
                ImGui::SetKeyboardFocusHere();
            }
            ImGui::SetNextItemWidth(px(300));
            inputString("##new name", &presets.newName);
            recordItem("preset:new name", "The preset's new name: its file's and its material's");
            return ImGui::IsItemDeactivated() && (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) ||
                                                  ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter)));
        },
        [&] { confirmPresetRename(state); });
    presetPrompt(
        state, "Delete preset?", presets.deleting, "Delete",
        [&] {
            ImGui::Text("Delete the preset %s? Its file is kept as %s.bak.", presets.deleting.stem().string().c_str(),
                        presets.deleting.filename().string().c_str());
            return false;
        },
        [&] { confirmPresetDelete(state); });
}
}  // namespace

// Each preset as its thumbnail in the fixed preview scene, captioned with its material's name;
// a search box over them.
void drawPresetsPanel(EditorState& state, EditorServices& services) {
    const float kThumb = px(64.0f);
    const float cell = kThumb + ImGui::GetStyle().ItemSpacing.x;
    const int columns = std::max(1, int(ImGui::GetContentRegionAvail().x / cell));
    ImGui::SetNextItemWidth(-FLT_MIN);
    inputString("##preset search", &state.presets.filter, 0, "Search presets");
    recordItem("preset search", "Show only the presets whose name has this in it");
    bool any = false;
    for (const std::filesystem::path& folder : state.presetFolders) {
        std::vector<std::filesystem::path> files;
        for (const std::filesystem::path& file : materialFilesIn(folder)) {
            const EditorServices::Preset* preset = services.preset(file);
            if (presetMatches(state.presets.filter, preset ? preset->name : "", file)) {
                files.push_back(file);
            }
        }
        if (files.empty()) {
            continue;
        }
        any = true;
        const bool own = folder == state.userPresetFolder;
        // Named for whose they are, the user's folder from their home: never a path of the
        // machine that built the program.
        const std::string header = own ? "Your presets (" + shownPath(folder) + ")" : std::string("Built-in presets");
        ImGui::TextDisabled("%s", header.c_str());
        recordItem(own ? "presets:yours" : "presets:built-in",
                   own ? ("Your presets, in " + shownPath(folder) + ": Save as preset writes here").c_str()
                       : "The presets that come with Patina: a click applies one, Save as preset makes your own");
        int column = 0;
        for (const std::filesystem::path& file : files) {
            presetCell(state, services, file, own, kThumb);
            if (++column < columns) {
                ImGui::SameLine();
            } else {
                column = 0;
            }
        }
        if (column != 0) {
            ImGui::NewLine();
        }
    }
    if (!any && !state.presets.filter.empty()) {
        ImGui::TextDisabled("No preset's name has \"%s\" in it.", state.presets.filter.c_str());
    }
    drawPresetPrompts(state);
}

}  // namespace patina::editor
