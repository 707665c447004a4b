#include "window/window_input.h"

#include <algorithm>
#include <utility>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

namespace patina::editor {
namespace {

WindowInput& inputOf(GLFWwindow* window) {
    return *static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
    for (int i = 0; i < count; ++i) {
        inputOf(window).droppedFiles.emplace_back(paths[i]);
    }
}

// Installed before ImGui's, which calls it after its own (imgui_impl_glfw chains callbacks).
void onKey(GLFWwindow* window, int key, int, int action, int mods) {
    if (action == GLFW_PRESS || action == GLFW_REPEAT) {
        inputOf(window).keyPresses.push_back(
            {key, (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_ALT) != 0});
    }
}

void deliver(GLFWwindow* window, const WindowInput::Event& event) {
    using Kind = WindowInput::Event::Kind;
    switch (event.kind) {
    case Kind::Key:
        ImGui_ImplGlfw_KeyCallback(window, event.key, event.scancode, event.action, event.mods);
        break;
    case Kind::Character:
        ImGui_ImplGlfw_CharCallback(window, event.codepoint);
        break;
    case Kind::MouseButton:
        ImGui_ImplGlfw_MouseButtonCallback(window, event.key, event.action, event.mods);
        break;
    case Kind::Scroll:
        ImGui_ImplGlfw_ScrollCallback(window, event.x, event.y);
        break;
    }
}

// A key ImGui reads by its state in this frame: Enter, Backspace, the arrows, the modifiers, and
// a letter held with Ctrl, Alt or Super (Ctrl+A). A plain character key is read as the
// character it typed, which ImGui queues.
bool readByState(int key) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool character = key >= GLFW_KEY_SPACE && key <= GLFW_KEY_WORLD_2;
    return !character || io.KeyCtrl || io.KeyAlt || io.KeySuper;
}

// Through to ImGui now, or in order after what already waits.
void offer(GLFWwindow* window, const WindowInput::Event& event) {
    WindowInput& input = inputOf(window);
    input.arrived = true;
    const bool key = event.kind == WindowInput::Event::Kind::Key;
    const bool releasesANewKey =
        key && event.action == GLFW_RELEASE && readByState(event.key) &&
        std::find(input.pressedSinceFrame.begin(), input.pressedSinceFrame.end(), event.key) !=
            input.pressedSinceFrame.end();
    if (!input.waiting.empty() || releasesANewKey) {
        input.waiting.push_back(event);
        return;
    }
    if (key && event.action == GLFW_PRESS) {
        input.pressedSinceFrame.push_back(event.key);
    }
    deliver(window, event);
}

using Kind = WindowInput::Event::Kind;

// Installed over ImGui's (after it), so that they see every event first.
void onKeyForImGui(GLFWwindow* window, int key, int scancode, int action, int mods) {
    offer(window, {Kind::Key, key, scancode, action, mods});
}
void onCharForImGui(GLFWwindow* window, unsigned int codepoint) {
    offer(window, {Kind::Character, 0, 0, 0, 0, codepoint});
}
void onMouseButtonForImGui(GLFWwindow* window, int button, int action, int mods) {
    offer(window, {Kind::MouseButton, button, 0, action, mods});
}
void onScrollForImGui(GLFWwindow* window, double x, double y) {
    offer(window, {Kind::Scroll, 0, 0, 0, 0, 0, x, y});
}
void onCursor(GLFWwindow* window, double, double) {   // ImGui 1.86 polls the position: none to chain
    inputOf(window).arrived = true;
}

}  // namespace

void installInputCallbacksBeforeImGui(GLFWwindow* window, WindowInput& input) {
    glfwSetWindowUserPointer(window, &input);
    glfwSetDropCallback(window, onDrop);
    glfwSetKeyCallback(window, onKey);
}

void installInputCallbacksOverImGui(GLFWwindow* window) {
    glfwSetKeyCallback(window, onKeyForImGui);
    glfwSetCharCallback(window, onCharForImGui);
    glfwSetMouseButtonCallback(window, onMouseButtonForImGui);
    glfwSetScrollCallback(window, onScrollForImGui);
    glfwSetCursorPosCallback(window, onCursor);
}

void keysRead(GLFWwindow* window) {
    inputOf(window).pressedSinceFrame.clear();
}

void releaseWaitingInput(GLFWwindow* window) {
    WindowInput& input = inputOf(window);
    const std::vector<WindowInput::Event> waiting = std::exchange(input.waiting, {});
    for (const WindowInput::Event& event : waiting) {
        offer(window, event);   // marks the input arrived: the next frame is drawn for it
    }
}

}  // namespace patina::editor
