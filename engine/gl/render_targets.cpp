#include "gl/render_targets.h"

#include <stdexcept>
#include <string>

namespace patina {

void GlImage::release() {
    if (isDepth()) {
        glDeleteRenderbuffers(1, &name);
    } else {
        glDeleteTextures(1, &name);
    }
    name = 0, width = height = 0, samples = -1, format = 0;
}

bool GlImage::ensure(int w, int h, int s, GLenum f) {
    if (name && w == width && h == height && s == samples && f == format) {
        return false;
    }
    release();
    width = w, height = h, samples = s, format = f;
    if (isDepth()) {
        glGenRenderbuffers(1, &name);
        glBindRenderbuffer(GL_RENDERBUFFER, name);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, w, h);
    } else if (samples > 0) {
        glGenTextures(1, &name);
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, name);
        glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, format, w, h, GL_TRUE);
        glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &actualSamples);
    } else {
        glGenTextures(1, &name);
        glBindTexture(GL_TEXTURE_2D, name);
        glTexImage2D(GL_TEXTURE_2D, 0, GLint(format), w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    return true;
}

void attach(GLuint framebuffer, const GlImage* linear, const GlImage* display, const GlImage* depth) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    const GlImage* colours[2] = {linear, display};
    GLenum drawBuffers[2] = {GL_NONE, GL_NONE};
    for (GLenum i = 0; i < 2; ++i) {
        glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, colours[i] ? colours[i]->name : 0, 0);
        drawBuffers[i] = colours[i] ? GL_COLOR_ATTACHMENT0 + i : GL_NONE;
    }
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth ? depth->name : 0);
    glDrawBuffers(2, drawBuffers);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        const GlImage* any = linear ? linear : display;
        throw std::runtime_error("OpenGL: render target " + std::to_string(any->width) + "x" +
                                 std::to_string(any->height) + " is incomplete");
    }
}

void detach(GLuint framebuffer) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    for (GLenum i = 0; i < 2; ++i) {
        glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, 0, 0);
    }
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
}

RenderTargets::RenderTargets() {
    for (GLuint* framebuffer : {&shadingFramebuffer, &displayFramebuffer, &readFramebuffer}) {
        glGenFramebuffers(1, framebuffer);
    }
}

RenderTargets::~RenderTargets() {
    for (GLuint* framebuffer : {&shadingFramebuffer, &displayFramebuffer, &readFramebuffer}) {
        glDeleteFramebuffers(1, framebuffer);
    }
}

void RenderTargets::prepare(int w, int h, int stripRows, int sampleCount, bool keepLinear, bool displayInPass) {
    // Bytes, as they are read back: llvmpipe converts floats to bytes in glReadPixels at
    // about 13 ns a pixel (3 ms for 512x512, 20-26 for 1920x1080), and on storing them costs
    // nothing measurable; without MSAA a frame that writes 8-bit display values is faster
    // too (docs/PERFORMANCE.md). The bytes are the same either way: both round to nearest.
    display.ensure(w, h, 0, GL_RGBA8);
    if (keepLinear) {
        linear.ensure(w, h, 0, GL_RGBA32F);
    } else {
        linear.release();
    }
    const GlImage* kept = keepLinear ? &linear : nullptr;
    if (sampleCount > 1) {
        if (samples.ensure(w, stripRows, sampleCount, GL_RGBA32F)) {
            sampleStamp = {};
        }
        // The same count as the colour got: a GL may round textures and renderbuffers apart,
        // and attachments of different counts make the framebuffer incomplete.
        depth.ensure(w, stripRows, samples.actualSamples, GL_DEPTH_COMPONENT24);
        attach(shadingFramebuffer, &samples, nullptr, &depth);
        attach(displayFramebuffer, kept, &display, nullptr);
        return;
    }
    samples.release();
    depth.ensure(w, h, 0, GL_DEPTH_COMPONENT24);
    attach(shadingFramebuffer, kept, displayInPass ? &display : nullptr, &depth);
    if (displayInPass) {
        detach(displayFramebuffer);
    } else {
        attach(displayFramebuffer, nullptr, &display, nullptr);
    }
}

bool RenderTargets::SampleStamp::advance() {
    constexpr float kLastExact = 16777216.0f;   // 2^24: a float counts exactly up to here
    const bool clear = value == 0.0f || value >= kLastExact;
    value = clear ? 1.0f : value + 1.0f;
    return clear;
}

}  // namespace patina
