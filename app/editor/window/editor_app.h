#pragma once
#include <chrono>
#include <string>
#include <vector>

namespace patina::editor {

struct EditorOptions {
    std::vector<std::string> files;   // opened in order: material, scene or screenshot
    bool stats = false;               // log first-frame and drag frame times to stderr
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
};

// Opens the editor window (GLFW, OpenGL 3.3 core) and runs until it is closed. Returns the
// process exit code; 1 with a message when no window can be opened (no display).
int runEditor(const EditorOptions& options);

}  // namespace patina::editor
