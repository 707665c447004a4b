#include "gl/gpu_probe.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <epoxy/gl.h>

#include "scene/light_packing.h"
#include "gl/environment_texture.h"
#include "gl/program.h"
#include "gl/shading_inputs.h"
#include "gl/shader_specialisation.h"
#include "gl/shading_programs.h"

namespace patina {


namespace {
constexpr int kTargetWidth = 1024;
constexpr size_t kBatch = size_t(kTargetWidth) * 1024;   // probes per draw
}  // namespace

struct GpuProbe::State {
    ShadingPrograms programs;
    EnvironmentTexture environment;
    LightBuffer lights;
    GLuint vertexArray = 0, vertices = 0, framebuffer = 0, target = 0;
};

GpuProbe::GpuProbe() : state_(std::make_unique<State>()) {
    State& s = *state_;
    glGenVertexArrays(1, &s.vertexArray);
    glGenBuffers(1, &s.vertices);
    glBindVertexArray(s.vertexArray);
    glBindBuffer(GL_ARRAY_BUFFER, s.vertices);
    for (GLuint attribute = 0; attribute < 3; ++attribute) {
        glEnableVertexAttribArray(attribute);
        glVertexAttribPointer(attribute, 3, GL_FLOAT, GL_FALSE, sizeof(ProbeSample),
                              reinterpret_cast<const void*>(attribute * sizeof(glm::vec3)));
    }
    glBindVertexArray(0);
    glGenFramebuffers(1, &s.framebuffer);
    glGenTextures(1, &s.target);
}

GpuProbe::~GpuProbe() {
    State& s = *state_;
    glDeleteTextures(1, &s.target);
    glDeleteFramebuffers(1, &s.framebuffer);
    glDeleteBuffers(1, &s.vertices);
    glDeleteVertexArrays(1, &s.vertexArray);
}

std::vector<glm::vec3> GpuProbe::evaluate(const Material& material, const std::vector<Light>& lights,
                                          const std::vector<ProbeSample>& samples,
                                          const std::shared_ptr<const Environment>& environment) {
    static_assert(sizeof(ProbeSample) == 9 * sizeof(float), "ProbeSample is uploaded as is");
    State& s = *state_;
    const Light* environmentLight = enabledEnvironment(lights);
    const std::shared_ptr<const Environment> shown =
        environmentLight ? environmentShown(environment, environmentLight->source) : nullptr;
    s.lights.upload(packEnabledLights(lights));
    s.lights.bind();
    // The probe draws the base alone, with its stretch (PATINA_ANISOTROPY, turned from the
    // fallback direction: a probe has no tangent), its specular tint and weight (PATINA_SPECULAR)
    // and its thin film (PATINA_IRIDESCENCE), as probeOnCpu shades it.
    const ShadingPrograms::Surface surface =
        ShadingPrograms::surfaceOf(false, false, false, false, false, hasAnisotropy(material), false,
                                   hasSpecularTint(material), hasIridescence(material));
    const GlProgram& program = s.programs.use(material.model, ShadingPrograms::Use::Probe,
                                              ShadingPrograms::Output::Linear, environmentLight, surface);
    setMaterialUniforms(program, material);
    if (environmentLight) {
        s.environment.bind(shown, ShadingPrograms::kEnvironmentMapUnit, ShadingPrograms::kEnvironmentIrradianceUnit);
        setEnvironmentUniforms(program, *shown, *environmentLight, ShadingPrograms::kEnvironmentMapUnit);
    }

    std::vector<glm::vec3> radiance;
    radiance.reserve(samples.size());
    std::vector<float> rgba;
    for (size_t first = 0; first < samples.size(); first += kBatch) {
        const size_t count = std::min(kBatch, samples.size() - first);
        const int width = int(std::min<size_t>(count, kTargetWidth));
        const int height = int((count + kTargetWidth - 1) / kTargetWidth);

        glBindTexture(GL_TEXTURE_2D, s.target);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        glBindFramebuffer(GL_FRAMEBUFFER, s.framebuffer);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, s.target, 0);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            throw std::runtime_error("OpenGL: probe target is incomplete");
        }
        glViewport(0, 0, width, height);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        glUniform2i(program.uniform("uTargetSize"), width, height);

        glBindBuffer(GL_ARRAY_BUFFER, s.vertices);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(count * sizeof(ProbeSample)), &samples[first],
                     GL_STREAM_DRAW);
        glBindVertexArray(s.vertexArray);
        glDrawArrays(GL_POINTS, 0, GLsizei(count));
        glBindVertexArray(0);

        rgba.resize(size_t(width) * height * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
        for (size_t i = 0; i < count; ++i) {
            radiance.emplace_back(rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2]);
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        throw std::runtime_error("OpenGL error " + std::to_string(error) + " while probing");
    }
    return radiance;
}

}  // namespace patina
