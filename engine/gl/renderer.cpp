#include "renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <epoxy/gl.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "../enum_names.h"
#include "../light_packing.h"
#include "mesh_buffers.h"
#include "program.h"
#include "shading_inputs.h"
#include "shading_programs.h"

namespace patina {

namespace shader_sources {
extern const char* const mesh_vert;
extern const char* const black_frag;
extern const char* const fullscreen_vert;
extern const char* const display_glsl;
extern const char* const display_frag;
}  // namespace shader_sources

std::string_view passModeName(PassMode mode) {
    switch (mode) {
    case PassMode::Single: return "single";
    case PassMode::Multi: return "multi";
    case PassMode::Specialised: return "specialised";
    case PassMode::BrdfFloor: return "brdf-floor";
    }
    return "single";
}

std::optional<PassMode> passModeFromName(std::string_view name) {
    static const PassMode all[] = {PassMode::Single, PassMode::Multi, PassMode::Specialised};
    return enumFromName(name, all, passModeName);
}

glm::mat4 viewProjection(const Camera& camera, float aspect) {
    const glm::vec3 forward = camera.target - camera.position;
    const float distance = glm::length(forward);
    // Looking straight up or down, +y cannot be the up vector.
    const glm::vec3 unitForward = forward / distance;
    const glm::vec3 up = std::abs(unitForward.y) > 0.999f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    const float nearPlane = std::max(1e-3f, distance * 0.01f);
    const float farPlane = distance * 10.0f + 10.0f;
    return glm::perspective(glm::radians(camera.fovYDegrees), aspect, nearPlane, farPlane) *
           glm::lookAt(camera.position, camera.target, up);
}

namespace {
// A framebuffer with one colour attachment (texture or multisampled renderbuffer) and an
// optional depth renderbuffer, rebuilt when size or format changes.
struct RenderTarget {
    GLuint framebuffer = 0, color = 0, depth = 0;
    int width = 0, height = 0, samples = -1;
    GLenum format = 0;

    ~RenderTarget() { release(); }

    void release() {
        glDeleteFramebuffers(1, &framebuffer);
        if (samples > 0) {
            glDeleteRenderbuffers(1, &color);
        } else {
            glDeleteTextures(1, &color);
        }
        glDeleteRenderbuffers(1, &depth);
        framebuffer = color = depth = 0;
    }

    void ensure(int w, int h, int s, GLenum f, bool withDepth) {
        if (framebuffer && w == width && h == height && s == samples && f == format) {
            return;
        }
        release();
        width = w, height = h, samples = s, format = f;
        glGenFramebuffers(1, &framebuffer);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        if (samples > 0) {
            glGenRenderbuffers(1, &color);
            glBindRenderbuffer(GL_RENDERBUFFER, color);
            glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, w, h);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
        } else {
            glGenTextures(1, &color);
            glBindTexture(GL_TEXTURE_2D, color);
            glTexImage2D(GL_TEXTURE_2D, 0, GLint(format), w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
        }
        if (withDepth) {
            glGenRenderbuffers(1, &depth);
            glBindRenderbuffer(GL_RENDERBUFFER, depth);
            glRenderbufferStorageMultisample(GL_RENDERBUFFER, std::max(samples, 0),
                                             GL_DEPTH_COMPONENT24, w, h);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
        }
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            throw std::runtime_error("OpenGL: render target " + std::to_string(w) + "x" +
                                     std::to_string(h) + " is incomplete");
        }
    }
};

// One render's chain: multisampled float -> resolved float -> display bytes.
struct Targets {
    RenderTarget shading, resolved, displayed;
};

template <typename T>
void flipRows(std::vector<T>& values, size_t rowLength, int rows) {
    for (int y = 0; y < rows / 2; ++y) {
        std::swap_ranges(values.begin() + std::ptrdiff_t(size_t(y) * rowLength),
                         values.begin() + std::ptrdiff_t(size_t(y + 1) * rowLength),
                         values.begin() + std::ptrdiff_t(size_t(rows - 1 - y) * rowLength));
    }
}

int toneMapIndex(Tonemap tonemap) {
    switch (tonemap) {
    case Tonemap::Aces: return shader::TONEMAP_ACES;
    case Tonemap::Reinhard: return shader::TONEMAP_REINHARD;
    case Tonemap::None: break;
    }
    return shader::TONEMAP_NONE;
}
}  // namespace

struct Renderer::State {
    ShadingPrograms shading;
    GlProgram depthPrepass{{shader_sources::mesh_vert}, {shader_sources::black_frag}};
    GlProgram display{{shader_sources::fullscreen_vert},
                      {shader_sources::display_glsl, shader_sources::display_frag}};
    LightBuffer lights;
    MeshBuffers mesh;
    GLuint emptyVertexArray = 0;
    std::array<Targets, kSlots> targets;
    GLuint timerQuery = 0;
    bool timerPending = false;
    double gpuMilliseconds = -1.0;
    int maxSamples = 0, maxSize = 0;
};

Renderer::Renderer() : state_(std::make_unique<State>()) {
    glGenVertexArrays(1, &state_->emptyVertexArray);
    glGenQueries(1, &state_->timerQuery);
    glGetIntegerv(GL_MAX_SAMPLES, &state_->maxSamples);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &state_->maxSize);
    setMesh(makeUvSphere());
}

Renderer::~Renderer() {
    glDeleteQueries(1, &state_->timerQuery);
    glDeleteVertexArrays(1, &state_->emptyVertexArray);
}

double Renderer::lastGpuMilliseconds() {
    State& s = *state_;
    if (s.timerPending) {
        GLint available = 0;
        glGetQueryObjectiv(s.timerQuery, GL_QUERY_RESULT_AVAILABLE, &available);
        if (available) {
            GLuint64 nanoseconds = 0;
            glGetQueryObjectui64v(s.timerQuery, GL_QUERY_RESULT, &nanoseconds);
            s.gpuMilliseconds = double(nanoseconds) * 1e-6;
            s.timerPending = false;
        }
    }
    return s.gpuMilliseconds;
}

void Renderer::setMesh(const Mesh& mesh) {
    state_->mesh.upload(mesh);
}

void Renderer::drawPasses(State& s, PassMode passes, const GlProgram& shading, size_t lights,
                          const Prepare& prepare) {
    if (passes != PassMode::Multi) {
        shading.use();
        prepare(shading);
        s.mesh.draw();
        return;
    }
    s.depthPrepass.use();
    prepare(s.depthPrepass);
    s.mesh.draw();
    // Light passes add onto the black mesh where depth matches the pre-pass exactly
    // (mesh.vert's gl_Position is invariant).
    shading.use();
    prepare(shading);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    for (size_t i = 0; i < lights; ++i) {
        glUniform1i(shading.uniform("uLightIndex"), GLint(i));
        s.mesh.draw();
    }
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

unsigned Renderer::draw(const Scene& scene, const RenderSettings& settings, int slot) {
    State& s = *state_;
    if (settings.width < 1 || settings.height < 1 || settings.width > s.maxSize ||
        settings.height > s.maxSize) {
        throw std::invalid_argument("image size " + std::to_string(settings.width) + "x" +
                                    std::to_string(settings.height) + " is outside 1.." +
                                    std::to_string(s.maxSize));
    }
    if (slot < 0 || slot >= kSlots) {
        throw std::invalid_argument("render slot " + std::to_string(slot) + " does not exist");
    }
    Targets& t = s.targets[size_t(slot)];
    const int w = settings.width, h = settings.height;
    const int samples = std::clamp(settings.samples, 0, s.maxSamples);
    const std::vector<shader::PackedLight> packed = packEnabledLights(scene.lights);
    s.lights.upload(packed);
    s.lights.bind();

    // Everything that can throw (targets the GL cannot make, a shader that does not compile)
    // comes before the timer query starts, so a failed draw leaves no state behind.
    const size_t bytesPerRow = size_t(w) * size_t(std::max(samples, 1)) * 4 * sizeof(float);
    // Strips as the budget allows, but never more than kMaxStrips: each draws the whole mesh.
    constexpr int kMaxStrips = 16;
    const int stripRows =
        settings.maxTargetBytes == 0
            ? h
            : std::max(int(std::clamp<size_t>(settings.maxTargetBytes / bytesPerRow, 1, size_t(h))),
                       (h + kMaxStrips - 1) / kMaxStrips);
    t.shading.ensure(w, stripRows, samples > 1 ? samples : 0, GL_RGBA32F, true);
    t.resolved.ensure(w, h, 0, GL_RGBA32F, false);
    t.displayed.ensure(w, h, 0, GL_RGBA8, false);
    const BrdfModelId model = scene.material.model;
    const GlProgram& shading =
        settings.passes == PassMode::Single  ? s.shading.use(model, ShadingPrograms::Use::SinglePass)
        : settings.passes == PassMode::Multi ? s.shading.use(model, ShadingPrograms::Use::MultiPass)
        : s.shading.useSpecialised(model, settings.passes == PassMode::Specialised
                                              ? specialiseFor(packed, scene.material)
                                              : brdfFloorFor(packed.size()));

    // One query in flight: a draw while the last is unread goes untimed.
    lastGpuMilliseconds();
    const bool timed = !s.timerPending;
    if (timed) {
        glBeginQuery(GL_TIME_ELAPSED, s.timerQuery);
    }
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glClearColor(scene.display.background.r, scene.display.background.g,
                 scene.display.background.b, 1.0f);
    glClearDepth(1.0);

    const glm::mat4 transform = viewProjection(scene.camera, float(w) / float(h));
    auto prepare = [&](const GlProgram& program) {
        glUniformMatrix4fv(program.uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(transform));
        glUniform3fv(program.uniform("uCameraPosition"), 1, glm::value_ptr(scene.camera.position));
        setMaterialUniforms(program, scene.material);
    };
    for (int top = 0; top < h; top += stripRows) {
        const int rows = std::min(stripRows, h - top);
        glBindFramebuffer(GL_FRAMEBUFFER, t.shading.framebuffer);
        // The whole image's viewport, moved down so rows [top, top + rows) land in the strip.
        glViewport(0, -top, w, h);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        drawPasses(s, settings.passes, shading, packed.size(), prepare);
        // Resolve MSAA into the float texture: the HDR result and the display pass's input.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, t.shading.framebuffer);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.resolved.framebuffer);
        glBlitFramebuffer(0, 0, w, rows, 0, top, w, top + rows, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glViewport(0, 0, w, h);

    glBindFramebuffer(GL_FRAMEBUFFER, t.displayed.framebuffer);
    glDisable(GL_DEPTH_TEST);
    s.display.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, t.resolved.color);
    glUniform1i(s.display.uniform("uHdr"), 0);
    glUniform1f(s.display.uniform("uExposure"), scene.display.exposure);
    glUniform1i(s.display.uniform("uTonemap"), toneMapIndex(scene.display.tonemap));
    glBindVertexArray(s.emptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (timed) {
        glEndQuery(GL_TIME_ELAPSED);
        s.timerPending = true;
    }
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        throw std::runtime_error("OpenGL error " + std::to_string(error) + " while rendering");
    }
    return t.displayed.color;
}

RenderOutput Renderer::readBack(int slot, bool hdr) const {
    const Targets& t = state_->targets.at(size_t(slot));
    const int w = t.resolved.width, h = t.resolved.height;
    RenderOutput output;
    // Straight into the outputs (no staging copies: a render's peak memory counts), then the
    // rows flipped in place, since GL's go bottom to top.
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (hdr) {
        output.hdr = {w, h, std::vector<float>(size_t(w) * h * 3)};
        glBindFramebuffer(GL_FRAMEBUFFER, t.resolved.framebuffer);
        glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, output.hdr.rgb.data());
        flipRows(output.hdr.rgb, size_t(w) * 3, h);
    }
    output.ldr = {w, h, std::vector<uint8_t>(size_t(w) * h * 4)};
    glBindFramebuffer(GL_FRAMEBUFFER, t.displayed.framebuffer);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, output.ldr.rgba.data());
    flipRows(output.ldr.rgba, size_t(w) * 4, h);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return output;
}

double Renderer::timedDraw(const Scene& scene, const RenderSettings& settings) {
    glFinish();
    lastGpuMilliseconds();   // collect a pending query so this draw is timed
    draw(scene, settings, 0);
    glFinish();
    return lastGpuMilliseconds();
}

RenderOutput Renderer::render(const Scene& scene, const RenderSettings& settings) {
    draw(scene, settings, 0);
    return readBack(0, settings.readHdr);
}

}  // namespace patina
