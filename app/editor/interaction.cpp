#include "interaction.h"

#include "editor_state.h"

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

Scene withMaterial(const EditorState& state, const Material& material) {
    Scene scene = renderedScene(state);
    scene.material = material;
    return scene;
}

}  // namespace patina::editor
