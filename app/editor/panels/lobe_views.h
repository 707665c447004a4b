#pragma once
// BRDF Explorer's views in the lobe panel (Burley 2012, section 3): the theta_h / theta_d image
// slice, the directional albedo against theta_v beside the ground truth, and the 3D lobe; each
// shows B, and A beside or over it when set, as the polar plot does.
#include <imgui.h>

#include "editor_services.h"
#include "editor_state.h"

namespace patina::editor {

void drawSliceView(EditorState& state, ImVec2 size);
void drawAlbedoView(const EditorState& state, EditorServices& services, ImVec2 size);
void drawLobe3dView(EditorState& state, ImVec2 size);

}  // namespace patina::editor
