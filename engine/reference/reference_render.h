#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "common/hdr_image.h"
#include "reference/pixel_surfaces.h"
#include "scene/prepared_scene.h"

namespace patina {

// The ground truth as a picture: every pixel the mesh covers shaded by the Monte Carlo estimate
// of reference/radiance.h (the environment's full-resolution image by MIS, the analytic lights
// exactly), through pixel centres (no antialiasing). The background is what the renderer draws
// there (the colour, or the environment read as background.frag reads it), so an error map
// against a render is the shading's alone.
struct ReferenceRenderOptions {
    int samplesPerPixel = 256;   // estimator iterations (one direction of each strategy each)
    int samplesPerPass = 16;     // the image is complete, and reported, after each pass
    // Shadows and occlusion: every light and the environment blocked by the scene's own
    // triangles and its ground's (ReferenceOptions::occluders, Embree). Off: each point lit as
    // if alone.
    bool visibility = false;
};

struct ReferenceImage {
    HdrImage value;
    HdrImage standardError;   // of each pixel's mean; 0 in the background
    int samplesPerPixel = 0;  // done so far
    // 1 where the flat background shows (no surface, no environment behind the mesh): the
    // pixels the renderer shows as the background's swatch (displayImage's `backdrop`).
    std::vector<uint8_t> backdrop;
};

// Told the image after each pass; false stops (the image so far is the result).
using ReferencePassDone = std::function<bool(const ReferenceImage&)>;

// The enabled environment light shows the prepared environment (std::invalid_argument without
// it); `surfaces` are the prepared scene's (rasterizeSurfaces), each shaded with its draw
// item's material.
ReferenceImage renderReference(const PreparedScene& prepared, const PixelSurfaces& surfaces,
                               const ReferenceRenderOptions& options, const ReferencePassDone& passDone = {});

}  // namespace patina
