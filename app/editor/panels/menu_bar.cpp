#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "panels/file_dialog.h"
#include "panels/menu_actions.h"
#include "panels/panels.h"
#include "storage/shown_path.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
void drawSaveItems(Document& document, const Interaction& interaction, Preferences& preferences, Prompts& prompts) {
    if (ImGui::MenuItem("Save", "Ctrl+S")) {
        save(document, preferences, prompts);
    }
    if (ImGui::MenuItem("Save material as...", "Ctrl+Shift+S")) {
        saveAs(document, prompts);
    }
    if (ImGui::MenuItem("Save scene", "Ctrl+Alt+S")) {
        saveSceneDocument(document, preferences, prompts);
    }
    recordItem("Save scene");
    if (ImGui::MenuItem("Save scene as...")) {
        saveSceneAs(document, prompts);
    }
    if (ImGui::MenuItem("Save as preset...", nullptr, false, !preferences.userPresetFolder.empty())) {
        saveAsPresetDialog(document, interaction, preferences, prompts);
    }
    recordItem("Save as preset", "Save the material into your presets folder; it shows in the preset browser");
}

void drawFileMenu(EditorState& state, EditorServices& services) {
    const bool fileMenu = ImGui::BeginMenu("File");
    if (!fileMenu) {
        recordItem("menu:File");   // while open, the last item is the menu's window
        return;
    }
    if (ImGui::MenuItem("New", "Ctrl+N")) {
        requestNew(state, state, state, state);
    }
    recordItem("New", "A new scene: the default sphere, lights and material, saved nowhere yet");
    if (ImGui::MenuItem("Open...", "Ctrl+O")) {
        openDialog(state, state);
    }
    recordItem("Open", "Open a material, scene, screenshot, glTF model or environment image");
    if (ImGui::BeginMenu("Open recent", !state.recentFiles.empty())) {
        for (const std::filesystem::path& recent : state.recentFiles) {
            if (ImGui::MenuItem(shownPath(recent).c_str())) {
                requestOpen(state, recent);
            }
        }
        ImGui::EndMenu();
    }
    drawSaveItems(state, state, state, state);
    ImGui::Separator();
    if (ImGui::MenuItem("Screenshot", "F12")) {
        screenshot(state, state, state, services);
    }
    if (ImGui::MenuItem("Open screenshot folder")) {
        openScreenshotFolder(state, state, state);
    }
    recordItem("Open screenshot folder", "Show the folder screenshots go to in the file manager");
    if (ImGui::MenuItem("Export comparison...", nullptr, false, state.compareA.has_value())) {
        startPathDialog(state, Prompts::PathDialog::ExportComparison, "comparison.png");
    }
    if (ImGui::MenuItem("Export as glTF...")) {
        const std::string stem = state.model ? std::filesystem::path(state.scene.meshFile).stem().string() : "material";
        startPathDialog(state, Prompts::PathDialog::ExportGltf, stem + "-tuned.glb");
    }
    recordItem("Export as glTF...", "Write the model with its tuned materials and maps (or the built-in mesh with "
                                    "the material) as .glb, or .gltf with its images beside it");
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) {
        state.pendingQuit = true;
    }
    ImGui::EndMenu();
}

void drawEditMenu(Document& document, Interaction& interaction, Prompts& prompts) {
    if (!ImGui::BeginMenu("Edit")) {
        return;
    }
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false,
                        document.history.canUndo() || document.snapshot() != document.committed)) {
        undo(document, interaction, prompts);
    }
    if (ImGui::MenuItem("Redo", "Ctrl+Shift+Z / Ctrl+Y", false, document.history.canRedo())) {
        redo(document, interaction, prompts);
    }
    ImGui::EndMenu();
}

// Steps, not a slider: the menu would grow under the mouse while it is dragged.
void drawUiSizeMenu(Preferences& preferences) {
    const bool sizes = ImGui::BeginMenu("UI size");
    if (!sizes) {   // while open, the last item is the menu's window
        recordItem("UI size", "Text and controls larger or smaller, on top of the screen's own scale");
        return;
    }
    for (int percent : {75, 100, 125, 150, 175, 200, 250, 300}) {
        const std::string label = std::to_string(percent) + "%";
        if (ImGui::MenuItem(label.c_str(), nullptr, std::lround(preferences.uiScaleSetting * 100.0f) == percent)) {
            preferences.uiScaleSetting = float(percent) / 100.0f;
        }
        recordItem("UI size " + label);
    }
    ImGui::EndMenu();
}

void drawScreenshotSettings(Preferences& preferences) {
    ImGui::SetNextItemWidth(px(90));
    ImGui::InputInt("Screenshot width (0: viewport)", &preferences.screenshotWidth);
    recordItem("Screenshot width", "Screenshots this many pixels wide; 0: as wide as the viewport");
    ImGui::SetNextItemWidth(px(90));
    ImGui::InputInt("Screenshot height (0: viewport)", &preferences.screenshotHeight);
    recordItem("Screenshot height", "Screenshots this many pixels high; 0: as high as the viewport");
    // What `patina render` takes: the renderer says at once when the GL cannot.
    preferences.screenshotWidth = std::clamp(preferences.screenshotWidth, 0, kLargestScreenshot);
    preferences.screenshotHeight = std::clamp(preferences.screenshotHeight, 0, kLargestScreenshot);
    std::string folder = preferences.screenshotFolder.string();
    if (inputString("Screenshot folder", &folder)) {
        preferences.screenshotFolder = folder;
    }
    recordItem("Screenshot folder", "Where F12 writes screenshots (made when missing)");
}

// View > Channel: the picture, a debug channel, or one light's share (docs/INSPECTOR.md).
void drawChannelMenu(const Document& document, Interaction& interaction) {
    const bool open = ImGui::BeginMenu("Channel");
    recordItem("Channel", "Show the data behind the picture: a value the shader computed, per pixel");
    if (!open) {
        return;
    }
    if (ImGui::MenuItem("Picture", nullptr, interaction.channel.channel < 0)) {
        interaction.channel = {-1, "", interaction.channel.srgb,
                               interaction.channel.strictPbr};   // the picture; the options stay
    }
    recordItem("channel:picture", "The shaded picture, with exposure and tone map");
    ImGui::Separator();
    for (const std::string& name : fixedChannelNames()) {
        const ChannelRequest request = *channelFromName(name);
        if (ImGui::MenuItem(name.c_str(), nullptr, interaction.channel.channel == request.channel)) {
            interaction.channel = {request.channel, "", interaction.channel.srgb, interaction.channel.strictPbr};
        }
        recordItem("channel:" + name);
    }
    ImGui::Separator();
    for (const Light& light : renderedScene(document, interaction).lights) {
        const std::string label = "light: " + light.name;
        const bool shown =
            interaction.channel.channel == shader::CHANNEL_LIGHT && interaction.channel.light == light.name;
        if (ImGui::MenuItem(label.c_str(), nullptr, shown, light.enabled)) {
            interaction.channel = {shader::CHANNEL_LIGHT, light.name, interaction.channel.srgb,
                                   interaction.channel.strictPbr};
        }
        recordItem("channel:light:" + light.name, light.enabled ? "This light's share of the picture"
                                                                : "Switched off (or soloed out): nothing to show");
    }
    ImGui::Separator();
    ImGui::MenuItem("sRGB-encode channel", nullptr, &interaction.channel.srgb);
    recordItem("sRGB-encode channel", "Show the channel's values sRGB-encoded (for colours); off: the values themselves");
    ImGui::MenuItem("Strict PBR ranges", nullptr, &interaction.channel.strictPbr);
    recordItem("Strict PBR ranges", "PBR validation: dielectrics 50-240 sRGB, metals from 180\n"
                                    "(off: 30-240 and 155, Substance's defaults)");
    ImGui::EndMenu();
}

// View > Turntable and its speed.
void drawTurntableItems(const Document& document, Interaction& interaction) {
    Turntable& turntable = interaction.turntable;
    bool turning = turntable.on;
    if (ImGui::MenuItem("Turntable", nullptr, &turning)) {
        if (turning) {
            startTurntable(turntable, document);
        } else {
            turntable.on = false;
        }
    }
    recordItem("Turntable", "Turn the camera about its target, round the vertical axis, at the speed below; any "
                            "edit pauses it (patina turntable writes the frames of a turn)");
    ImGui::SetNextItemWidth(px(120));
    ImGui::DragFloat("Turntable speed", &turntable.degreesPerSecond, 0.5f, -360.0f, 360.0f, "%.0f deg/s",
                     ImGuiSliderFlags_AlwaysClamp);
    recordItem("Turntable speed", "Degrees a second the turntable turns (negative: the other way). Ctrl+click or "
                                  "double-click to type");
}

void drawViewMenu(Document& document, Interaction& interaction, Preferences& preferences) {
    const bool viewMenu = ImGui::BeginMenu("View");
    if (!viewMenu) {
        recordItem("menu:View");   // while open, the last item is the menu's window
        return;
    }
    if (ImGui::MenuItem("Frame mesh", "F")) {
        frameMesh(document);
    }
    recordItem("Frame mesh", "Aim the camera at the whole mesh");
    drawTurntableItems(document, interaction);
    ImGui::MenuItem("Light gizmos", nullptr, &preferences.showGizmos);
    recordItem("Light gizmos", "Show the lights' dots and arrows over the viewport");
    ImGui::MenuItem("Lobe panel", nullptr, &preferences.layout.showLobe);
    recordItem("Lobe panel", "Show the BRDF lobe under the viewport; hidden, the viewport takes its room");
    ImGui::MenuItem("Advanced controls", nullptr, &preferences.showAdvanced);
    recordItem("Advanced controls", "The BRDF model, render path, timings, derived values and the Accuracy tab");
    drawChannelMenu(document, interaction);
    ImGui::MenuItem("PBR validation overlay", nullptr, &interaction.pbrOverlay);
    recordItem("PBR validation overlay", "Stripe the pixels whose base colour no real material has: blue darker "
                                         "than charcoal, red brighter than snow, yellow a metal too dark");
    ImGui::MenuItem("Pixel read-out", nullptr, &interaction.pixelReadOut);
    recordItem("Pixel read-out", "Hover the picture to see what gives a pixel its colour; a click pins it");
    drawUiSizeMenu(preferences);
    ImGui::Separator();
    drawScreenshotSettings(preferences);
    ImGui::EndMenu();
}

void drawHelpMenu(Prompts& prompts) {
    if (ImGui::BeginMenu("Help")) {
        if (ImGui::MenuItem("Shortcuts", "F1")) {
            prompts.showShortcuts = true;
        }
        ImGui::EndMenu();
    }
}

// "PBR: 812 of 31070 pixels flagged (2.6%)", while the overlay or the channel shows them, the
// breakdown in its tooltip.
void drawPbrTally(const Interaction& interaction, const PbrTally& tally) {
    const PbrRanges ranges = interaction.channel.strictPbr ? PbrRanges::strict() : PbrRanges{};
    const double percent = tally.texels ? 100.0 * double(tally.flagged()) / double(tally.texels) : 0.0;
    ImGui::SameLine(0.0f, px(24));
    const ImVec4 colour = tally.flagged() ? kWarningColour : ImVec4(0.55f, 0.85f, 0.55f, 1.0f);
    ImGui::TextColored(colour, "PBR: %zu of %zu pixels flagged (%.1f%%)", tally.flagged(), tally.texels, percent);
    char detail[200];
    std::snprintf(detail, sizeof detail, "Dielectric below %d sRGB: %zu (blue)\nDielectric above %d: %zu (red)\n"
                  "Metal below %d: %zu (yellow)", ranges.dielectricMin, tally.dielectricDark, ranges.dielectricMax,
                  tally.dielectricBright, ranges.metalMin, tally.metalDark);
    recordItem("PBR tally", detail);
}

// The last completed action, on one line where it moves nothing: its first line, cut with "..."
// where the window ends, the whole of it in a tooltip (a long one used to run off the window's
// edge, unreadable); after a screenshot, a button to its folder.
void drawStatus(const Preferences& preferences, Jobs& jobs, Prompts& prompts) {
    const std::string status = prompts.status.substr(0, prompts.status.find('\n'));
    const bool screenshot =
        !prompts.lastScreenshot.empty() && status.find(shownPath(prompts.lastScreenshot)) != std::string::npos;
    ImGui::SameLine(0.0f, px(24));
    const ImGuiStyle& style = ImGui::GetStyle();
    const float button =
        screenshot ? ImGui::CalcTextSize("Open folder").x + 2.0f * style.FramePadding.x + style.ItemSpacing.x : 0.0f;
    // The lines under the first are notes (what a model's file has that is not drawn): their
    // count in amber, so that they are not missed behind the tooltip.
    const auto notes = std::count(prompts.status.begin(), prompts.status.end(), '\n');
    const std::string count = notes == 0 ? "" : "+" + std::to_string(notes) + (notes == 1 ? " note" : " notes");
    const float counted = notes == 0 ? 0.0f : ImGui::CalcTextSize(count.c_str()).x + style.ItemSpacing.x;
    const std::string shown =
        fittedText(status, std::max(ImGui::GetContentRegionAvail().x - button - counted, px(60)));
    ImGui::TextDisabled("%s", shown.c_str());
    recordItem("status", prompts.status.empty() ? "What the editor did last shows here" : prompts.status.c_str());
    if (notes > 0) {
        ImGui::SameLine();
        ImGui::TextColored(kWarningColour, "%s", count.c_str());
        recordItem("status notes", prompts.status.c_str());
    }
    if (screenshot) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Open folder")) {
            openScreenshotFolder(preferences, jobs, prompts);
        }
        recordItem("Open folder", "Show the screenshot's folder in the file manager");
    }
}
}  // namespace

void drawMenuBar(EditorState& state, EditorServices& services) {
    if (!ImGui::BeginMainMenuBar()) {
        return;
    }
    drawFileMenu(state, services);
    drawEditMenu(state, state, state);
    drawViewMenu(state, state, state);
    drawHelpMenu(state);
    if (services.pbrTally) {
        drawPbrTally(state, *services.pbrTally);
    }
    drawStatus(state, state, state);
    ImGui::EndMainMenuBar();
}

}  // namespace patina::editor
