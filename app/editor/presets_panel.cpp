#include <algorithm>

#include <imgui.h>

#include "panels.h"
#include "io/scene_file.h"
#include "ui_scale.h"
#include "widgets.h"

namespace patina::editor {

// Each preset as its thumbnail in the fixed preview scene, captioned with its material's name.
void drawPresetsPanel(EditorState& state, EditorServices& services) {
    const float kThumb = px(64.0f);
    const float cell = kThumb + ImGui::GetStyle().ItemSpacing.x;
    const int columns = std::max(1, int(ImGui::GetContentRegionAvail().x / cell));
    for (const std::filesystem::path& folder : state.presetFolders) {
        const std::vector<std::filesystem::path> files = materialFilesIn(folder);
        if (files.empty()) {
            continue;
        }
        ImGui::TextDisabled("%s", folder.string().c_str());
        int column = 0;
        for (const std::filesystem::path& file : files) {
            ImGui::PushID(file.string().c_str());
            const EditorServices::Preset* preset = services.preset(file);
            const std::string name = preset && !preset->name.empty() ? preset->name : file.stem().string();
            ImGui::BeginGroup();
            bool clicked;
            if (preset) {
                clicked = ImGui::ImageButton(
                    reinterpret_cast<ImTextureID>(static_cast<intptr_t>(preset->texture->id())), ImVec2(kThumb, kThumb),
                    ImVec2(0, 0), ImVec2(1, 1), 0);
            } else {
                clicked = ImGui::Button("?", ImVec2(kThumb, kThumb));   // unreadable file
            }
            const std::string tooltip = name + "\n" + file.filename().string() + (preset ? "" : "\n(cannot be read)");
            recordItem("preset:" + file.stem().string(), tooltip.c_str());
            ImGui::TextUnformatted(fittedText(name, kThumb).c_str());
            recordItem("caption:" + file.stem().string());
            ImGui::EndGroup();
            if (clicked) {
                requestOpen(state, file);
            }
            ImGui::PopID();
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
}

}  // namespace patina::editor
