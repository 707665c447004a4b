#pragma once
#include <memory>
#include <string>

namespace patina {

// An OpenGL 3.3 core context with no window and no X server: EGL's surfaceless platform
// (EGL_MESA_platform_surfaceless), as Mesa's llvmpipe offers. Rendering goes to FBOs.
class HeadlessContext {
public:
    // Throws std::runtime_error saying which EGL step failed.
    HeadlessContext();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    void makeCurrent();
    std::string rendererName() const;   // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace patina
