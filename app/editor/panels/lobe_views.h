#pragma once
// BRDF Explorer's views in the lobe panel (Burley 2012, section 3): the theta_h / theta_d image
// slice, the directional albedo against theta_v beside the ground truth, and the 3D lobe; each
// shows B, and A beside or over it when set, as the polar plot does.
#include <imgui.h>

#include "window/editor_services.h"
#include "state/editor_state.h"

namespace patina::editor {

void drawSliceView(const Document& document, const Interaction& interaction, ImVec2 size);
void drawAlbedoView(const Document& document, const Interaction& interaction, EditorServices& services, ImVec2 size);
// Dragged, it turns (interaction.lobe's yaw and pitch).
void drawLobe3dView(const Document& document, Interaction& interaction, ImVec2 size);

}  // namespace patina::editor
