#include "panels/viewport_toolbar.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "state/camera_choice.h"
#include "state/editor_state.h"
#include "views/text_match.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
// A model being read, last on the toolbar so that no control moves under the pointer while the
// seconds count: the mesh shown stays until it is done, or for good if cancelled.
void drawModelLoad(Jobs& jobs, Prompts& prompts) {
    const std::shared_ptr<ModelLoad> load = jobs.modelLoad;
    if (!load) {
        return;
    }
    char text[320];
    const std::string name = load->path().filename().string();
    if (load->fraction() > 0.0f) {
        std::snprintf(text, sizeof text, "Loading %s (%.0f s, images %.0f%%)", name.c_str(), load->seconds(),
                      100.0f * load->fraction());
    } else {
        std::snprintf(text, sizeof text, "Loading %s (%.0f s)", name.c_str(), load->seconds());
    }
    const ImGuiStyle& style = ImGui::GetStyle();
    sameLineIfFits(ImGui::CalcTextSize(text).x + style.ItemSpacing.x + ImGui::CalcTextSize("Cancel").x +
                   style.FramePadding.x * 2);
    ImGui::TextUnformatted(text);
    ImGui::SameLine();
    if (ImGui::Button("Cancel##model")) {
        cancelModelLoad(jobs, prompts);
    }
    recordItem("Model cancel", "Stop waiting for the model being read and keep the mesh shown");
}

// The ambient occlusion being baked, last on the toolbar as a model's load is; drawn without it
// until then.
void drawOcclusionBake(const Jobs& jobs) {
    if (!jobs.occlusionBake) {
        return;
    }
    char text[96];
    std::snprintf(text, sizeof text, "Baking ambient occlusion (%.0f s)", jobs.occlusionBake->seconds());
    sameLineIfFits(ImGui::CalcTextSize(text).x);
    ImGui::TextDisabled("%s", text);
    recordItem("Occlusion baking", "Rays from every vertex; the viewport shows the occlusion when they are done");
}

// What each tone map is, for its entry's tooltip (docs/FORMATS.md, display.tonemap).
const char* tonemapSummary(Tonemap tonemap) {
    switch (tonemap) {
    case Tonemap::None: return "None: clamped at white, no curve";
    case Tonemap::PbrNeutral: return "Khronos PBR Neutral: colours up to 0.8 kept as they are, highlights compressed "
                                     "towards white (model-viewer's default)";
    case Tonemap::AcesHill: return "ACES as three.js and the Khronos glTF viewer show it: Hill's fit of the RRT + ODT, "
                                   "exposure boosted by 1/0.6";
    case Tonemap::Agx: return "AgX, Blender 4's default view, with its base look, as three.js applies it";
    case Tonemap::AcesNarkowicz: return "ACES by Narkowicz's fit, what Patina called \"aces\": brighter "
                                        "shadows, no colour matrices";
    case Tonemap::Reinhard: return "Reinhard: x / (1 + x)";
    }
    return "";
}

// The Camera list's bookmarks: each to go to, with its delete button, then a name and Save view
// (Enter in the name saves too).
void drawBookmarks(Document& document, Interaction& interaction, Prompts& prompts, const std::string& current) {
    ImGui::Separator();
    ImGui::TextDisabled("Bookmarks (saved with the scene)");
    std::optional<size_t> deleted;
    const std::vector<CameraBookmark>& bookmarks = document.scene.bookmarks;
    for (size_t i = 0; i < bookmarks.size(); ++i) {
        const std::string index = std::to_string(i);
        const float deleteWidth = ImGui::CalcTextSize("x").x + ImGui::GetStyle().FramePadding.x * 2.0f;
        const std::string label = bookmarks[i].name + "##bookmark" + index;
        if (ImGui::Selectable(label.c_str(), bookmarks[i].name == current, 0,
                              ImVec2(std::max(px(140), ImGui::GetContentRegionAvail().x - deleteWidth -
                                                           ImGui::GetStyle().ItemSpacing.x), 0.0f))) {
            goToBookmark(document, interaction, prompts, i);
        }
        recordItem("bookmark:" + index, "Look from this saved view");
        ImGui::SameLine();
        if (ImGui::SmallButton(("x##bookmark delete" + index).c_str())) {
            deleted = i;
        }
        recordItem("bookmark delete:" + index, "Delete this bookmark (Ctrl+Z brings it back)");
    }
    if (deleted) {
        deleteBookmark(document, prompts, *deleted);
    }
    ImGui::SetNextItemWidth(px(140));
    inputString("##bookmark name", &interaction.bookmarkName, 0, "bookmark name");
    recordItem("Bookmark name", "The name to save the view under (a name saved again takes the view as it is now)");
    const bool entered = ImGui::IsItemDeactivated() && (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) ||
                                                        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter)));
    ImGui::SameLine();
    if (ImGui::Button("Save view") || entered) {
        saveBookmark(document, interaction, prompts, interaction.bookmarkName);
        if (!trimmed(interaction.bookmarkName).empty()) {
            interaction.bookmarkName.clear();
            ImGui::CloseCurrentPopup();
        }
    }
    recordItem("Save view", "Save the camera as it is now under the name typed beside: it comes back from this "
                            "list, and is saved with the scene");
}

// The Camera list (model-viewer's framing, then the model's own cameras; the view is made when
// one is chosen, so no frame measures the mesh) and the field of view.
void drawCameraControls(Document& document, Interaction& interaction, Prompts& prompts) {
    const std::string current = currentCameraName(document, interaction);
    // Wide enough for the name shown (up to a limit), as the mesh's.
    const float width = std::clamp(ImGui::CalcTextSize(current.c_str()).x + ImGui::GetFrameHeight() +
                                       ImGui::GetStyle().FramePadding.x * 2.0f,
                                   px(90), px(200));
    sameLineIfFits(labelledWidth(width, "Camera"));
    ImGui::SetNextItemWidth(width);
    if (ImGui::BeginCombo("Camera", current.c_str())) {
        const std::vector<CameraChoice> choices = cameraChoices(document);
        for (size_t i = 0; i < choices.size(); ++i) {
            const CameraChoice& choice = choices[i];
            ImGui::BeginDisabled(!choice.usable);
            const std::string label = choice.name + "##camera" + std::to_string(i);
            if (ImGui::Selectable(label.c_str(), choice.usable && choice.name == current)) {
                chooseCamera(document, interaction, prompts, choice);
            }
            recordItem("camera:" + std::to_string(i), choice.detail.c_str());   // dimmed when not usable
            ImGui::EndDisabled();
        }
        if (choices.size() == 1) {
            ImGui::TextDisabled("a glTF model's own cameras are listed here");
        }
        drawBookmarks(document, interaction, prompts, current);
        ImGui::EndCombo();
    }
    recordItem("Camera", "Look from model-viewer's framing (the front, the whole shape in view), from one of the "
                         "glTF file's own cameras (render --camera takes the same) or from a bookmark; save the "
                         "view as a bookmark");
    sameLineIfFits(labelledWidth(px(80), "FOV"));
    ImGui::SetNextItemWidth(px(80));
    ImGui::DragFloat("FOV", &document.scene.camera.fovYDegrees, 0.2f, 1.0f, 179.0f, "%.1f deg",
                     ImGuiSliderFlags_AlwaysClamp);
    recordItem("FOV", "The camera's vertical field of view in degrees (model-viewer's field-of-view; saved with the "
                      "scene): a wider lens from the same place. Ctrl+click or double-click to type");
}

// What each ground is, for its entry's tooltip (docs/FORMATS.md, display.ground).
const char* groundSummary(Ground ground) {
    switch (ground) {
    case Ground::None: return "Nothing under the model";
    case Ground::Shadow: return "A shadow catcher: the background, darkened where the model shadows the ground "
                                "(lights with Shadows on)";
    case Ground::Floor: return "A floor with its own colour and roughness, lit by every light and the environment";
    }
    return "";
}

// The Ground list, and the floor's colour and roughness while it is the floor.
void drawGroundControls(DisplaySettings& display) {
    sameLineIfFits(labelledWidth(px(80), "Ground"));
    ImGui::SetNextItemWidth(px(80));
    if (ImGui::BeginCombo("Ground", std::string(groundName(display.ground)).c_str())) {
        for (const Ground ground : kGrounds) {
            const std::string name(groundName(ground));
            if (ImGui::Selectable(name.c_str(), ground == display.ground)) {
                display.ground = ground;
            }
            recordItem("ground:" + name, groundSummary(ground));
        }
        ImGui::EndCombo();
    }
    // Named apart from the hemisphere light's Ground colour in the lights panel.
    recordItem("Ground plane", "A plane under the model at its lowest point: none, a shadow catcher over the background, "
                         "or a floor (saved with the scene)");
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Ambient occlusion"));
    ImGui::Checkbox("Ambient occlusion", &display.ambientOcclusion);
    recordItem("Ambient occlusion", "The environment's and the hemisphere light's light hidden by the model itself and "
                                    "the ground, baked once per model (a second for a large one), with specular "
                                    "occlusion in cavities (saved with the scene)");
    if (display.ground != Ground::Floor) {
        return;
    }
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Floor"));
    colorEditLinear("Floor", "The floor's colour", &display.groundColor, false, ImGuiColorEditFlags_NoInputs);
    sameLineIfFits(labelledWidth(px(80), "Floor roughness"));
    ImGui::SetNextItemWidth(px(80));
    ImGui::SliderFloat("Floor roughness", &display.groundRoughness, 0.0f, 1.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    recordItem("Floor roughness", "The floor's roughness: 0 a mirror, 1 matte. Ctrl+click to type");
}

}  // namespace

// The toolbar's controls wrap onto a second line when the viewport is narrow, rather than
// being cut off at its edge.
void drawViewportToolbar(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts) {
    DisplaySettings& display = document.scene.display;
    // sphere, torus, or the glTF file opened or dropped on the window.
    const std::string current = document.scene.meshFile.empty()
                                    ? std::string(meshKindName(document.scene.mesh))
                                    : std::filesystem::path(document.scene.meshFile).filename().string();
    // Wide enough for a model's file name (up to a limit), so "BoxTextured.glb" is not cut.
    const float nameWidth = ImGui::CalcTextSize(current.c_str()).x + ImGui::GetFrameHeight() +
                            ImGui::GetStyle().FramePadding.x * 2.0f;
    ImGui::SetNextItemWidth(std::clamp(nameWidth, px(110), px(240)));
    if (ImGui::BeginCombo("Mesh", current.c_str())) {
        for (MeshKind kind : {MeshKind::Sphere, MeshKind::Torus}) {
            if (ImGui::Selectable(std::string(meshKindName(kind)).c_str(),
                                  document.scene.meshFile.empty() && document.scene.mesh == kind)) {
                chooseBuiltinMesh(document, kind);
            }
        }
        ImGui::TextDisabled("or open / drop a .gltf or .glb");
        ImGui::EndCombo();
    }
    recordItem("Mesh", "The shape the material is shown on; open or drop a .gltf or .glb for your own");
    drawCameraControls(document, interaction, prompts);
    sameLineIfFits(labelledWidth(px(110), "Exposure"));
    // A drag, not a slider: 16 stops across 110 pixels moved 8 EV in 60 of them. Fine steps
    // (0.02 EV a pixel) for a look; a big change is typed.
    ImGui::SetNextItemWidth(px(110));
    ImGui::DragFloat("Exposure", &display.exposure, 0.02f, -8.0f, 8.0f, "%.2f EV", ImGuiSliderFlags_AlwaysClamp);
    recordItem("Exposure", "Brightness of the picture in stops (EV): +1 doubles it. Drag for fine steps (0.02 EV a "
                           "pixel); Ctrl+click or double-click to type");
    sameLineIfFits(labelledWidth(px(120), "Tone map"));
    ImGui::SetNextItemWidth(px(120));
    if (ImGui::BeginCombo("Tone map", std::string(tonemapName(display.tonemap)).c_str())) {
        for (const Tonemap tonemap : kTonemaps) {
            const std::string name(tonemapName(tonemap));
            if (ImGui::Selectable(name.c_str(), tonemap == display.tonemap)) {
                display.tonemap = tonemap;
            }
            recordItem("tonemap:" + name, tonemapSummary(tonemap));
        }
        ImGui::EndCombo();
    }
    recordItem("Tone map", "How light above white is brought into the screen's range, as the engines that show the "
                           "asset do (the same names as render --tonemap)");
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Background"));
    colorEditLinear("Background", "The colour behind the mesh", &display.background, false,
                    ImGuiColorEditFlags_NoInputs);
    drawGroundControls(display);

    const ImGuiStyle& style = ImGui::GetStyle();
    auto radioWidth = [&](const char* label) { return labelledWidth(ImGui::GetFrameHeight(), label); };
    if (ImGui::Button("Set A")) {
        interaction.compareA = labelledMaterial(document, interaction);
        if (interaction.compareView == CompareView::Single) {
            interaction.compareView = CompareView::Split;
        }
    }
    recordItem("Set A", "Keep the current material as A, to compare with what you edit next (B)");
    sameLineIfFits(radioWidth("Single"));
    ImGui::BeginDisabled(!interaction.compareA);
    int view = int(interaction.compareView);
    ImGui::RadioButton("Single", &view, int(CompareView::Single));
    recordItem("Single", "Show B, the material being edited, alone");
    sameLineIfFits(radioWidth("Split"));
    ImGui::RadioButton("Split", &view, int(CompareView::Split));
    recordItem("Split", "A left of a divider you can drag, B right of it");
    sameLineIfFits(radioWidth("Side by side"));
    ImGui::RadioButton("Side by side", &view, int(CompareView::SideBySide));
    recordItem("Side by side", "A and B next to each other, each half as wide");
    interaction.compareView = interaction.compareA ? CompareView(view) : CompareView::Single;
    sameLineIfFits(ImGui::CalcTextSize("Clear A").x + style.FramePadding.x * 2);
    if (ImGui::Button("Clear A")) {
        interaction.compareA.reset();
    }
    recordItem("Clear A", "Forget A and show B alone");
    ImGui::EndDisabled();
    drawModelLoad(jobs, prompts);
    drawOcclusionBake(jobs);
}

}  // namespace patina::editor
