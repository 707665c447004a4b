#include "state/interaction.h"

#include <algorithm>

#include "state/editor_state.h"
#include "files/input_error.h"
#include "shading/shading.h"

namespace patina::editor {

void toggleSolo(Interaction& interaction, int index) {
    interaction.soloLight = interaction.soloLight == index ? -1 : index;
}

bool soloedOut(const Document& document, const Interaction& interaction, int index) {
    return document.hasLight(interaction.soloLight) && index != interaction.soloLight;
}

Scene renderedScene(const Document& document, const Interaction& interaction) {
    Scene scene = document.scene;
    if (document.hasLight(interaction.soloLight)) {
        for (size_t i = 0; i < scene.lights.size(); ++i) {
            scene.lights[i].enabled = !soloedOut(document, interaction, int(i));
        }
    }
    return scene;
}

namespace {
// The shown model's part the Material panel edits; -1 for a built-in mesh (its material).
int editedPart(const Document& document, const Interaction& interaction) {
    const int count = modelMaterialCount(document);
    return count > 0 ? std::clamp(interaction.selectedModelMaterial, 0, count - 1) : -1;
}
}  // namespace

Material editedMaterial(const Document& document, const Interaction& interaction) {
    const int part = editedPart(document, interaction);
    return part >= 0 ? modelMaterial(document, document.scene, part) : document.scene.material;
}

Material labelledMaterial(const Document& document, const Interaction& interaction) {
    Material material = editedMaterial(document, interaction);
    if (const int part = editedPart(document, interaction); part >= 0) {
        const auto preset = interaction.partPresets.find(part);
        if (preset != interaction.partPresets.end() && preset->second.second == material) {
            material.name += " (" + preset->second.first + ")";
        }
    }
    return material;
}

void setEditedMaterial(const Document& document, const Interaction& interaction, Scene& scene,
                       const Material& material) {
    if (const int part = editedPart(document, interaction); part >= 0) {
        setModelMaterial(document, scene, part, material);
    } else {
        scene.material = material;
    }
}

Scene withMaterial(const Document& document, const Interaction& interaction, const Material& material) {
    Scene scene = renderedScene(document, interaction);
    setEditedMaterial(document, interaction, scene, material);
    return scene;
}

void keepChannelShowable(const Document& document, Interaction& interaction, Prompts& prompts) {
    if (interaction.channel.channel != shader::CHANNEL_LIGHT) {
        return;
    }
    try {
        channelLights(renderedScene(document, interaction).lights, interaction.channel);
    } catch (const InputError&) {
        prompts.status =
            "The viewport shows the picture again: no enabled light \"" + interaction.channel.light + "\" to show";
        interaction.channel = {-1, "", interaction.channel.srgb,
                               interaction.channel.strictPbr};   // the picture; the options stay
    }
}

}  // namespace patina::editor
