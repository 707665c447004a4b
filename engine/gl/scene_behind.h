#pragma once
// What a transmitting item sees through its wall (KHR_materials_transmission, docs/SHADING.md
// S7): the frame's opaque items that do not transmit, drawn first into an image of their own,
// premultiplied by their coverage (alpha 1 where an item is, 0 where the background is), with
// its mip chain, so that shade.frag reads it at the pixel (thin-walled: no refraction) blurred
// by the wall's roughness (PATINA_SCENE_BEHIND), and lets the environment show through where
// nothing of the scene is behind. Drawn only in a frame with a transmitting item.
#include <epoxy/gl.h>

namespace patina {

class SceneBehind {
public:
    SceneBehind() = default;
    ~SceneBehind();
    SceneBehind(const SceneBehind&) = delete;
    SceneBehind& operator=(const SceneBehind&) = delete;

    // Makes room for w x h, binds the framebuffer with colour attachment 0 only (a program's
    // display output goes nowhere), clears it to (0, 0, 0, 0) and its depth to far, and sets
    // the viewport to the whole image.
    void begin(int w, int h);
    // Builds the mip chain and binds the image to `unit` (then unit 0 is active again).
    void finish(int unit) const;
    int width() const { return width_; }

private:
    GLuint texture_ = 0, depth_ = 0, framebuffer_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace patina
