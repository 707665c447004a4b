#include <imgui.h>

#include "accuracy/accuracy.h"
#include "panels/panels.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
// A small stratified set of angles for the current material's live error numbers.
const AccuracySet& angleSet() {
    static const AccuracySet set = stratifiedAccuracySet(1, 1, 1, 2048, 7);
    return set;
}
}  // namespace

AccuracyNumbers accuracyOf(const Material& material) {
    AccuracySet set = angleSet();
    for (AccuracySample& sample : set.samples) {
        sample.material = material;
    }
    return {physicalError(material.model, set), cpuImplementationError(material.model, set)};
}

void drawAccuracyPanel(const Document& document, const Interaction& interaction, const Preferences& preferences,
                       EditorServices& services) {
    const Material material = editedMaterial(document, interaction);
    const BrdfModelInfo& model = brdfModel(material.model);
    ImGui::Text("Model: %s", std::string(model.name).c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%s", std::string(model.summary).c_str());
    const AccuracyNumbers& numbers = services.accuracy(material);
    ImGui::Text("This material against reference (f*NoL, 2048 directions, NoV and NoL >= 0.01):");
    ImGui::Text("  relative RMSE %.4f   max relative %.4f", numbers.physical.relativeRmse, numbers.physical.maxRelative);
    ImGui::Text("fp32 against the same model in fp64:");
    ImGui::Text("  relative RMSE %.2e   max relative %.2e", numbers.implementation.relativeRmse,
                numbers.implementation.maxRelative);
    ImGui::TextDisabled("The lobe panel draws the reference lobe in cyan.");
    ImGui::Separator();
    if (const Texture* chart = services.benchChart(preferences.benchFolder / "speed_accuracy.png")) {
        const float width = ImGui::GetContentRegionAvail().x;
        const float height = width * float(chart->height()) / float(chart->width());
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(chart->id())), ImVec2(width, height));
    } else {
        ImGui::TextWrapped("No bench chart in %s yet: run `patina bench --out-dir %s`.",
                           preferences.benchFolder.string().c_str(), preferences.benchFolder.string().c_str());
    }
}

}  // namespace patina::editor
