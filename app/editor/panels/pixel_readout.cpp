// The inspector in the editor (docs/INSPECTOR.md): with View > Pixel read-out, the hovered
// pixel's story (reference/pixel_story.h, the CPU twin of the shaders) as a tooltip, a click
// pins, each pin marked on the picture and listed in the Pinned pixels window (removable, copied
// as CSV).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "panels/panels.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char text[128];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

std::string vec3Text(glm::vec3 v) {
    return format("%.4g  %.4g  %.4g", v.x, v.y, v.z);
}

// The story a line each, as the tooltip and the pins' window show it.
std::vector<std::string> storyLines(const PixelStory& s) {
    const shader::ChannelInputs& c = s.inputs;
    std::vector<std::string> lines{
        "pixel " + std::to_string(s.x) + ", " + std::to_string(s.y) +
            (s.item.empty() ? "   " + s.model : "   " + s.item + " (" + s.material + ", " + s.model + ")"),
        "radiance      " + vec3Text(c.radiance),
        "shown (sRGB)  " + format("%.0f  %.0f  %.0f", s.display[0], s.display[1], s.display[2]),
        "base colour   " + vec3Text(c.baseColor) + format("   alpha %.3g", c.alpha),
        format("roughness %.3g  metallic %.3g  specular %.3g", c.roughness, c.metallic, c.specular),
        "F0            " + vec3Text(c.f0),
        "N             " + vec3Text(c.shadingNormal) + format("   N.V %.3g", c.NoV),
        "UV0           " + format("%.4g  %.4g", c.uv0.x, c.uv0.y)};
    if (!s.keyLight.empty()) {
        lines.push_back(format("D %.4g  G %.4g  F ", c.D, c.G) + vec3Text(c.F) + "  (" + s.keyLight + ")");
    }
    for (const LightShare& light : s.lights) {
        lines.push_back(light.name + ": diffuse " + vec3Text(light.diffuse) + ", specular " + vec3Text(light.specular));
    }
    if (s.environment) {
        lines.push_back(s.environment->name + ": diffuse " + vec3Text(s.environment->diffuse) + ", specular " +
                        vec3Text(s.environment->specular));
    }
    if (c.emission != glm::vec3(0.0f)) {
        lines.push_back("emission      " + vec3Text(c.emission));
    }
    // The layers' own light, where the part has them (docs/SHADING.md S5, S6, S7).
    if (c.clearcoat != glm::vec3(0.0f)) {
        lines.push_back("clear coat    " + vec3Text(c.clearcoat));
    }
    if (c.sheen != glm::vec3(0.0f)) {
        lines.push_back("sheen         " + vec3Text(c.sheen));
    }
    if (c.transmission != glm::vec3(0.0f)) {
        lines.push_back("transmission  " + vec3Text(c.transmission));
    }
    if (s.anisotropy) {   // KHR_materials_anisotropy: where the highlight stretches (S8)
        lines.push_back("stretched along " + vec3Text(s.anisotropy->direction) +
                        format("   alpha %.3g along, %.3g across", s.anisotropy->alphaT, s.anisotropy->alphaB));
    }
    return lines;
}

// A light's name as a column name's stem: letters, digits and underscores.
std::string columnStem(const std::string& name) {
    std::string stem;
    for (char c : name) {
        stem += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    }
    return stem;
}

// The columns, then each light's and the environment's diffuse and specular share, by the first
// pin's story (every pin's scene is the same one).
std::string csvHeader(const PixelStory* first) {
    std::string header = "pin,x,y,item,material,radiance_r,radiance_g,radiance_b,shown_r,shown_g,shown_b,base_r,"
                         "base_g,base_b,alpha,roughness,metallic,specular,f0_r,f0_g,f0_b,n_x,n_y,n_z,nov,u0,v0,d,g,"
                         "f_r,f_g,f_b";
    std::vector<std::string> shares;
    if (first) {
        for (const LightShare& light : first->lights) {
            shares.push_back(columnStem(light.name));
        }
        if (first->environment) {
            shares.push_back(columnStem(first->environment->name));
        }
    }
    for (const std::string& stem : shares) {
        for (const char* lobe : {"diffuse", "specular"}) {
            for (const char* c : {"r", "g", "b"}) {
                header += "," + stem + "_" + lobe + "_" + c;
            }
        }
    }
    return header + "\n";
}

std::string csvLine(size_t pin, const PixelStory& s) {
    const shader::ChannelInputs& c = s.inputs;
    std::string line = std::to_string(pin + 1) + "," + std::to_string(s.x) + "," + std::to_string(s.y) + ",\"" +
                       s.item + "\",\"" + s.material + "\"";
    auto add = [&](double value) { line += format(",%.9g", value); };
    for (float v : {c.radiance.x, c.radiance.y, c.radiance.z}) add(v);
    for (uint8_t v : s.display) add(v);
    for (float v : {c.baseColor.x, c.baseColor.y, c.baseColor.z, c.alpha, c.roughness, c.metallic, c.specular, c.f0.x,
                    c.f0.y, c.f0.z, c.shadingNormal.x, c.shadingNormal.y, c.shadingNormal.z, c.NoV, c.uv0.x, c.uv0.y,
                    c.D, c.G, c.F.x, c.F.y, c.F.z}) {
        add(v);
    }
    auto share = [&](glm::vec3 diffuse, glm::vec3 specular) {
        for (float v : {diffuse.x, diffuse.y, diffuse.z, specular.x, specular.y, specular.z}) add(v);
    };
    for (const LightShare& light : s.lights) {
        share(light.diffuse, light.specular);
    }
    if (s.environment) {
        share(s.environment->diffuse, s.environment->specular);
    }
    return line + "\n";
}

glm::ivec2 pinPixel(glm::vec2 pin, int width, int height) {
    return {std::min(int(pin.x * float(width)), width - 1), std::min(int(pin.y * float(height)), height - 1)};
}

// Where the Pinned pixels window first opens: beside the picture (`min` to `max`), never over
// it (it once covered the model): below it, over the lobe panel, where there is room; else right
// of it, over the lights panel; else over the picture's lower part, the last resort.
void placePinsWindow(ImVec2 min, ImVec2 max) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float gap = px(4);
    ImVec2 at(min.x + px(8), min.y + (max.y - min.y) * 0.55f), size(px(520), px(300));
    if (display.y - max.y - gap >= px(150)) {
        at = ImVec2(min.x, max.y + gap);
        size = ImVec2(std::min(px(560), display.x - min.x), display.y - at.y);
    } else if (display.x - max.x - gap >= px(240)) {
        at = ImVec2(max.x + gap, min.y);
        size = ImVec2(display.x - at.x, std::min(px(360), display.y - at.y));
    }
    ImGui::SetNextWindowPos(at, ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(size, ImGuiCond_FirstUseEver);
}

// Every pin's story, recomputed for the scene as it is now.
void drawPinsWindow(Interaction& interaction, Prompts& prompts, EditorServices& services, const PreparedScene& shown,
                    ImVec2 origin, int width, int height) {
    if (interaction.pins.empty()) {
        return;
    }
    ImVec2 pictureMin, pictureMax;   // the whole picture: both halves of a comparison
    if (!itemRect("viewport", &pictureMin, &pictureMax)) {
        pictureMin = origin;
        pictureMax = ImVec2(origin.x + float(width), origin.y + float(height));
    }
    placePinsWindow(pictureMin, pictureMax);
    bool open = true;
    if (!ImGui::Begin("Pinned pixels", &open)) {
        ImGui::End();
        return;
    }
    std::string header, rows;   // the header by the first story (each pin's lights are the scene's)
    // The stories scroll; the buttons under them stay in view however many pins there are.
    ImGui::BeginChild("pins", ImVec2(0.0f, -(ImGui::GetFrameHeightWithSpacing() + ImGui::GetStyle().ItemSpacing.y)));
    for (size_t i = 0; i < interaction.pins.size(); ++i) {
        const glm::ivec2 at = pinPixel(interaction.pins[i], width, height);
        ImGui::PushID(int(i));
        const bool remove = ImGui::SmallButton("x");
        recordItem("unpin:" + std::to_string(i + 1), "Remove this pin");
        ImGui::SameLine();
        if (const PixelStory* story = services.pixelStory(shown, width, height, at.x, at.y)) {
            const std::vector<std::string> lines = storyLines(*story);
            ImGui::Text("%zu  %s", i + 1, lines[0].c_str());
            for (size_t l = 1; l < lines.size(); ++l) {
                ImGui::TextUnformatted(("     " + lines[l]).c_str());
            }
            header = header.empty() ? csvHeader(story) : header;
            rows += csvLine(i, *story);
        } else {
            ImGui::Text("%zu  pixel %d, %d: no surface here now", i + 1, at.x, at.y);
        }
        ImGui::PopID();
        if (remove) {
            interaction.pins.erase(interaction.pins.begin() + long(i));
            break;
        }
    }
    ImGui::EndChild();
    const std::string csv = (header.empty() ? csvHeader(nullptr) : header) + rows;
    ImGui::Separator();
    if (ImGui::Button("Copy as CSV")) {
        ImGui::SetClipboardText(csv.c_str());
        prompts.status = "Copied " + std::to_string(interaction.pins.size()) + " pinned pixel(s) as CSV";
    }
    recordItem("Copy pins as CSV", "Every pin's values, a line each, for a spreadsheet");
    ImGui::SameLine();
    if (ImGui::Button("Clear pins")) {
        interaction.pins.clear();
    }
    recordItem("Clear pins");
    ImGui::End();
    if (!open) {
        interaction.pins.clear();
    }
}
}  // namespace

void drawPixelReadOut(Interaction& interaction, Prompts& prompts, EditorServices& services,
                      const std::vector<ReadOutPicture>& pictures, bool hovered) {
    if (!interaction.pixelReadOut || pictures.empty()) {
        return;
    }
    ImDrawList* draw = ImGui::GetWindowDrawList();
    for (const ReadOutPicture& picture : pictures) {
        draw->PushClipRect(picture.hoverMin, picture.hoverMax, true);
        for (size_t i = 0; i < interaction.pins.size(); ++i) {
            const ImVec2 at(picture.origin.x + interaction.pins[i].x * picture.size.x,
                            picture.origin.y + interaction.pins[i].y * picture.size.y);
            draw->AddCircle(at, px(5), IM_COL32(255, 220, 120, 255), 12, px(2));
            draw->AddText(ImVec2(at.x + px(6), at.y - px(16)), IM_COL32(255, 220, 120, 255), std::to_string(i + 1).c_str());
        }
        draw->PopClipRect();
    }
    const ImGuiIO& io = ImGui::GetIO();
    const bool busy = ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                      ImGui::IsMouseDown(ImGuiMouseButton_Middle);
    // The picture under the mouse: the last that holds it (Split's A is over B's left part).
    const ReadOutPicture* under = nullptr;
    for (const ReadOutPicture& picture : pictures) {
        under = hovered && ImGui::IsMouseHoveringRect(picture.hoverMin, picture.hoverMax) ? &picture : under;
    }
    if (under && !busy) {
        const int width = int(under->size.x), height = int(under->size.y);
        const int x = int(io.MousePos.x - under->origin.x), y = int(io.MousePos.y - under->origin.y);
        const PixelStory* story = services.pixelStory(*under->scene, width, height, x, y);
        ImGui::BeginTooltip();
        if (*under->side) {
            ImGui::Text("%s", under->side);
        }
        if (story) {
            for (const std::string& line : storyLines(*story)) {
                ImGui::TextUnformatted(line.c_str());
            }
            ImGui::TextDisabled("Click pins this pixel (Ctrl+click: without picking its part)");
        } else {
            ImGui::Text("pixel %d, %d: background, no surface", x, y);
        }
        ImGui::EndTooltip();
        recordArea(std::string("pixel story") + (*under->side ? std::string(" ") + under->side : std::string()),
                   under->hoverMin, under->hoverMax);
    }
    // A click pins (a drag turns the camera and pins nothing).
    if (under && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
        io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] <= px(3.0f) * px(3.0f)) {
        interaction.pins.push_back({(io.MousePos.x - under->origin.x) / under->size.x,
                              (io.MousePos.y - under->origin.y) / under->size.y});
    }
    const ReadOutPicture& b = pictures.back();
    drawPinsWindow(interaction, prompts, services, *b.scene, b.origin, int(b.size.x), int(b.size.y));
}

}  // namespace patina::editor
