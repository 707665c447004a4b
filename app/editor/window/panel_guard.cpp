#include "window/panel_guard.h"

#include <exception>
#include <string>

#include <imgui.h>
#include <imgui_internal.h>

namespace patina::editor {

namespace {
// Ends the innermost window (a child, popup, combo or menu) with whatever it left open inside.
void endInnermostWindow() {
    ImGui::ErrorCheckEndWindowRecover(nullptr);
    if (ImGui::GetCurrentWindow()->Flags & ImGuiWindowFlags_ChildWindow) {
        ImGui::EndChild();
    } else {
        ImGui::End();   // also pops a popup's or menu's entry
    }
}
}  // namespace

bool drawGuarded(Prompts& prompts, const char* what, const std::function<void()>& draw) {
    ImGuiContext& context = *ImGui::GetCurrentContext();
    const int windows = context.CurrentWindowStack.Size;
    std::string message;
    try {
        draw();
        return true;
    } catch (const std::exception& error) {
        message = error.what();
    } catch (...) {
        message = "an unknown error";
    }
    // Back to the window the panel was drawing into, then its own stacks back to how Begin
    // left them (ErrorCheckEndWindowRecover compares against the sizes Begin recorded).
    while (context.CurrentWindowStack.Size > windows) {
        endInnermostWindow();
    }
    ImGui::ErrorCheckEndWindowRecover(nullptr);
    prompts.error = std::string(what) + " failed: " + message;
    return false;
}

int recoverFrame() {
    ImGuiContext& context = *ImGui::GetCurrentContext();
    int closed = 0;
    // The bottom entry is ImGui's own fallback window, which NewFrame opened and Render ends.
    while (context.CurrentWindowStack.Size > 1) {
        endInnermostWindow();
        ++closed;
    }
    ImGui::ErrorCheckEndWindowRecover(nullptr);
    return closed;
}

}  // namespace patina::editor
