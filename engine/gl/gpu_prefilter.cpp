#include "gl/gpu_prefilter.h"

#include <epoxy/gl.h>

#include "gl/environment_texture.h"
#include "gl/program.h"
#include "shading/shading.h"

namespace patina {

namespace shader_sources {
extern const char* const brdf_glsl;
extern const char* const environment_glsl;
extern const char* const ibl_glsl;
extern const char* const fullscreen_vert;
extern const char* const prefilter_frag;
}  // namespace shader_sources

CubeChain prefilterCubeOnGpu(const CubeChain& source, const PrefilterSettings& settings, const Progress& progress) {
    const int levels = prefilterLevelCount(source.front().size, settings);
    const float maxLod = float(levels - 1);
    CubeChain chain;
    chain.push_back(source.front());
    const GlProgram program({shader_sources::fullscreen_vert},
                            {shader_sources::brdf_glsl, shader_sources::environment_glsl, shader_sources::ibl_glsl,
                             shader_sources::prefilter_frag});
    program.use();
    glActiveTexture(GL_TEXTURE0);
    const unsigned sourceTexture = uploadCubeChain(source);
    glUniform1i(program.uniform("uEnvironmentSource"), 0);
    glUniform1f(program.uniform("uEnvironmentSourceSize"), float(source.front().size));
    glUniform1i(program.uniform("uSamples"), int(settings.samples));
    GLuint framebuffer = 0, target = 0, vertexArray = 0;
    glGenFramebuffers(1, &framebuffer);
    glGenTextures(1, &target);
    glGenVertexArrays(1, &vertexArray);
    glBindVertexArray(vertexArray);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    bool stopped = false;
    const int faces = 6 * (levels - 1);
    for (int level = 1; level < levels && !stopped; ++level) {
        CubeLevel& out = chain.emplace_back(source.front().size >> level);
        glBindTexture(GL_TEXTURE_2D, target);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, out.size, out.size, 0, GL_RGBA, GL_FLOAT, nullptr);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
        glViewport(0, 0, out.size, out.size);
        glUniform1f(program.uniform("uLevelSize"), float(out.size));
        glUniform1f(program.uniform("uRoughness"), shader::lodToRoughness(float(level), maxLod));
        for (int face = 0; face < 6 && !stopped; ++face) {
            glUniform1i(program.uniform("uFace"), face);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glPixelStorei(GL_PACK_ALIGNMENT, 4);
            glReadPixels(0, 0, out.size, out.size, GL_RGB, GL_FLOAT, out.faces[size_t(face)].data());
            const int done = 6 * (level - 1) + face + 1;
            stopped = progress && !progress(float(done) / float(faces));
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vertexArray);
    glDeleteTextures(1, &target);
    glDeleteTextures(1, &sourceTexture);
    glDeleteFramebuffers(1, &framebuffer);
    if (stopped) {
        return {};
    }
    return chain;
}

}  // namespace patina
