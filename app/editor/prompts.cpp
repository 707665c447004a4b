#include "prompts.h"

#include "editor_state.h"

namespace patina::editor {

bool promptOpen(const EditorState& state) {
    return state.recoverable.has_value() || state.pendingOpen.has_value() || state.pendingNew ||
           state.pendingQuit || state.pathDialog != EditorState::PathDialog::None ||
           !state.presets.renaming.empty() || !state.presets.deleting.empty();
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) {
        text += (text.empty() ? "" : "\n") + line;
    }
    return text;
}

}  // namespace patina::editor
