#include <algorithm>
#include <cmath>
#include <cstdio>

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <imgui.h>

#include "environment/builtin_environments.h"
#include "window/editor_services.h"
#include "panels/panels.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
float buttonWidth(const char* label) {
    return ImGui::CalcTextSize(label).x + ImGui::GetStyle().FramePadding.x * 2;
}

const char* typeIcon(LightType type) {
    switch (type) {
    case LightType::Point: return "(o)";
    case LightType::Directional: return "-->";
    case LightType::Hemisphere: return "(^)";
    case LightType::Environment: return "(*)";
    case LightType::Sphere: return "(O)";
    case LightType::Tube: return "(=)";
    }
    return "?";
}

// A directional light as azimuth (about +y, from +z towards +x) and elevation of the
// direction it comes from, in degrees: the angles an artist thinks in.
void editDirection(Light& light) {
    const glm::vec3 toLight = -glm::normalize(light.direction);
    float azimuth = glm::degrees(std::atan2(toLight.x, toLight.z));
    float elevation = glm::degrees(std::asin(glm::clamp(toLight.y, -1.0f, 1.0f)));
    bool changed = ImGui::SliderFloat("Azimuth", &azimuth, -180.0f, 180.0f, "%.1f deg");
    recordItem("Azimuth", "Where the light comes from around the mesh: 0 is from the front (+z)");
    changed |= ImGui::SliderFloat("Elevation", &elevation, -90.0f, 90.0f, "%.1f deg");
    recordItem("Elevation", "How high the light stands: 90 is straight overhead");
    if (changed) {
        const float a = glm::radians(azimuth), e = glm::radians(elevation);
        light.direction = -glm::vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
    }
    if (ImGui::DragFloat3("Direction", &light.direction.x, 0.01f)) {
        if (glm::dot(light.direction, light.direction) == 0.0f) {
            light.direction = {0.0f, -1.0f, 0.0f};   // a zero direction has no light
        }
    }
    recordItem("Direction", "The direction the light travels in, as a vector (x, y, z)");
}

// Blender's eight CC0 studio HDRIs (Debian's blender-data), offered when installed.
std::vector<std::filesystem::path> blenderEnvironments() {
    static const std::vector<std::filesystem::path> found = [] {
        std::vector<std::filesystem::path> files;
        std::error_code error;
        for (const auto& entry :
             std::filesystem::directory_iterator("/usr/share/blender/datafiles/studiolights/world", error)) {
            if (entry.path().extension() == ".exr") {
                files.push_back(entry.path());
            }
        }
        std::sort(files.begin(), files.end());
        return files;
    }();
    return found;
}

// The environment's own editor: where it comes from, how bright, how turned, and whether it is
// the background too. A source is loaded before it replaces the current one.
void editEnvironment(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts,
                     EditorServices& services, Light& light) {
    if (ImGui::BeginCombo("Source", environmentName(light.source).c_str())) {
        for (std::string_view builtin : builtinEnvironmentNames()) {
            const std::string source = builtinSource(builtin);
            if (ImGui::Selectable(("built-in " + std::string(builtin)).c_str(), light.source == source)) {
                setEnvironmentSource(document, interaction, jobs, prompts, source);
            }
        }
        for (const std::filesystem::path& file : blenderEnvironments()) {
            if (ImGui::Selectable(("Blender " + file.stem().string()).c_str(), light.source == file.string())) {
                setEnvironmentSource(document, interaction, jobs, prompts, file.string());
            }
        }
        ImGui::EndCombo();
    }
    const std::string sourceTip = light.source + "\nOpen or drop an .hdr or .exr file to light with it";
    recordItem("Environment source", sourceTip.c_str());
    if (const std::shared_ptr<EnvironmentLoad>& load = jobs.environmentLoad) {
        // A file being prepared: the one shown stays until it is done, or for good if cancelled.
        const std::string overlay = "Preparing " + environmentName(load->source());
        ImGui::ProgressBar(load->progress(), ImVec2(-1.0f, 0.0f), overlay.c_str());
        recordItem("Environment progress", "Decoding and prefiltering the image; the picture changes when it is done");
        if (ImGui::Button("Cancel")) {
            jobs.environmentLoad.reset();
            prompts.status = "Environment left as it was";
        }
        recordItem("Environment cancel", "Stop preparing the new environment and keep the current one");
    }
    // What the light shows once loaded (resolveEnvironmentShown); none while it is not.
    const std::shared_ptr<const Environment> shown =
        document.environment && document.environment->source == light.source ? document.environment : nullptr;
    if (const Texture* panorama = services.environmentThumbnail(shown)) {
        const float width = ImGui::GetContentRegionAvail().x;
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(panorama->id())), ImVec2(width, width * 0.5f));
        recordItem("Environment panorama",
                   "The environment's image, the centre straight ahead of the default camera's view: behind the "
                   "sphere. Drag in the viewport with the right button to turn it");
    }
    ImGui::SliderFloat("Rotation", &light.rotationDegrees, -180.0f, 180.0f, "%.1f deg");
    recordItem("Environment rotation", "Turns the environment about the vertical axis");
    bool background = document.scene.display.backgroundFromEnvironment;
    if (ImGui::Checkbox("Show as background", &background)) {
        document.scene.display.backgroundFromEnvironment = background;
    }
    recordItem("Environment background", "Show the environment behind the mesh instead of the background colour");
    ImGui::BeginDisabled(!background);
    ImGui::SliderFloat("Background blur", &document.scene.display.backgroundBlur, 0.0f, 1.0f, "%.2f");
    recordItem("Background blur", "Blurs the environment shown behind the mesh (not the lighting)");
    ImGui::EndDisabled();
}

// The point light's falloff, which sphere and tube lights share.
void editFalloff(Light& light) {
    ImGui::DragFloat("Range", &light.range, 0.05f, 0.0f, 1e4f, light.range > 0 ? "%.3f" : "none",
                     ImGuiSliderFlags_AlwaysClamp);
    recordItem("Range", "Beyond this distance the light fades to nothing (0: no limit)");
    ImGui::DragFloat("a_c", &light.attenuation.x, 0.01f, 0.0f, 1e4f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
    recordItem("a_c", "Falloff 1 / (a_c + a_l d + a_q d^2): the constant term");
    ImGui::DragFloat("a_l", &light.attenuation.y, 0.01f, 0.0f, 1e4f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
    recordItem("a_l", "Falloff 1 / (a_c + a_l d + a_q d^2): the linear term");
    ImGui::DragFloat("a_q", &light.attenuation.z, 0.01f, 0.0f, 1e4f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
    recordItem("a_q", "Falloff 1 / (a_c + a_l d + a_q d^2): the quadratic term (1: physical)");
}

void editPosition(Light& light) {
    ImGui::DragFloat3("Position", &light.position.x, 0.01f);
    recordItem("Position", "Where the light is (x, y, z); or drag it in the viewport");
}

// A sphere's or a tube's size (Karis 2013, "Area lights"): 0 makes a sphere the point light.
void editSourceRadius(Light& light) {
    ImGui::SliderFloat("Source radius", &light.sourceRadius, 0.0f, 2.0f, "%.3f",
                       ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
    recordItem("Source radius", "The light's size: a larger source gives a broader, softer highlight (0: a point)");
}

// A tube by its ends, and by its length about its middle along its own axis (along x when its
// ends meet).
void editTube(Light& light) {
    ImGui::DragFloat3("Start", &light.start.x, 0.01f);
    recordItem("Start", "One end of the tube (x, y, z); or drag it in the viewport");
    ImGui::DragFloat3("End", &light.end.x, 0.01f);
    recordItem("End", "The other end of the tube (x, y, z); or drag it in the viewport");
    const glm::vec3 middle = 0.5f * (light.start + light.end);
    const glm::vec3 axis = light.end - light.start;
    float length = glm::length(axis);
    if (ImGui::SliderFloat("Length", &length, 0.0f, 10.0f, "%.3f", ImGuiSliderFlags_AlwaysClamp)) {
        const glm::vec3 direction = glm::dot(axis, axis) > 0.0f ? glm::normalize(axis) : glm::vec3(1.0f, 0.0f, 0.0f);
        light.start = middle - 0.5f * length * direction;
        light.end = middle + 0.5f * length * direction;
    }
    recordItem("Length", "The tube's length about its middle (0: a sphere)");
    editSourceRadius(light);
}

// The intensity, shown divided by `scale` (intensityScale): at a model's scale, 1 lights the
// model as 1 lights the unit sphere; the file keeps the intensity itself.
void editIntensity(Light& light, float scale) {
    float shown = light.intensity / scale;
    // Each pixel of drag changes the intensity by 1% of itself: 8 to 100 is about 250 pixels,
    // not 1800 as at a fixed step, and small values stay as easy to set as large ones.
    if (ImGui::DragFloat("Intensity", &shown, std::max(shown, 0.1f) * 0.01f, 0.0f, 1e6f,
                         scale == 1.0f ? "%.3f" : "%.3f (model scale)", ImGuiSliderFlags_AlwaysClamp)) {
        light.intensity = shown * scale;
    }
    if (scale == 1.0f) {
        recordItem("Intensity", "How bright the light is; a drag changes it in proportion to itself. Ctrl+click to type");
        return;
    }
    char tooltip[320];
    std::snprintf(tooltip, sizeof tooltip,
                  "How bright the light is at the model's scale: 1 lights the model as 1 lights the unit sphere. The "
                  "scene holds it times the model's radius squared (%.6g x %.6g = %.6g). A drag changes it in "
                  "proportion to itself; Ctrl+click to type",
                  double(shown), double(scale), double(light.intensity));
    recordItem("Intensity", tooltip);
}

void editLight(Light& light, float intensityScale) {
    // Written as typed, as the material's name: the edit commits when the field lets go, by
    // Enter or by a click elsewhere (it used to be lost unless Enter was pressed).
    inputString("Name", &light.name);
    recordItem("Light name", "The light's name in the list and the scene file");
    ImGui::Checkbox("Enabled", &light.enabled);
    recordItem("Light enabled", "Whether this light shines");
    if (castsShadows(light.type)) {
        ImGui::Checkbox("Shadows", &light.shadows);
        recordItem("Light shadows", "Whether the model casts shadows of this light, on itself and on the ground "
                                    "(the viewport's Ground list); a shadow map (six, a cube map, for a light among the "
                                    "model's parts), saved with the scene. At most four shadowed lights and twelve maps");
    }
    if (light.type != LightType::Environment) {   // an environment's colour is its image's
        colorEditLinear("Colour", "The light's colour; values above 1 are kept", &light.color, true);
    }
    editIntensity(light, intensityScale);
    switch (light.type) {
    case LightType::Point:
        editPosition(light);
        editFalloff(light);
        break;
    case LightType::Sphere:
        editPosition(light);
        editSourceRadius(light);
        editFalloff(light);
        break;
    case LightType::Tube:
        editTube(light);
        editFalloff(light);
        break;
    case LightType::Directional: editDirection(light); break;
    case LightType::Hemisphere:
        colorEditLinear("Sky", "The colour from above", &light.sky, true);
        colorEditLinear("Ground", "The colour from below", &light.ground, true);
        break;
    case LightType::Environment: break;   // editEnvironment, which needs the scene
    }
}

// The Add buttons, one a light type, wrapping onto more lines in a narrow panel.
void drawAddButtons(Document& document, Interaction& interaction, Prompts& prompts) {
    struct AddButton {
        LightType type;
        const char* label;
        const char* tooltip;
    };
    static const AddButton buttons[] = {
        {LightType::Point, "Add point", "A light from one point, like a bulb"},
        {LightType::Sphere, "Add sphere", "A round light with a size, like a globe lamp: broad, soft highlights"},
        {LightType::Tube, "Add tube", "A long light with a size, like a fluorescent tube"},
        {LightType::Directional, "Add directional", "Parallel light from far away, like the sun"},
        {LightType::Hemisphere, "Add hemisphere", "A sky colour above and a ground colour below"},
    };
    for (const AddButton& button : buttons) {
        if (button.type != LightType::Point) {
            sameLineIfFits(buttonWidth(button.label));
        }
        if (ImGui::Button(button.label)) {
            addLight(document, interaction, prompts, button.type);
        }
        recordItem(button.label, button.tooltip);
    }
    sameLineIfFits(buttonWidth("Add environment"));
    const bool hasEnvironment = editedEnvironment(document) != nullptr;
    ImGui::BeginDisabled(hasEnvironment);   // a scene has one at most
    if (ImGui::Button("Add environment")) {
        addLight(document, interaction, prompts, LightType::Environment);
    }
    ImGui::EndDisabled();
    recordItem("Add environment", hasEnvironment ? "Light from a whole surrounding image (HDR). The scene has one "
                                                   "already: change its source in the list"
                                                 : "Light from a whole surrounding image (HDR)");
}

// One row of the list: enabled, the name to select it by, solo.
void drawLightRow(Document& document, Interaction& interaction, int i) {
    Light& light = document.scene.lights[size_t(i)];
    ImGui::PushID(i);
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    // A light solo leaves out is greyed out, still there to pick.
    const bool faded = soloedOut(document, interaction, i);
    ImGui::PushStyleVar(ImGuiStyleVar_Alpha, faded ? ImGui::GetStyle().DisabledAlpha : 1.0f);
    const std::string id = "light:" + std::to_string(i);
    ImGui::Checkbox("##enabled", &light.enabled);
    recordItem(id + " enabled", "Whether this light shines");
    ImGui::TableNextColumn();
    const std::string label = std::string(typeIcon(light.type)) + " " + light.name;
    if (ImGui::Selectable(label.c_str(), interaction.selectedLight == i)) {
        interaction.selectedLight = i;
    }
    recordItem(id, faded ? "Left out by solo; click to edit it" : "Click to edit this light");
    ImGui::PopStyleVar();
    ImGui::TableNextColumn();
    const bool solo = interaction.soloLight == i;
    if (solo) {
        ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.8f, 0.6f, 0.1f, 1.0f));
    }
    if (ImGui::SmallButton("S")) {
        toggleSolo(interaction, i);
    }
    if (solo) {
        ImGui::PopStyleColor();
    }
    recordItem(id + " solo", "Solo: render only this light (click again for all)");
    ImGui::PopID();
}

void drawLightTable(Document& document, Interaction& interaction) {
    if (!ImGui::BeginTable("lights", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH)) {
        return;
    }
    ImGui::TableSetupColumn("on", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("solo", ImGuiTableColumnFlags_WidthFixed);
    for (int i = 0; i < int(document.scene.lights.size()); ++i) {
        drawLightRow(document, interaction, i);
    }
    ImGui::EndTable();
}

// Duplicate, Delete, up and down, on the selected light.
void drawSelectionButtons(Document& document, Interaction& interaction, Prompts& prompts) {
    const int selected = interaction.selectedLight;
    ImGui::BeginDisabled(!document.hasLight(selected));
    if (ImGui::Button("Duplicate")) {
        duplicateLight(document, interaction, prompts, selected);
    }
    recordItem("Duplicate light", "A copy of the selected light");
    ImGui::SameLine();
    if (ImGui::Button("Delete")) {
        deleteLight(document, interaction, selected);
    }
    recordItem("Delete light", "Delete the selected light (Delete key)");
    ImGui::SameLine();
    if (ImGui::ArrowButton("up", ImGuiDir_Up)) {
        moveLight(document, interaction, selected, -1);
    }
    recordItem("Light up", "Move the selected light up the list");
    ImGui::SameLine();
    if (ImGui::ArrowButton("down", ImGuiDir_Down)) {
        moveLight(document, interaction, selected, +1);
    }
    recordItem("Light down", "Move the selected light down the list");
    ImGui::EndDisabled();
}
}  // namespace

void drawLightsPanel(EditorState& state, EditorServices& services) {
    drawAddButtons(state, state, state);
    drawLightTable(state, state);
    drawSelectionButtons(state, state, state);
    if (state.hasLight(state.selectedLight)) {
        ImGui::Separator();
        Light& light = state.scene.lights[size_t(state.selectedLight)];
        editLight(light, intensityScale(state, light));
        if (light.type == LightType::Environment) {
            editEnvironment(state, state, state, state, services, light);
        }
    }
}

}  // namespace patina::editor
