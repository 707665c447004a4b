#include "window/editor_app.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <thread>
#include <utility>

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "gl/gpu_prefilter.h"
#include "files/file_bytes.h"
#include "storage/editor_settings.h"
#include "views/frame_stats.h"
#include "window/panel_guard.h"
#include "panels/panels.h"
#include "window/ui_scale.h"
#include "window/widgets.h"
#include "window/window_input.h"

#ifndef PATINA_PRESETS_DIR
#define PATINA_PRESETS_DIR "presets"
#endif

namespace patina::editor {

namespace {
// After input, ImGui needs a couple of frames to settle (hover, popups): draw this many more,
// then sleep in glfwWaitEvents until the next event.
constexpr int kFramesAfterInput = 3;

std::optional<std::chrono::milliseconds> earliest(std::optional<std::chrono::milliseconds> a,
                                                  std::optional<std::chrono::milliseconds> b) {
    return a && b ? std::min(*a, *b) : a ? a : b;
}

// The window, sized for the monitor it opens on (a laptop's 1366 x 768 holds the default window
// whole), with its GL context current; null, said on stderr, when it cannot be made.
GLFWwindow* openWindow(WindowGeometry& geometry) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        int x = 0, y = 0, workWidth = 0, workHeight = 0;
        float scaleX = 1.0f, scaleY = 1.0f;
        glfwGetMonitorWorkarea(monitor, &x, &y, &workWidth, &workHeight);
        glfwGetMonitorContentScale(monitor, &scaleX, &scaleY);
        geometry = windowSizeFor(geometry, workWidth, workHeight, scaleX);
    } else {
        geometry = windowSizeFor(geometry, 0, 0, 1.0f);
    }
    GLFWwindow* window = glfwCreateWindow(geometry.width, geometry.height, "Patina", nullptr, nullptr);
    if (!window) {
        std::cerr << "error: cannot create an OpenGL 3.3 window\n";
        return nullptr;
    }
    glfwMakeContextCurrent(window);
    return window;
}

void startImGui(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;   // panel sizes persist in settings.json instead
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
}

void stopImGui() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

// What the status line says, which a frame drawn after the change must show: the messages, and
// the PBR count the viewport sets after the menu bar has drawn the last one.
std::string shownText(const Prompts& prompts, const EditorServices& services) {
    std::string text = prompts.status + '\n' + prompts.error;
    if (services.pbrTally) {
        text += '\n' + std::to_string(services.pbrTally->flagged()) + '/' + std::to_string(services.pbrTally->texels);
    }
    return text;
}

// What the loop carries from one frame to the next.
struct Loop {
    GLFWwindow* window;
    WindowInput& input;
    EditorState& state;
    EditorServices& services;
    WindowGeometry& geometry;
    SettingsWriter settingsWriter;
    FrameStats stats;
    const char* layoutDump = std::getenv("PATINA_UI_LAYOUT");
    // Automation's aid too: every frame this much slower, as a heavy model on a software
    // rasteriser makes it (the window tests check that no key is lost then).
    const int frameDelayMs = std::clamp(std::atoi(std::getenv("PATINA_FRAME_DELAY_MS") ? std::getenv("PATINA_FRAME_DELAY_MS") : "0"), 0, 2000);
    std::string title{};   // the window's, as last set
    int framesLeft = kFramesAfterInput;
    float appliedScale = 0.0f;   // none yet
    std::optional<std::chrono::milliseconds> autosaveDue{}, settingsDue{};
    std::string shownMessages = shownText(state, services);
};

// A few frames after input (every frame while the turntable turns), then asleep until input, or
// until a change waiting to be written is due.
void waitForEvents(Loop& loop) {
    if (loop.framesLeft > 0) {
        glfwPollEvents();
        // A click that came as the last of them was drawn used to get its press frame only: the
        // loop then slept, its release unseen until the next input (a menu item stayed held,
        // and the next click landed where the closed menu had been).
        if (std::exchange(loop.input.arrived, false)) {
            loop.framesLeft = kFramesAfterInput;
        }
        return;
    }
    const std::optional<std::chrono::milliseconds> due = earliest(loop.autosaveDue, loop.settingsDue);
    if (loop.state.environmentLoad || loop.state.modelLoad || loop.state.occlusionBake) {
        glfwWaitEventsTimeout(0.1);   // the load's (or bake's) progress, and its end, are shown
    } else if (due) {
        glfwWaitEventsTimeout(std::chrono::duration<double>(*due).count() + 0.01);
    } else {
        glfwWaitEvents();
    }
    loop.input.arrived = false;
    loop.framesLeft = kFramesAfterInput;
}

// The window's close button, dropped files and keys, handed to the editor.
void takeInput(Loop& loop) {
    EditorState& state = loop.state;
    if (glfwWindowShouldClose(loop.window)) {
        glfwSetWindowShouldClose(loop.window, GLFW_FALSE);
        state.pendingQuit = true;
    }
    // A file dropped while a prompt is up waits for it: nothing edits the document behind one.
    std::vector<std::filesystem::path>& dropped = loop.input.droppedFiles;
    while (!dropped.empty() && !promptOpen(state, state)) {
        requestOpen(state, dropped.front());
        dropped.erase(dropped.begin());
    }
    loop.services.keyPresses.swap(loop.input.keyPresses);
    loop.input.keyPresses.clear();
}

// The UI's scale follows the monitor the window is on and the View menu's setting; the font
// atlas is rebuilt between frames when it changes.
void followUiScale(Loop& loop) {
    float contentScale = 1.0f, unused = 1.0f;
    glfwGetWindowContentScale(loop.window, &contentScale, &unused);
    const float scale = uiScaleFor(contentScale, loop.state.uiScaleSetting);
    if (scale == loop.appliedScale) {
        return;
    }
    if (const std::string message = applyUiScale(scale); !message.empty()) {
        loop.state.status = message;
    }
    if (loop.appliedScale > 0.0f) {   // the first frame's NewFrame makes the texture
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }
    loop.appliedScale = scale;
}

void drawFrame(Loop& loop) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    keysRead(loop.window);
    // Each panel catches its own errors (drawGuarded); this is the last resort for anything
    // between them, with ImGui's stacks closed so the frame still ends cleanly.
    try {
        drawEditorFrame(loop.state, loop.services);
    } catch (const std::exception& error) {
        recoverFrame();
        loop.state.error = error.what();
    }
    ImGui::Render();
    releaseWaitingInput(loop.window);
    int width = 0, height = 0;
    glfwGetFramebufferSize(loop.window, &width, &height);
    glViewport(0, 0, width, height);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(loop.window);
}

// A window that opened in this frame is measured hidden and placed in the next (a centred
// prompt has no size yet): draw that frame, or a prompt that comes as the loop goes to sleep
// stays hidden, or where a click on it misses, until the next input.
bool windowsSettling() {
    for (const ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
        if (window->Active && (window->Appearing || window->HiddenFramesCannotSkipItems > 0 ||
                               window->HiddenFramesCanSkipItems > 0)) {
            return true;
        }
    }
    return false;
}

// Through a temporary file and a rename: a reader never sees half a dump.
void dumpLayout(const char* path, bool asleep) {
    const std::string json = layoutJson(asleep);
    try {
        writeFileAtomic(path, std::vector<uint8_t>(json.begin(), json.end()));
    } catch (const std::exception&) {
        // Automation's aid only: a dump that cannot be written is no reason to stop.
    }
}

// The title, the layout dump, and what is written when due: the autosave and the settings.
void afterFrame(Loop& loop) {
    EditorState& state = loop.state;
    if (const std::string wanted = windowTitle(state); wanted != loop.title) {
        glfwSetWindowTitle(loop.window, wanted.c_str());
        loop.title = wanted;
    }
    loop.autosaveDue = updateAutosave(state, state.autosave, state, AutosaveClock::now());
    glfwGetWindowSize(loop.window, &loop.geometry.width, &loop.geometry.height);
    loop.settingsDue = loop.settingsWriter.update(state, state, state, loop.geometry, SettingsWriter::Clock::now());
    // A message set during this frame (a failed screenshot, an autosave error) is drawn now,
    // not when the next input happens to wake the loop.
    if (std::string messages = shownText(state, loop.services); messages != loop.shownMessages) {
        loop.shownMessages = std::move(messages);
        loop.framesLeft = std::max(loop.framesLeft, kFramesAfterInput);
    }
    // A window settling, or the turntable turning: the next frame is drawn without waiting.
    if (windowsSettling() || state.turntable.on) {
        loop.framesLeft = std::max(loop.framesLeft, 1);
    }
    if (loop.layoutDump) {
        dumpLayout(loop.layoutDump, loop.framesLeft <= 0);
    }
}

// The session from the command line's files to a confirmed quit.
void runSession(Loop& loop) {
    while (!loop.state.quitConfirmed) {
        waitForEvents(loop);
        const FrameStats::Clock::time_point frameStart = FrameStats::Clock::now();
        --loop.framesLeft;
        takeInput(loop);
        followUiScale(loop);
        drawFrame(loop);
        if (loop.frameDelayMs > 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(loop.frameDelayMs));
        }
        loop.stats.frameDone(
            std::chrono::duration<double, std::milli>(FrameStats::Clock::now() - frameStart).count(),
            ImGui::IsAnyItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left));
        afterFrame(loop);
    }
}
}  // namespace

int runEditor(const EditorOptions& options) {
    if (!glfwInit()) {
        std::cerr << "error: cannot open a window (no display?). The command line works without one: "
                     "patina --help\n";
        return 1;
    }
    EditorState state;
    WindowGeometry geometry;
    const std::filesystem::path settingsFile = configFolder() / "settings.json";
    loadSettings(state, state, state, geometry, settingsFile);
    state.userPresetFolder = configFolder() / "presets";
    state.presetFolders = {PATINA_PRESETS_DIR, state.userPresetFolder};
    GLFWwindow* window = openWindow(geometry);
    if (!window) {
        glfwTerminate();
        return 1;
    }
    // Environments made ready on this (the UI) thread, as a scene opens, prefilter on the GPU;
    // files chosen in the light list are prepared on a worker, on the CPU, while this draws.
    state.uiPrefilter = prefilterCubeOnGpu;
    glfwSwapInterval(1);
    WindowInput input;
    installInputCallbacksBeforeImGui(window, input);
    startImGui(window);
    installInputCallbacksOverImGui(window);
    {
        EditorServices services(state.assets);
        openStartupFiles(state, std::vector<std::filesystem::path>(options.files.begin(), options.files.end()));
        startAutosave(state, state, state, configFolder() / "autosave");
        Loop loop{window, input, state, services, geometry, SettingsWriter(state, geometry, settingsFile),
                  FrameStats(options.stats ? &std::cerr : nullptr, options.start)};
        runSession(loop);
        removeAutosave(state.autosave);   // a clean quit: nothing to recover
        loop.stats.finish();
        if (!saveSettings(state, state, state, geometry, settingsFile)) {
            std::cerr << "warning: " << state.error << "\n";
        }
    }
    stopImGui();
    glfwDestroyWindow(window);
    glfwTerminate();
    return 0;
}

}  // namespace patina::editor
