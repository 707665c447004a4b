#include <algorithm>
#include <string>

#include <imgui.h>

#include "gltf/extensions.h"
#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "shading/shading.h"
#include "storage/document_files.h"
#include "panels/file_dialog.h"
#include "panels/panels.h"
#include "storage/shown_path.h"
#include "views/text_match.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
// The BRDF model of what the panel edits: the built-in mesh's material, the selected part of a
// model, or every part where the scene shades them all with one (Scene::modelBrdf).
void drawModelChoice(Document& document, const Interaction& interaction) {
    const bool parts = modelMaterialCount(document) > 0;
    const bool everyPart = parts && document.scene.modelBrdf.has_value();
    Material edited = editedMaterial(document, interaction);
    BrdfModelId chosen = edited.model;
    if (ImGui::BeginCombo("Model", std::string(brdfModel(chosen).name).c_str())) {
        for (const BrdfModelInfo& model : brdfModels()) {
            if (ImGui::Selectable(std::string(model.name).c_str(), model.id == chosen)) {
                chosen = model.id;
            }
            if (ImGui::IsItemHovered()) {
                ImGui::SetTooltip("%s", std::string(model.summary).c_str());
            }
        }
        ImGui::EndCombo();
    }
    recordItem("Model", !parts      ? "The BRDF model the renderer shades with (saved with the material)"
                        : everyPart ? "The BRDF model every part of the model is shaded with (saved in the scene)"
                                    : "The BRDF model this part is shaded with: glTF's own (gltf) as the file "
                                      "defines it, or another to compare (saved in the scene)");
    if (chosen != edited.model) {
        if (!parts) {
            document.scene.material.model = chosen;
        } else if (everyPart) {
            document.scene.modelBrdf = chosen;
        } else {
            edited.model = chosen;
            setEditedMaterial(document, interaction, document.scene, edited);
        }
    }
    if (everyPart) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("Every part is shaded with %s: the scene chose one model for all (a scene saved "
                            "before each part had its own, or --model).",
                            std::string(brdfModel(chosen).name).c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::SmallButton("Each part its own model")) {
            document.scene.modelBrdf.reset();
        }
        recordItem("Each part its own model",
                   "Shade each part with its own BRDF model again: glTF's (gltf) for the file's materials");
    }
}

// The research controls: which BRDF model and render path, and what the shader derives.
void drawAdvanced(Document& document, Interaction& interaction) {
    drawModelChoice(document, interaction);
    int path = int(interaction.renderPath);
    ImGui::TextUnformatted("Render path");
    ImGui::RadioButton("single", &path, int(RenderPath::Single));
    recordItem("Path single", "One pass shades every light (the default)");
    sameLineIfFits(ImGui::GetFrameHeight() + ImGui::CalcTextSize("multi").x + ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::RadioButton("multi", &path, int(RenderPath::Multi));
    recordItem("Path multi", "One additive pass a light, to compare against single");
    sameLineIfFits(ImGui::GetFrameHeight() + ImGui::CalcTextSize("specialised").x +
                   ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::RadioButton("specialised", &path, int(RenderPath::Specialised));
    recordItem("Path specialised", "A shader compiled for this scene's lights");
    interaction.renderPath = RenderPath(path);
    // The environment's shading: the split sum as published, or a variant docs/LIGHTING.md
    // measures against the ground truth.
    EnvironmentShading& environment = interaction.environmentShading;
    if (ImGui::BeginCombo("Environment", std::string(environmentMethodName(environment.method)).c_str())) {
        for (EnvironmentMethod method :
             {EnvironmentMethod::SplitSum, EnvironmentMethod::Dominant, EnvironmentMethod::Stochastic}) {
            if (ImGui::Selectable(std::string(environmentMethodName(method)).c_str(), method == environment.method)) {
                environment.method = method;
            }
        }
        ImGui::EndCombo();
    }
    recordItem("Environment method",
               "How the environment lights the mesh: Karis's split sum (the default), the split sum along the "
               "dominant direction (half the error, same cost), or N filtered importance samples a pixel (noisy)");
    if (environment.method == EnvironmentMethod::Stochastic) {
        // 64 at most here: each sample is a filtered cube-map read a pixel, and at 256 a frame
        // took over a second on a software rasteriser (patina render takes up to 256).
        ImGui::SliderInt("Samples", &environment.samples, 1, 64, "%d", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
        recordItem("Environment samples",
                   "Samples a pixel of the stochastic mode: more is less noisy and slower (each one is a texture "
                   "read per pixel)");
    }
    ImGui::PushTextWrapPos(0.0f);   // notes wrap at the panel's edge
    ImGui::TextDisabled("The viewport shows the render's CPU and GPU time.");

    // What the shader derives from the four parameters (shaders/shared/brdf.glsl), guards included.
    const Material edited = editedMaterial(document, interaction);
    const shader::SurfaceMaterial derived = surfaceMaterial(edited);
    ImGui::TextDisabled("Derived");
    ImGui::Text("alpha = r^2       %.5f", double(derived.alpha));
    ImGui::Text("k = (r+1)^2 / 8   %.5f", double(shader::k_Karis(derived.roughness)));
    if (derived.roughness != edited.roughness) {
        ImGui::TextDisabled("roughness floored at %.3f (D is 0/0 at r = 0)", double(derived.roughness));
    }
    ImGui::PopTextWrapPos();
    linearSwatch("c_diff", "The diffuse colour the shader uses: base colour times (1 - metallic)",
                 derived.diffuseColor);
    linearSwatch("F0", "The reflectance head-on: 0.08 specular for a dielectric (times its specular tint and weight), "
                       "the base colour for a metal",
                 derived.f0);
}
}  // namespace

namespace {
// The four factors, each with its reset to `file` (as opened or last saved) and to `defaults`.
void drawFactors(Material& material, const Material& file, const Material& defaults) {
    // The label above: beside the field it left the three numbers too little room to be read.
    ImGui::TextUnformatted("Base colour (sRGB)");
    ImGui::SetNextItemWidth(widthBesideReset(""));
    colorEditLinear("##Base colour", "The colour of diffuse light, or of the reflection for a metal (click the swatch to pick)",
                    &material.baseColor);
    ImGui::SameLine();
    resetButton("Base colour", &material.baseColor, file.baseColor, defaults.baseColor);
    sliderWithReset("Roughness", "0: a mirror-sharp highlight; 1: a broad, dull one. Ctrl+click to type",
                    &material.roughness, 0.0f, 1.0f, file.roughness, defaults.roughness);
    sliderWithReset("Specular", "How strongly a non-metal reflects head-on (0.5 is 4%, most materials)",
                    &material.specular, 0.0f, 1.0f, file.specular, defaults.specular);
    sliderWithReset("Metallic", "0: a dielectric (plastic, stone); 1: a metal, whose reflection takes the base colour",
                    &material.metallic, 0.0f, 1.0f, file.metallic, defaults.metallic);
}

// The button that puts a layer on the part whole or, where `present`, takes it off, one step to
// undo: true when clicked, and then what it did in `said` for the status line.
bool layerButton(const char* add, const char* remove, bool present, const char* what, std::string& said) {
    const char* label = present ? remove : add;
    const bool clicked = ImGui::Button(label);
    if (clicked) {
        said = present ? std::string("Took the ") + what + " off" : std::string("Added the ") + what + " to";
    }
    const std::string tooltip = present ? std::string("Take the ") + what + " off the part (its factors to 0; Ctrl+Z "
                                                                         "puts it back)"
                                        : std::string("Put a ") + what + " on the part, to tune from here (Ctrl+Z "
                                                                         "takes it off)";
    recordItem(label, tooltip.c_str());
    return clicked;
}

// KHR_materials_clearcoat's two factors in a section of their own under the factors, first
// shown open where the part has a coat (each part keeps its own open state); its maps are among
// the part's maps above. A coat of 0 is none.
void drawClearcoat(Material& material, const Material& file, const Material& defaults, int part, std::string& said) {
    ImGui::PushID(part);
    ImGui::SetNextItemOpen(material.clearcoat > 0.0f, ImGuiCond_Once);
    const bool open = ImGui::CollapsingHeader("Clearcoat");
    recordItem("Clearcoat", "A clear lacquer over the part (KHR_materials_clearcoat), as on a car's paint");
    if (open) {
        const bool coated = material.clearcoat > 0.0f;
        if (layerButton("Add coat", "Remove coat", coated, "clear coat", said)) {   // added: a full, nearly smooth coat
            material.clearcoat = coated ? 0.0f : 1.0f;
            material.clearcoatRoughness = coated ? 0.0f : 0.03f;
        }
        sliderWithReset("Coat", "How much clear coat lies over the part: 0 none, 1 a full coat (index 1.5)",
                        &material.clearcoat, 0.0f, 1.0f, file.clearcoat, defaults.clearcoat);
        sliderWithReset("Coat roughness", "0: the coat's highlight mirror-sharp; 1: broad. Ctrl+click to type",
                        &material.clearcoatRoughness, 0.0f, 1.0f, file.clearcoatRoughness,
                        defaults.clearcoatRoughness);
    }
    ImGui::PopID();
}

// KHR_materials_sheen's colour and roughness in a section of their own under the coat's, first
// shown open where the part has a sheen (each part keeps its own open state); its maps are
// among the part's maps above. A colour of 0 is none.
void drawSheen(Material& material, const Material& file, const Material& defaults, int part, std::string& said) {
    ImGui::PushID(part);
    ImGui::SetNextItemOpen(material.sheenColor != glm::vec3(0.0f), ImGuiCond_Once);
    const bool open = ImGui::CollapsingHeader("Sheen");
    recordItem("Sheen", "A fuzz of fibres over the part (KHR_materials_sheen), as on velvet or satin");
    if (open) {
        const bool sheened = material.sheenColor != glm::vec3(0.0f);
        if (layerButton("Add sheen", "Remove sheen", sheened, "sheen", said)) {
            material.sheenColor = glm::vec3(sheened ? 0.0f : 0.5f);
            material.sheenRoughness = sheened ? 0.0f : 0.5f;
        }
        ImGui::TextUnformatted("Sheen colour (sRGB)");
        ImGui::SetNextItemWidth(widthBesideReset(""));
        colorEditLinear("##Sheen colour", "The colour of the light the fibres reflect, brightest at grazing angles: "
                                          "black is no sheen (click the swatch to pick)",
                        &material.sheenColor);
        ImGui::SameLine();
        resetButton("Sheen colour", &material.sheenColor, file.sheenColor, defaults.sheenColor);
        sliderWithReset("Sheen roughness", "0: a thin bright rim at grazing angles; 1: a broad soft glow. "
                                           "Ctrl+click to type",
                        &material.sheenRoughness, 0.0f, 1.0f, file.sheenRoughness, defaults.sheenRoughness);
    }
    ImGui::PopID();
}

// KHR_materials_transmission's factor in a section of its own under the sheen's, first shown
// open where the part passes light; KHR_materials_volume's three beside it in a Volume section,
// which acts only on a transmission. Their maps are in the part's map list with the others.
void drawTransmission(Material& material, const Material& file, const Material& defaults, int part, std::string& said) {
    ImGui::PushID(part);
    ImGui::SetNextItemOpen(material.transmission > 0.0f, ImGuiCond_Once);
    const bool open = ImGui::CollapsingHeader("Transmission");
    recordItem("Transmission", "Light through the part's thin wall (KHR_materials_transmission), as through glass");
    if (open) {
        const bool passes = material.transmission > 0.0f;
        if (layerButton("Add transmission", "Remove transmission", passes, "transmission", said)) {   // a clear glass
            material.transmission = passes ? 0.0f : 1.0f;
        }
        sliderWithReset("Transmission factor", "How much of the diffuse light passes through instead, tinted by the base "
                                        "colour: 0 none, 1 clear glass",
                        &material.transmission, 0.0f, 1.0f, file.transmission, defaults.transmission);
    }
    ImGui::SetNextItemOpen(material.thickness > 0.0f, ImGuiCond_Once);
    const bool volume = ImGui::CollapsingHeader("Volume");
    recordItem("Volume", "What the light through the part loses inside it (KHR_materials_volume, Beer-Lambert)");
    if (volume) {
        sliderWithReset("Thickness", "The wall's thickness in the model's units (times the node's scale); 0: thin. "
                                     "Acts only where there is a transmission",
                        &material.thickness, 0.0f, 10.0f, file.thickness, defaults.thickness);
        ImGui::TextUnformatted("Attenuation colour (sRGB)");
        ImGui::SetNextItemWidth(widthBesideReset(""));
        colorEditLinear("##Attenuation colour", "The colour white light turns after the attenuation distance inside",
                        &material.attenuationColor);
        ImGui::SameLine();
        resetButton("Attenuation colour", &material.attenuationColor, file.attenuationColor, defaults.attenuationColor);
        sliderWithReset("Attenuation distance", "How far inside the light travels to take the attenuation colour, in "
                                                "the model's units; 0: infinitely far (no attenuation)",
                        &material.attenuationDistance, 0.0f, 10.0f, file.attenuationDistance,
                        defaults.attenuationDistance,
                        material.attenuationDistance > 0.0f ? "%.3f" : "none (%.0f)");
    }
    ImGui::PopID();
}

// KHR_materials_anisotropy's strength and rotation in a section of their own under the
// transmission's, first shown open where the part's highlight is stretched; its map is kept with
// the part (not drawn). A strength of 0 is none.
void drawAnisotropy(Material& material, const Material& file, const Material& defaults, int part, std::string& said) {
    ImGui::PushID(part);
    ImGui::SetNextItemOpen(material.anisotropyStrength > 0.0f, ImGuiCond_Once);
    const bool open = ImGui::CollapsingHeader("Anisotropy");
    recordItem("Anisotropy", "Highlights stretched along one direction (KHR_materials_anisotropy), as on brushed metal");
    if (open) {
        const bool stretched = material.anisotropyStrength > 0.0f;
        if (layerButton("Add anisotropy", "Remove anisotropy", stretched, "anisotropy", said)) {   // added: half stretched
            material.anisotropyStrength = stretched ? 0.0f : 0.5f;
            material.anisotropyRotation = 0.0f;
        }
        sliderWithReset("Anisotropy strength", "How far the highlight is stretched along the direction: 0 round, "
                                               "1 drawn out fully. Ctrl+click to type",
                        &material.anisotropyStrength, 0.0f, 1.0f, file.anisotropyStrength,
                        defaults.anisotropyStrength);
        sliderWithReset("Anisotropy rotation", "The stretch's direction, in radians counter-clockwise from the "
                                               "mesh's tangent. Ctrl+click to type",
                        &material.anisotropyRotation, -3.14159265f, 3.14159265f, file.anisotropyRotation,
                        defaults.anisotropyRotation);
    }
    ImGui::PopID();
}

// KHR_materials_specular's tint of the dielectric's F0 and weight of its Fresnel (with
// KHR_materials_ior's F0 beyond 0.08 in the tint), in a section of their own under the
// anisotropy's, first shown open where the part has them; the F0 they give, and the ior it
// corresponds to, said below. A tint of 1 and a weight of 1 are none.
void drawSpecularColour(Material& material, const Material& file, const Material& defaults, int part) {
    ImGui::PushID(part);
    ImGui::SetNextItemOpen(material.specularTint != glm::vec3(1.0f) || material.specularWeight != 1.0f,
                           ImGuiCond_Once);
    const bool open = ImGui::CollapsingHeader("Specular colour");
    recordItem("Specular colour", "The dielectric's reflection tinted and weighted (KHR_materials_specular, "
                                  "KHR_materials_ior), as on a tinted plastic or a gem");
    if (open) {
        // Linear numbers, not a colour picker: the tint runs past 1 (an F0 above 0.08), which an sRGB
        // swatch cannot show.
        ImGui::TextUnformatted("Specular tint (linear; 1 1 1 is none)");
        ImGui::SetNextItemWidth(widthBesideReset(""));
        ImGui::DragFloat3("##Specular tint", &material.specularTint.x, 0.01f, 0.0f, 12.5f, "%.3f",
                          ImGuiSliderFlags_AlwaysClamp);
        recordItem("Specular tint", "Multiplies the non-metal's reflectance head-on, 0.08 specular, per channel "
                                    "(linear): 1 keeps it; above 1 reaches a gem's F0 (up to 12.5, F0 1). Drag, or "
                                    "Ctrl+click to type");
        ImGui::SameLine();
        resetButton("Specular tint", &material.specularTint, file.specularTint, defaults.specularTint);
        sliderWithReset("Specular weight", "Scales the non-metal's whole reflection, head-on and at grazing angles "
                                           "alike (glTF's specularFactor): 0 leaves only the diffuse",
                        &material.specularWeight, 0.0f, 1.0f, file.specularWeight, defaults.specularWeight);
        const shader::SurfaceMaterial derived =
            surfaceMaterial(MaterialParameters{.specular = material.specular, .metallic = 0.0f,
                                               .specularTint = material.specularTint});
        // The extension's dielectric_f0 (the weight in); the ior its largest channel's before the
        // weight, from F0 = ((ior - 1) / (ior + 1))^2.
        const glm::vec3 tinted = derived.dielectricF0;
        const glm::vec3 f0 = tinted * material.specularWeight;
        const float root = std::sqrt(std::min(std::max({tinted.r, tinted.g, tinted.b}), 0.999999f));
        ImGui::PushTextWrapPos(0.0f);   // wraps at the panel's edge
        ImGui::TextDisabled("Non-metal F0 %.3f %.3f %.3f (ior %.2f), F90 %.2f", double(f0.r), double(f0.g), double(f0.b),
                            double((1.0f + root) / (1.0f - root)), double(material.specularWeight));
        ImGui::PopTextWrapPos();
    }
    ImGui::PopID();
}

// KHR_materials_iridescence's thin film in a section of its own under the specular colour's,
// first shown open where the part has one; its maps are in the part's map list with the others.
// A strength of 0 is none.
void drawIridescence(Material& material, const Material& file, const Material& defaults, int part, std::string& said) {
    ImGui::PushID(part);
    ImGui::SetNextItemOpen(material.iridescence > 0.0f, ImGuiCond_Once);
    const bool open = ImGui::CollapsingHeader("Iridescence");
    recordItem("Iridescence", "A thin film's interference colours over the part (KHR_materials_iridescence), as on a "
                              "soap bubble, an oil slick or heat-tinted metal");
    if (open) {
        const bool filmed = material.iridescence > 0.0f;
        if (layerButton("Add iridescence", "Remove iridescence", filmed, "thin film", said)) {   // the extension's film
            const MaterialParameters plain;
            material.iridescence = filmed ? 0.0f : 1.0f;
            material.iridescenceIor = plain.iridescenceIor;
            material.iridescenceThicknessMinimum = plain.iridescenceThicknessMinimum;
            material.iridescenceThicknessMaximum = plain.iridescenceThicknessMaximum;
        }
        sliderWithReset("Iridescence strength", "How much of the reflection the film colours: 0 none, 1 all",
                        &material.iridescence, 0.0f, 1.0f, file.iridescence, defaults.iridescence);
        sliderWithReset("Film ior", "The film's index of refraction: its colours shift and strengthen away from "
                                    "the surroundings' 1. Ctrl+click to type",
                        &material.iridescenceIor, 1.0f, 2.5f, file.iridescenceIor, defaults.iridescenceIor);
        sliderWithReset("Film thickness", "The film's thickness in nanometres (its thickness map's white): its "
                                          "colours cycle as it grows; 0 is no film. Ctrl+click to type",
                        &material.iridescenceThicknessMaximum, 0.0f, 1200.0f, file.iridescenceThicknessMaximum,
                        defaults.iridescenceThicknessMaximum);
        sliderWithReset("Film thickness minimum", "The thickness in nanometres where the thickness map is black "
                                                  "(used only with a thickness map)",
                        &material.iridescenceThicknessMinimum, 0.0f, 1200.0f, file.iridescenceThicknessMinimum,
                        defaults.iridescenceThicknessMinimum);
    }
    ImGui::PopID();
}

// Every layer's section under the factors, in one order, for a model's part (`part` its index)
// and for Patina's own material alike; a layer put on or taken off whole is said in `status`,
// naming the material.
void drawLayers(Material& material, const Material& file, const Material& defaults, int part, std::string& status) {
    std::string said;
    drawClearcoat(material, file, defaults, part, said);
    drawSheen(material, file, defaults, part, said);
    drawTransmission(material, file, defaults, part, said);
    drawAnisotropy(material, file, defaults, part, said);
    drawSpecularColour(material, file, defaults, part);
    drawIridescence(material, file, defaults, part, said);
    if (!said.empty()) {
        status = said + " \"" + material.name + "\" (Ctrl+Z undoes it)";
    }
}

// "a, b, c".
std::string joinNames(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) {
        text += (text.empty() ? "" : ", ") + name;
    }
    return text;
}

// One part's row: a swatch of its base colour as tuned, its index and name, how many maps it
// uses, and the nodes drawn with it, greyed (a model's materials often share one name:
// 2CylinderEngine has nine "Material_17"); the maps and every node in the tooltip.
bool drawPartRow(const Document& document, int i, bool selected) {
    const Material tuned = modelMaterial(document, document.scene, i);
    const glm::vec3 srgb = shader::srgbColor(glm::clamp(tuned.baseColor, 0.0f, 1.0f));
    const float side = ImGui::GetTextLineHeight();
    ImGui::ColorButton("##swatch", ImVec4(srgb.r, srgb.g, srgb.b, 1.0f),
                       ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop, ImVec2(side, side));
    ImGui::SameLine();
    const std::string maps = mapNames(document, i);
    const int mapCount = maps.empty() ? 0 : int(std::count(maps.begin(), maps.end(), ',')) + 1;
    const std::string label = std::to_string(i) + ": " + document.model->materials[size_t(i)].name +
                              (mapCount ? "  (" + std::to_string(mapCount) + (mapCount > 1 ? " maps)" : " map)") : "");
    const std::string nodes = joinNames(partNodes(document, i));
    const ImVec2 start = ImGui::GetCursorScreenPos();
    const bool clicked = ImGui::Selectable(("##part" + std::to_string(i)).c_str(), selected);
    const std::string tooltip = label + "\nDrawn on: " + (nodes.empty() ? "no node" : nodes) + "\n" +
                                (maps.empty() ? "Factors only, no texture maps" : "Maps: " + maps);
    recordItem("part:" + std::to_string(i), tooltip.c_str());
    // The label, then the nodes greyed, cut where the row ends.
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float right = ImGui::GetItemRectMax().x;
    draw->AddText(start, ImGui::GetColorU32(ImGuiCol_Text), label.c_str());
    const float after = start.x + ImGui::CalcTextSize(label.c_str()).x + px(10);
    if (!nodes.empty() && after < right) {
        draw->AddText(ImVec2(after, start.y), ImGui::GetColorU32(ImGuiCol_TextDisabled),
                      fittedText(nodes, right - after).c_str());
    }
    return clicked;
}

// A model's parts (its materials), a row each, under a search box that keeps the rows whose
// material or node has what is typed. The list grows with the panel (at least six rows, up to
// about half the panel). A click makes a part the one the panel edits; a part picked in the
// viewport is scrolled into view.
void drawPartList(const Document& document, Interaction& interaction) {
    const int count = modelMaterialCount(document);
    int& selected = interaction.selectedModelMaterial;
    selected = std::clamp(selected, 0, count - 1);
    const float line = ImGui::GetTextLineHeightWithSpacing();
    ImGui::TextUnformatted("Parts");
    if (count > 6) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-FLT_MIN);
        inputString("##part search", &interaction.partFilter, 0, "Search parts or nodes");
        recordItem("part search", "Show only the parts whose material or node has this in its name");
    }
    std::vector<int> rows;
    for (int i = 0; i < count; ++i) {
        if (partMatches(document, i, interaction.partFilter)) {
            rows.push_back(i);
        }
    }
    const float least = (float(std::min(count, 6)) + 0.4f) * line;
    const float wanted = (float(rows.size()) + 0.4f) * line;
    const float height = std::max(least, std::min(wanted, ImGui::GetContentRegionAvail().y * 0.5f));
    if (ImGui::BeginListBox("##parts", ImVec2(-FLT_MIN, height))) {
        for (int i : rows) {
            ImGui::PushID(i);
            if (drawPartRow(document, i, i == selected)) {
                selected = i;
            }
            if (i == selected && interaction.partScrolledTo != selected) {
                ImGui::SetScrollHereY();
                interaction.partScrolledTo = selected;
            }
            ImGui::PopID();
        }
        if (rows.empty()) {
            ImGui::TextDisabled("No part or node has \"%s\" in its name.", interaction.partFilter.c_str());
        }
        ImGui::EndListBox();
    }
    recordItem("Model material", "Which of the model's materials the sliders, presets and A/B edit (or click a part "
                                 "in the viewport)");
}

// The map's image, small; hovered, larger with its name and size. Greyed where it is not drawn.
void drawMapThumbnail(const Document& document, EditorServices& services, const char* name, int image, bool shown) {
    const Texture* thumbnail = services.mapThumbnail(document.model, image);
    if (!thumbnail) {
        return;
    }
    const float side = ImGui::GetFrameHeight() * 1.6f;
    auto fitted = [&](float box) {
        const float scale = box / float(std::max(thumbnail->width(), thumbnail->height()));
        return ImVec2(float(thumbnail->width()) * scale, float(thumbnail->height()) * scale);
    };
    const auto id = reinterpret_cast<ImTextureID>(static_cast<intptr_t>(thumbnail->id()));
    ImGui::Image(id, fitted(side), ImVec2(0, 0), ImVec2(1, 1), ImVec4(1, 1, 1, shown ? 1.0f : 0.35f));
    recordItem("map image: " + std::string(name));
    if (ImGui::IsItemHovered()) {
        const ModelImage& source = document.model->images.at(size_t(image));
        ImGui::BeginTooltip();
        ImGui::Image(id, fitted(px(160)));
        ImGui::Text("%s, %d x %d", source.name.c_str(), source.width, source.height);
        ImGui::EndTooltip();
    }
    ImGui::SameLine();
}

// Replace... puts an image file in place of the map (a path dialog); Restore, shown once it is
// replaced, draws the file's own again. Both undoable, saved in the scene.
void drawMapReplace(Document& document, AssetCache& assets, Prompts& prompts, int index, const char* key,
                    const char* name) {
    const std::string replaced = mapReplacement(document.scene, index, key);
    ImGui::SameLine();
    ImGui::PushID(key);
    if (ImGui::SmallButton("Replace...")) {
        prompts.replacedMaterial = index;
        prompts.replacedMap = key;
        const std::filesystem::path near = std::filesystem::path(replaced.empty() ? document.scene.meshFile : replaced);
        startPathDialog(prompts, Prompts::PathDialog::ReplaceMap, near.parent_path() / "");
    }
    recordItem("map replace: " + std::string(name),
               ("Draw an image file (PNG, JPEG or WebP) in place of the " + std::string(name) +
                " map, with its UV set, sampling and transform" +
                (replaced.empty()
                     ? std::string()
                     : "; now " + shownPath(replaced, std::filesystem::path(document.scene.meshFile).parent_path())))
                   .c_str());
    if (!replaced.empty()) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Restore")) {
            restoreMap(document, assets, prompts, index, key);
        }
        recordItem("map restore: " + std::string(name),
                   ("Draw the file's own " + std::string(name) + " map again, not " +
                    std::filesystem::path(replaced).filename().string())
                       .c_str());
    }
    ImGui::PopID();
}

// Each map the file gives the part, as a thumbnail and a checkbox: unticked, the factor alone
// is drawn there (an undoable edit, saved in the scene and kept by an export).
void drawMapSwitches(Document& document, AssetCache& assets, Prompts& prompts, EditorServices& services, int index) {
    for (const auto& map : mapsOf(document.model->materials.at(size_t(index)))) {
        if (!map.slot->present()) {
            continue;
        }
        bool shown = mapShown(document.scene, index, map.key);
        drawMapThumbnail(document, services, map.name, map.slot->image, shown);
        const std::string label = std::string(map.name) + "##map";
        if (ImGui::Checkbox(label.c_str(), &shown)) {
            setMapShown(document, document.scene, index, map.key, shown);
        }
        recordItem("map: " + std::string(map.name), ("Draw the " + std::string(map.name) +
                                   " map; unticked, its factor alone is drawn (the map stays in the file)")
                                      .c_str());
        drawMapReplace(document, assets, prompts, index, map.key, map.name);
    }
}

// Every extension the model's file uses and what Patina draws of it: what the picture lacks
// of the file is said here as in the status line when it opened.
void drawModelExtensions(const Model& model) {
    const std::string title = "File extensions (" + std::to_string(model.extensions.size()) + ")###File extensions";
    const bool open = ImGui::CollapsingHeader(title.c_str());
    recordItem("File extensions", "The glTF extensions the model's file uses, each with what Patina draws of it");
    if (!open) {
        return;
    }
    ImGui::PushTextWrapPos(0.0f);
    if (model.extensions.empty()) {
        ImGui::TextDisabled("None: the file is core glTF 2.0");
    }
    for (const ModelExtension& extension : model.extensions) {
        const bool lacking =
            extension.support == ExtensionSupport::NotDrawn || extension.support == ExtensionSupport::Unknown;
        const std::string line = gltf::extensionLine(extension);
        if (lacking) {
            ImGui::TextColored(kWarningColour, "%s", line.c_str());
        } else {
            ImGui::TextDisabled("%s", line.c_str());
        }
    }
    ImGui::PopTextWrapPos();
}

// The edited part of a model: its factors, each multiplying its map as glTF defines.
void drawModelMaterial(Document& document, Interaction& interaction, AssetCache& assets, Prompts& prompts,
                       EditorServices& services) {
    drawPartList(document, interaction);
    const int selected = interaction.selectedModelMaterial;
    const std::string maps = mapNames(document, selected);
    const char* colours = hasVertexColours(document, selected) ? " Its vertex colours multiply the base colour." : "";
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s%s", maps.empty() ? "No texture maps: the factors are its values."
                                             : ("Maps: " + maps + ". Each factor multiplies its map.").c_str(),
                        colours);
    ImGui::PopTextWrapPos();
    drawMapSwitches(document, assets, prompts, services, selected);
    Material material = modelMaterial(document, document.scene, selected);
    const Material before = material;
    Scene untuned = document.scene;
    untuned.modelMaterials.clear();
    const Material saved = modelMaterial(document, document.savedScene, selected);
    const Material defaults = modelMaterial(document, untuned, selected);
    drawFactors(material, saved, defaults);
    // The layer sections' open states are the model's own: another file's part of the same
    // index must not open (or close) them as that part's were left.
    ImGui::PushID(document.scene.meshFile.c_str());
    drawLayers(material, saved, defaults, selected, prompts.status);
    ImGui::PopID();
    if (material != before) {
        setModelMaterial(document, document.scene, selected, material);
    }
    if (document.model) {
        drawModelExtensions(*document.model);
    }
}
}  // namespace

void drawMaterialPanel(EditorState& state, EditorServices& services) {
    if (modelMaterialCount(state) > 0) {
        drawModelMaterial(state, state, *state.assets, state, services);
    } else {
        Material& material = state.scene.material;
        inputString("Name", &material.name);
        recordItem("Material name", "The material's name, saved in its file and shown in captions");
        drawFactors(material, state.savedMaterial, Material());
        // Patina's own material carries the layers too (the presets' coat, sheen and film), in
        // the sections a model's part has; their open states are the material file's own, so
        // that a file opened with a film shows it open.
        ImGui::PushID(("own material " + state.materialPath.string()).c_str());
        drawLayers(material, state.savedMaterial, Material(), 0, state.status);
        ImGui::PopID();
    }

    ImGui::SetNextItemOpen(state.showAdvanced);
    state.showAdvanced = ImGui::CollapsingHeader("Advanced");
    recordItem("Advanced", "The BRDF model, render path, timings, derived values and the Accuracy tab");
    if (state.showAdvanced) {
        drawAdvanced(state, state);
    }
}

}  // namespace patina::editor
