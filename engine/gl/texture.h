#pragma once
#include "common/ldr_image.h"

namespace patina {

// An RGBA8 texture made from an image (e.g. a preset thumbnail). Needs a current context.
class Texture {
public:
    explicit Texture(const LdrImage& image);
    ~Texture();
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;

    unsigned id() const { return id_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    unsigned id_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace patina
