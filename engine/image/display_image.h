#pragma once
#include "common/hdr_image.h"
#include "image/image.h"
#include "scene/scene.h"

namespace patina {

// The display image of linear radiance on the CPU: exposure, tone map and sRGB by the shaders'
// own displayTransform (shaders/shared/display.glsl), rounded to bytes as the GPU's RGBA8 target
// stores them. For images made without the GPU (the ground-truth render).
LdrImage displayImage(const HdrImage& linear, const DisplaySettings& display);

}  // namespace patina
