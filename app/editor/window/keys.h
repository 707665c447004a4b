#pragma once
#include <vector>

// Key codes are GLFW's (letters are their ASCII capitals). Headless tests press the same.
namespace patina::editor {
constexpr int kKeyF = 'F';
constexpr int kKeyN = 'N';
constexpr int kKeyO = 'O';
constexpr int kKeyQ = 'Q';
constexpr int kKeyS = 'S';
constexpr int kKeyY = 'Y';
constexpr int kKeyZ = 'Z';
constexpr int kKeyEscape = 256;   // GLFW_KEY_ESCAPE
constexpr int kKeyDelete = 261;   // GLFW_KEY_DELETE
constexpr int kKeyF1 = 290;    // GLFW_KEY_F1
constexpr int kKeyF12 = 301;   // GLFW_KEY_F12

// One key press (or auto-repeat) with its modifiers. ImGui 1.86 keeps only "is it down now",
// so a press and release that arrive in one event batch (fast typing, xdotool) would be lost;
// the app queues presses from GLFW's key callback instead, and shortcuts read this queue.
struct KeyPress {
    int key;
    bool ctrl = false;
    bool shift = false;
    bool alt = false;
};
using KeyPresses = std::vector<KeyPress>;

inline bool pressed(const KeyPresses& presses, int key, bool ctrl = false, bool shift = false, bool alt = false) {
    for (const KeyPress& press : presses) {
        if (press.key == key && press.ctrl == ctrl && press.shift == shift && press.alt == alt) {
            return true;
        }
    }
    return false;
}

}  // namespace patina::editor
