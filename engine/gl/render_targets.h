#pragma once
// The images and framebuffers one renderer slot draws into (engine/gl/renderer.cpp).
#include <epoxy/gl.h>

namespace patina {

// A colour texture (multisampled when samples > 0) or a depth renderbuffer
// (GL_DEPTH_COMPONENT24), remade when its size, samples or format change.
struct GlImage {
    GLuint name = 0;
    int width = 0, height = 0, samples = -1;
    GLenum format = 0;
    int actualSamples = 0;   // what the GL made of `samples` (it may round up)

    GlImage() = default;
    ~GlImage() { release(); }
    GlImage(const GlImage&) = delete;
    GlImage& operator=(const GlImage&) = delete;

    bool isDepth() const { return format == GL_DEPTH_COMPONENT24; }
    void release();
    // True when it made a new image (whose contents are undefined).
    bool ensure(int w, int h, int s, GLenum f);
};

// Colour attachment 0 takes linear radiance and 1 display values, in every pass that writes
// them (shade.frag, display.frag); nullptr leaves one out. Throws std::runtime_error when the
// framebuffer is incomplete.
void attach(GLuint framebuffer, const GlImage* linear, const GlImage* display, const GlImage* depth);
// Lets go of a framebuffer's images: deleting a texture detaches it only from the bound
// framebuffer, so one left attached elsewhere would keep its memory.
void detach(GLuint framebuffer);

// One slot's images. With MSAA: a strip of samples -> (display pass: resolve and display
// transform) -> display, and linear when kept. Without: the shading pass draws straight into
// the full-size images, and writes display values itself except for the multi path's sum.
struct RenderTargets {
    GlImage samples;   // multisampled linear radiance, alpha the strip's stamp (MSAA only)
    GlImage depth;     // the shading pass's (multisampled with MSAA, one strip tall)
    GlImage linear;    // the linear image, when kept
    GlImage display;   // display-referred sRGB values, RGBA8: reading back is a copy
    GLuint shadingFramebuffer = 0, displayFramebuffer = 0, readFramebuffer = 0;
    bool drawn = false;       // the last draw finished: there is an image to read back
    bool hasLinear = false;
    // With MSAA the shading passes write a stamp into the samples' alpha, new for each strip,
    // and the resolve takes a sample with another stamp for background: the samples are not
    // cleared for each strip (on llvmpipe the clear of 4 float samples a pixel cost a few
    // percent of a 512x512 frame).
    struct SampleStamp {
        float value = 0.0f;   // the last strip's; 0: none since the samples were made
        // To the next strip's stamp. True when the samples must first be cleared to stamp 0:
        // just made (contents undefined), or past the last count a float holds exactly.
        bool advance();
    };
    SampleStamp sampleStamp;

    RenderTargets();
    ~RenderTargets();
    RenderTargets(const RenderTargets&) = delete;
    RenderTargets& operator=(const RenderTargets&) = delete;

    // Makes and attaches the images a draw of w x h needs (sampleCount > 1: MSAA, in strips of
    // `stripRows`), releasing those it does not.
    void prepare(int w, int h, int stripRows, int sampleCount, bool keepLinear, bool displayInPass);
};

}  // namespace patina
