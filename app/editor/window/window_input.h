#pragma once
#include <filesystem>
#include <vector>

#include "window/keys.h"

struct GLFWwindow;

// What GLFW hands the editor between frames, and the gate that feeds ImGui 1.86 so that a slow
// frame loses nothing. ImGui 1.86 reads each key's state and the modifiers once a frame: a key
// pressed and released between two frames was never seen, and characters typed in the same
// batch as Ctrl+A were dropped (ImGui ignores characters while it sees Ctrl down). So the
// release of a key pressed since the last frame waits for the next frame when the key is read
// by its state (not a plain character key, or one held with a modifier), and every event after
// a waiting one waits too, in order (ImGui 1.87's input queue does the same).
namespace patina::editor {

struct WindowInput {
    std::vector<std::filesystem::path> droppedFiles;
    KeyPresses keyPresses;   // for the shortcuts, every press, in order
    // Set by every input callback: input polled between frames earns the frames after it that
    // input which woke the loop does (a click is a press frame, then a release frame).
    bool arrived = false;

    struct Event {
        enum class Kind { Key, Character, MouseButton, Scroll } kind;
        int key = 0, scancode = 0, action = 0, mods = 0;   // a key's; a mouse button's in key
        unsigned int codepoint = 0;
        double x = 0.0, y = 0.0;   // a scroll's
    };
    std::vector<int> pressedSinceFrame;
    std::vector<Event> waiting;   // for the next frame
};

// The window's user pointer is `input`; callbacks chained with ImGui's backend, which must be
// initialised between the two calls.
void installInputCallbacksBeforeImGui(GLFWwindow* window, WindowInput& input);
void installInputCallbacksOverImGui(GLFWwindow* window);

// NewFrame has read the keys: a release from now on is of a key some frame has seen down.
void keysRead(GLFWwindow* window);
// After the frame (never inside one: ImGui checks that the modifiers stay as NewFrame read
// them), the events that waited reach ImGui, up to the next that must wait again.
void releaseWaitingInput(GLFWwindow* window);

}  // namespace patina::editor
