#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "scene/probe.h"
#include "scene/scene.h"

namespace patina {

// What the centre of each pixel of a width x height image of the scene sees, as the GPU
// rasterises it (shaders/stages/mesh.vert): the nearest surface of the mesh, with position and
// normal interpolated perspective-correctly across its triangle (the normal not normalised,
// as the shaders get it), and the unit vector to the camera. The ground-truth render shades
// these points; rows top first, as images are stored.
struct PixelSurfaces {
    int width = 0, height = 0;
    std::vector<int32_t> sampleOfPixel;   // index into samples; -1 where the mesh is not
    std::vector<ProbeSample> samples;
};

// `mesh` seen by `camera` at width x height (triangles are clipped at the near plane).
PixelSurfaces rasterizeSurfaces(const Mesh& mesh, const Camera& camera, int width, int height);

// The unit direction of the view ray through the centre of pixel (x, y), top row first.
glm::vec3 pixelRayDirection(const Camera& camera, int width, int height, int x, int y);

}  // namespace patina
