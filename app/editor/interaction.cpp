#include "interaction.h"

#include <algorithm>

#include "editor_state.h"
#include "files/input_error.h"
#include "shading/shading.h"

namespace patina::editor {

void toggleSolo(Interaction& interaction, int index) {
    interaction.soloLight = interaction.soloLight == index ? -1 : index;
}

bool soloedOut(const EditorState& state, int index) {
    return state.hasLight(state.soloLight) && index != state.soloLight;
}

Scene renderedScene(const EditorState& state) {
    Scene scene = state.scene;
    if (state.hasLight(state.soloLight)) {
        for (size_t i = 0; i < scene.lights.size(); ++i) {
            scene.lights[i].enabled = !soloedOut(state, int(i));
        }
    }
    return scene;
}

Material editedMaterial(const EditorState& state) {
    if (modelMaterialCount(state) > 0) {
        return modelMaterial(state, state.scene, std::clamp(state.selectedModelMaterial, 0, modelMaterialCount(state) - 1));
    }
    return state.scene.material;
}

Material labelledMaterial(const EditorState& state) {
    Material material = editedMaterial(state);
    if (modelMaterialCount(state) > 0) {
        const auto preset = state.partPresets.find(std::clamp(state.selectedModelMaterial, 0, modelMaterialCount(state) - 1));
        if (preset != state.partPresets.end() && preset->second.second == material) {
            material.name += " (" + preset->second.first + ")";
        }
    }
    return material;
}

void setEditedMaterial(const EditorState& state, Scene& scene, const Material& material) {
    if (modelMaterialCount(state) > 0) {
        setModelMaterial(state, scene, std::clamp(state.selectedModelMaterial, 0, modelMaterialCount(state) - 1),
                         material);
    } else {
        scene.material = material;
    }
}

Scene withMaterial(const EditorState& state, const Material& material) {
    Scene scene = renderedScene(state);
    setEditedMaterial(state, scene, material);
    return scene;
}

void keepChannelShowable(EditorState& state) {
    if (state.channel.channel != shader::CHANNEL_LIGHT) {
        return;
    }
    try {
        channelLights(renderedScene(state).lights, state.channel);
    } catch (const InputError&) {
        state.status = "The viewport shows the picture again: no enabled light \"" + state.channel.light + "\" to show";
        state.channel = {-1, "", state.channel.srgb, state.channel.strictPbr};   // the picture; the options stay
    }
}

}  // namespace patina::editor
