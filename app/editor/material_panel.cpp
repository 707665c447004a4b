#include <imgui.h>

#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "panels.h"
#include "widgets.h"

namespace patina::editor {

void drawMaterialPanel(EditorState& state) {
    Material& material = state.scene.material;
    const Material defaults;
    const Material& file = state.savedMaterial;   // as opened or last saved
    inputString("Name", &material.name);
    ImGui::SetNextItemWidth(widthBesideReset("Base colour"));
    colorEditLinear("Base colour", &material.baseColor);
    ImGui::SameLine();
    resetButton("Base colour", &material.baseColor, file.baseColor, defaults.baseColor);
    sliderWithReset("Roughness", &material.roughness, 0.0f, 1.0f, file.roughness, defaults.roughness);
    sliderWithReset("Specular", &material.specular, 0.0f, 1.0f, file.specular, defaults.specular);
    sliderWithReset("Metallic", &material.metallic, 0.0f, 1.0f, file.metallic, defaults.metallic);
    if (ImGui::BeginCombo("Model", std::string(brdfModel(material.model).name).c_str())) {
        for (const BrdfModelInfo& model : brdfModels()) {
            if (ImGui::Selectable(std::string(model.name).c_str(), model.id == material.model)) {
                material.model = model.id;
            }
            if (ImGui::IsItemHovered()) {
                ImGui::SetTooltip("%s", std::string(model.summary).c_str());
            }
        }
        ImGui::EndCombo();
    }
    recordItem("Model");

    // What the shader derives from the four parameters (shaders/shared/brdf.glsl), guards included.
    const shader::SurfaceMaterial derived = surfaceMaterial(material);
    ImGui::Separator();
    ImGui::TextDisabled("Derived");
    const float k = (derived.roughness + 1.0f) * (derived.roughness + 1.0f) / 8.0f;
    ImGui::Text("alpha = r^2       %.5f", double(derived.alpha));
    ImGui::Text("k = (r+1)^2 / 8   %.5f", double(k));
    if (derived.roughness != material.roughness) {
        ImGui::TextDisabled("roughness floored at %.3f (D is 0/0 at r = 0)", double(derived.roughness));
    }
    linearSwatch("c_diff", derived.diffuseColor);
    linearSwatch("F0    ", derived.f0);
}

}  // namespace patina::editor
