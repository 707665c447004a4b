#pragma once
// An LdrImage and a Cairo image surface, each into the other: captions draw on part of an
// image through one, charts are drawn on one and handed on as an image.
#include <cairo.h>

#include "image/image.h"

namespace patina {

// A new ARGB32 surface holding the image's pixels of the rectangle at (x, y), width by height,
// all inside it.
cairo_surface_t* surfaceFromImage(const LdrImage& image, int x, int y, int width, int height);

// Writes the surface's pixels over the image's with its top left corner at (x, y); it must fit.
void copySurfaceToImage(cairo_surface_t* surface, LdrImage& image, int x, int y);

// The surface as a new image.
LdrImage imageFromSurface(cairo_surface_t* surface);

}  // namespace patina
