#include "gl/headless_context.h"


#include <stdexcept>
#include <string_view>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

namespace patina {

struct HeadlessContext::State {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

namespace {
[[noreturn]] void eglFail(const char* step) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", unsigned(eglGetError()));
    throw std::runtime_error(std::string("headless OpenGL: ") + step + " failed (EGL error " +
                             code + ")");
}

bool hasExtension(const char* list, std::string_view name) {
    std::string_view all = list ? list : "";
    size_t start = 0;
    while (start < all.size()) {
        const size_t end = std::min(all.find(' ', start), all.size());
        if (all.substr(start, end - start) == name) {
            return true;
        }
        start = end + 1;
    }
    return false;
}
}  // namespace

HeadlessContext::HeadlessContext() : state_(std::make_unique<State>()) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        throw std::runtime_error(
            "headless OpenGL: EGL_MESA_platform_surfaceless is missing (install libegl-mesa0)");
    }
    state_->display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                               nullptr);
    if (state_->display == EGL_NO_DISPLAY) {
        eglFail("eglGetPlatformDisplayEXT(surfaceless)");
    }
    if (!eglInitialize(state_->display, nullptr, nullptr)) {
        eglFail("eglInitialize");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglFail("eglBindAPI(OpenGL)");
    }
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    // No surface is ever made, so any config that renders OpenGL serves.
    if (!eglChooseConfig(state_->display, configAttributes, &config, 1, &configCount) ||
        configCount == 0) {
        config = nullptr;   // EGL_KHR_no_config_context
    }
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3,
                                        EGL_CONTEXT_MINOR_VERSION, 3,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_NONE};
    state_->context = eglCreateContext(state_->display, config, EGL_NO_CONTEXT, contextAttributes);
    if (state_->context == EGL_NO_CONTEXT) {
        eglFail("eglCreateContext(OpenGL 3.3 core)");
    }
    makeCurrent();
}

HeadlessContext::~HeadlessContext() {
    if (state_->display != EGL_NO_DISPLAY) {
        eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (state_->context != EGL_NO_CONTEXT) {
            eglDestroyContext(state_->display, state_->context);
        }
        eglTerminate(state_->display);
    }
}

void HeadlessContext::makeCurrent() {
    if (!eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, state_->context)) {
        eglFail("eglMakeCurrent(surfaceless)");
    }
}

std::string HeadlessContext::rendererName() const {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name ? name : "unknown";
}

}  // namespace patina
