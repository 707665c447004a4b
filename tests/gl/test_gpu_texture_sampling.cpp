// The GPU's texture units against the CPU twin (engine/shading/texture_sampling.h): an RGBA8
// texture uploaded in file order, sampled through shaders/shared/texture.glsl's transform at
// UVs well outside [0, 1], read back as floats and compared with sampleTexture texel by texel.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gl/program.h"
#include "shading/texture_sampling.h"
#include "test_support.h"

namespace patina {

namespace shader_sources {
extern const char* const texture_glsl;
extern const char* const fullscreen_vert;
}  // namespace shader_sources

namespace {

// Each fragment's UV spans a window larger than [0, 1] and goes through KHR_texture_transform
// in the shader, as a material's lookup will; the texture unit wraps and filters.
const char* const kSampleFragment = R"(
uniform sampler2D uTexture;
uniform vec2 uOrigin;
uniform vec2 uSpan;
uniform vec2 uTargetSize;
uniform vec2 uOffset;
uniform vec2 uScale;
uniform float uRotation;
layout(location = 0) out vec4 fragColor;
void main() {
    vec2 uv = uOrigin + gl_FragCoord.xy / uTargetSize * uSpan;
    fragColor = texture(uTexture, transformTextureCoordinate(uv, uOffset, uScale, uRotation));
}
)";

constexpr int kTextureSize = 4;
constexpr int kTargetWidth = 61, kTargetHeight = 47;   // not square: rows and columns told apart
const glm::vec2 kOrigin(-1.3f, -0.9f), kSpan(3.7f, 3.1f);

TextureTransform sampleTransform() {
    TextureTransform transform;
    transform.offset = {0.15f, -0.35f};
    transform.scale = {1.2f, 0.9f};
    transform.rotation = 0.5f;
    return transform;
}

GLint glWrap(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
        case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
        case TextureWrap::Repeat: break;
    }
    return GL_REPEAT;
}

// Rows in file order (no flip): row 0 of the bytes is t in [0, 1/4), UV v = 0 as glTF says.
GLuint uploadTexture(const std::vector<uint8_t>& rgba, GLenum internalFormat, const TextureSampler& sampler) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat), kTextureSize, kTextureSize, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 rgba.data());
    const GLint filter = sampler.nearestMagnification ? GL_NEAREST : GL_LINEAR;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);   // no mipmaps: mip 0, as the CPU
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, glWrap(sampler.wrapS));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, glWrap(sampler.wrapT));
    return texture;
}

// One fullscreen pass into an RGBA32F target; texels row by row from gl_FragCoord.y = 0.5.
std::vector<glm::vec4> drawSamples(const GlProgram& program, GLuint texture) {
    GLuint framebuffer = 0, target = 0, vertexArray = 0;
    glGenFramebuffers(1, &framebuffer);
    glGenTextures(1, &target);
    glGenVertexArrays(1, &vertexArray);
    glBindTexture(GL_TEXTURE_2D, target);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kTargetWidth, kTargetHeight, 0, GL_RGBA, GL_FLOAT, nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    glViewport(0, 0, kTargetWidth, kTargetHeight);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    program.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    glBindVertexArray(vertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<glm::vec4> pixels(size_t(kTargetWidth) * size_t(kTargetHeight));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, kTargetWidth, kTargetHeight, GL_RGBA, GL_FLOAT, pixels.data());
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteVertexArrays(1, &vertexArray);
    glDeleteTextures(1, &target);
    glDeleteFramebuffers(1, &framebuffer);
    return pixels;
}

void setUniforms(const GlProgram& program) {
    const TextureTransform transform = sampleTransform();
    program.use();
    glUniform1i(program.uniform("uTexture"), 0);
    glUniform2f(program.uniform("uOrigin"), kOrigin.x, kOrigin.y);
    glUniform2f(program.uniform("uSpan"), kSpan.x, kSpan.y);
    glUniform2f(program.uniform("uTargetSize"), float(kTargetWidth), float(kTargetHeight));
    glUniform2f(program.uniform("uOffset"), transform.offset.x, transform.offset.y);
    glUniform2f(program.uniform("uScale"), transform.scale.x, transform.scale.y);
    glUniform1f(program.uniform("uRotation"), transform.rotation);
}

struct Difference {
    float worst = 0.0f;   // the largest channel difference
    double mean = 0.0;    // of |GPU - CPU| over every channel of every sample
};

// The GPU's pixels against the CPU twin at the same UVs (the same float steps as the shader).
Difference difference(const std::vector<glm::vec4>& gpu, const LinearTexture& texture, const TextureSampler& sampler) {
    const glm::vec2 targetSize{float(kTargetWidth), float(kTargetHeight)};
    Difference result;
    for (int y = 0; y < kTargetHeight; ++y) {
        for (int x = 0; x < kTargetWidth; ++x) {
            const glm::vec2 fragCoord(float(x) + 0.5f, float(y) + 0.5f);
            const glm::vec2 uv = kOrigin + fragCoord / targetSize * kSpan;
            const glm::vec4 cpu = sampleTexture(texture, sampler, transformedUv(sampleTransform(), uv));
            const glm::vec4 d = glm::abs(gpu[size_t(y) * size_t(kTargetWidth) + size_t(x)] - cpu);
            result.worst = std::max({result.worst, d.x, d.y, d.z, d.w});
            result.mean += double(d.x + d.y + d.z + d.w);
        }
    }
    result.mean /= 4.0 * kTargetWidth * kTargetHeight;
    return result;
}

// What the GPU may differ by. Measured on llvmpipe (Mesa 22.3, LLVM 15), the worst of the 9
// wrap pairs:
// - RGBA8, NEAREST: one texel, turned to float as the CPU does: 6e-8.
// - sRGB, either filter: llvmpipe's sRGB decode is not quite the exact curve: 1.2e-3, the same
//   with NEAREST as with LINEAR, so its filtering adds no more; 2e-3 allowed.
// - RGBA8, LINEAR: llvmpipe filters 8-bit texels in fixed point (the worst results come back
//   as whole 1/255 steps) with sub-texel weights coarser than float's: 4.8e-3, 1.23 steps,
//   with no bias (mean signed difference 2e-5); two 8-bit steps allowed (2e-3
//   would not hold here).
float tolerance(bool srgb, bool nearest) {
    if (srgb) {
        return 2e-3f;
    }
    return nearest ? 1e-6f : 2.0f / 255.0f;
}

TEST(GpuTextureSampling, AgreesWithTheCpuTwinForEachWrapFilterAndFormat) {
    std::printf("%s\n", test::glContext().rendererName().c_str());
    const GlProgram program({shader_sources::fullscreen_vert}, {shader_sources::texture_glsl, kSampleFragment});
    setUniforms(program);
    std::mt19937 rng(25);
    std::uniform_int_distribution<int> byte(0, 255);
    std::vector<uint8_t> rgba(size_t(kTextureSize) * kTextureSize * 4);
    std::generate(rgba.begin(), rgba.end(), [&] { return uint8_t(byte(rng)); });
    const TextureWrap wraps[] = {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat};
    for (bool srgb : {false, true}) {
        const LinearTexture cpuTexture = linearTexture(rgba.data(), kTextureSize, kTextureSize, srgb);
        for (bool nearest : {false, true}) {
            Difference worst;
            for (TextureWrap s : wraps) {
                for (TextureWrap t : wraps) {
                    TextureSampler sampler;
                    sampler.wrapS = s;
                    sampler.wrapT = t;
                    sampler.nearestMagnification = sampler.nearestMinification = nearest;
                    sampler.mipmaps = false;
                    const GLuint texture = uploadTexture(rgba, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, sampler);
                    const Difference d = difference(drawSamples(program, texture), cpuTexture, sampler);
                    glDeleteTextures(1, &texture);
                    const std::string what = std::string(srgb ? "sRGB" : "RGBA8") + (nearest ? " nearest" : " linear") +
                                             " wrap S " + std::to_string(int(s)) + " T " + std::to_string(int(t));
                    EXPECT_LT(d.worst, tolerance(srgb, nearest)) << what;
                    // Rounding is a fraction of a step on average (llvmpipe's RGBA8 LINEAR: 0.32 steps); a shifted,
                    // flipped or wrongly wrapped image would be off by tenths.
                    EXPECT_LT(d.mean, 1.0 / 255.0) << what;
                    worst.worst = std::max(worst.worst, d.worst);
                    worst.mean = std::max(worst.mean, d.mean);
                }
            }
            std::printf("%s texture, %s filter: GPU - CPU worst %.3g, mean |difference| up to %.3g\n",
                        srgb ? "sRGB" : "RGBA8", nearest ? "nearest" : "linear", double(worst.worst), worst.mean);
        }
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace patina
