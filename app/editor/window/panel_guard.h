#pragma once
// Runs a panel's drawing so that an error thrown inside it is shown, not fatal: ImGui's stacks
// are closed back to where the panel began (its window, child windows, popups, tab bars, ID and
// style stacks), the message goes into Prompts::error, and the frame goes on.
#include <functional>

#include "state/prompts.h"

namespace patina::editor {

// Calls `draw`; if it throws, unwinds what it left open and reports "<what> failed: <error>".
// Returns false when it threw.
bool drawGuarded(Prompts& prompts, const char* what, const std::function<void()>& draw);

// Closes every window and stack still open in this frame (the last resort around a whole frame,
// before ImGui::Render). Returns the number of windows it closed.
int recoverFrame();

}  // namespace patina::editor
