#include <algorithm>

#include <imgui.h>

#include "panels.h"
#include "io/scene_file.h"
#include "widgets.h"

namespace patina::editor {

void drawPresetsPanel(EditorState& state, EditorServices& services) {
    constexpr float kThumb = 56.0f;
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
            const Texture* texture = services.thumbnail(file, state.scene);
            bool clicked;
            if (texture) {
                clicked = ImGui::ImageButton(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture->id())),
                                             ImVec2(kThumb, kThumb), ImVec2(0, 0), ImVec2(1, 1), 0);
            } else {
                clicked = ImGui::Button("?", ImVec2(kThumb, kThumb));   // unreadable file
            }
            recordItem("preset:" + file.stem().string());
            if (ImGui::IsItemHovered()) {
                ImGui::SetTooltip("%s", file.filename().string().c_str());
            }
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
