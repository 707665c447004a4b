#include "image/cairo_image.h"

#include <cstdint>
#include <cstring>

namespace patina {

namespace {

// Cairo's ARGB32 is one native-endian 32-bit word a pixel with the colour premultiplied by alpha.
uint32_t toCairo(const uint8_t* rgba) {
    const uint32_t a = rgba[3];
    auto premultiply = [a](uint8_t c) { return (uint32_t(c) * a + 127) / 255; };
    return a << 24 | premultiply(rgba[0]) << 16 | premultiply(rgba[1]) << 8 | premultiply(rgba[2]);
}

void fromCairo(uint32_t pixel, uint8_t* rgba) {
    const uint32_t a = pixel >> 24;
    auto unpremultiply = [a](uint32_t c) { return uint8_t(a == 0 ? 0 : (c * 255 + a / 2) / a); };
    rgba[0] = unpremultiply(pixel >> 16 & 0xFF);
    rgba[1] = unpremultiply(pixel >> 8 & 0xFF);
    rgba[2] = unpremultiply(pixel & 0xFF);
    rgba[3] = uint8_t(a);
}

}  // namespace

cairo_surface_t* surfaceFromImage(const LdrImage& image, int x, int y, int width, int height) {
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
    cairo_surface_flush(surface);
    unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    for (int row = 0; row < height; ++row) {
        for (int column = 0; column < width; ++column) {
            const uint8_t* rgba = &image.rgba[(size_t(y + row) * size_t(image.width) + size_t(x + column)) * 4];
            const uint32_t pixel = toCairo(rgba);
            std::memcpy(data + size_t(row) * size_t(stride) + size_t(column) * 4, &pixel, 4);
        }
    }
    cairo_surface_mark_dirty(surface);
    return surface;
}

void copySurfaceToImage(cairo_surface_t* surface, LdrImage& image, int x, int y) {
    cairo_surface_flush(surface);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    for (int row = 0; row < cairo_image_surface_get_height(surface); ++row) {
        for (int column = 0; column < cairo_image_surface_get_width(surface); ++column) {
            uint32_t pixel = 0;
            std::memcpy(&pixel, data + size_t(row) * size_t(stride) + size_t(column) * 4, 4);
            fromCairo(pixel, &image.rgba[(size_t(y + row) * size_t(image.width) + size_t(x + column)) * 4]);
        }
    }
}

LdrImage imageFromSurface(cairo_surface_t* surface) {
    LdrImage image{cairo_image_surface_get_width(surface), cairo_image_surface_get_height(surface), {}};
    image.rgba.resize(size_t(image.width) * size_t(image.height) * 4);
    copySurfaceToImage(surface, image, 0, 0);
    return image;
}

}  // namespace patina
