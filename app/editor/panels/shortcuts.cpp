#include <imgui.h>

#include "keys.h"
#include "menu_actions.h"
#include "panels.h"

namespace patina::editor {

void handleShortcuts(EditorState& state, EditorServices& services) {
    if (ImGui::GetIO().WantTextInput) {
        return;   // typing a name or a path: keys are text
    }
    const KeyPresses& keys = services.keyPresses;
    // F1 shows the shortcuts and Escape closes them, as any help window, behind a prompt too.
    if (pressed(keys, kKeyF1)) {
        state.showShortcuts = !state.showShortcuts;
    } else if (pressed(keys, kKeyEscape)) {
        state.showShortcuts = false;
    }
    if (promptOpen(state)) {
        // Nothing edits the document behind a prompt: Ctrl+Z or Ctrl+O there once undid or
        // replaced what the prompt was asking about.
        return;
    }
    if (pressed(keys, kKeyN, true)) {
        requestNew(state);
    }
    if (pressed(keys, kKeyZ, true)) {
        undo(state);
    }
    if (pressed(keys, kKeyZ, true, true) || pressed(keys, kKeyY, true)) {
        redo(state);
    }
    if (pressed(keys, kKeyS, true)) {
        save(state);
    }
    if (pressed(keys, kKeyS, true, true)) {
        saveAs(state);
    }
    if (pressed(keys, kKeyS, true, false, true)) {
        saveSceneDocument(state);
    }
    if (pressed(keys, kKeyO, true)) {
        openDialog(state);
    }
    if (pressed(keys, kKeyQ, true)) {
        state.pendingQuit = true;
    }
    if (pressed(keys, kKeyF12)) {
        screenshot(state, services);
    }
    if (pressed(keys, kKeyDelete)) {
        deleteLight(state, state.selectedLight);   // one undo step, as the Delete button
    }
}

}  // namespace patina::editor
