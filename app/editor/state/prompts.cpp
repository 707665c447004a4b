#include "state/prompts.h"

#include "state/editor_state.h"

namespace patina::editor {

bool promptOpen(const Jobs& jobs, const Prompts& prompts) {
    return jobs.recoverable.has_value() || prompts.pendingOpen.has_value() || prompts.pendingNew ||
           prompts.pendingQuit || prompts.pathDialog != Prompts::PathDialog::None ||
           !prompts.presets.renaming.empty() || !prompts.presets.deleting.empty();
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) {
        text += (text.empty() ? "" : "\n") + line;
    }
    return text;
}

}  // namespace patina::editor
