#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "reference/surface_maps.h"
#include "scene/prepared_scene.h"
#include "scene/probe.h"
#include "scene/scene.h"

namespace patina {

// What the centre of each pixel of a width x height image of the scene sees, as the GPU
// rasterises it (shaders/stages/mesh.vert): the nearest surface of the draw items, with
// position and normal in world space interpolated perspective-correctly across its triangle
// (the normal not normalised, as the shaders get it; reversed on a back face where the item's
// material says so), the unit vector to the camera, and which item it is of. The ground-truth
// render shades these points, each with its item's material; rows top first, as images are
// stored.
struct PixelSurfaces {
    int width = 0, height = 0;
    std::vector<int32_t> sampleOfPixel;   // index into samples; -1 where no item is
    std::vector<ProbeSample> samples;
    std::vector<int32_t> drawOfSample;    // index into the draw list (and materials)
    std::vector<MaterialParameters> materials;   // each draw item's, in the list's order
    // With a textured item (SceneDraw::maps), per sample what the maps make of it
    // (reference/surface_maps.h): its material (the item's factors where it has no maps), the
    // occlusion of its environment and hemisphere light, its emission; the sample's normal is
    // then the normal map's. Empty without one.
    std::vector<MaterialParameters> sampleMaterials;
    std::vector<float> occlusion;
    std::vector<glm::vec3> emission;
    std::vector<float> alpha;                     // the maps' alpha (the inspector's channel)
    std::vector<MapCoordinates> coordinates;      // UVs and tangent, as the maps read them
    // Per sample, always: the unit normal before any normal map (reversed on a back face where
    // the material says so), the inspector's geometry normal.
    std::vector<glm::vec3> geometryNormals;
    // Per sample, always: the world tangent as mesh.vert hands it on (w the bitangent's sign;
    // 0 for an item drawn with neither maps nor anisotropy, or a mesh without tangents), which
    // KHR_materials_anisotropy's direction turns from.
    std::vector<glm::vec4> tangents;
};

// `draws` seen by `camera` at width x height, with the renderer's rules: triangles clipped at
// the near plane, back faces of a single-sided item culled (a mirrored item's front faces
// wind clockwise), the nearest fragment kept and the first drawn on a tie. A blended item
// counts as opaque here: the ground truth has no transparency yet. `model`: the one whose
// materials the draws' maps point into (their images), for MASK and the mapped samples.
PixelSurfaces rasterizeSurfaces(const std::vector<SceneDraw>& draws, const Camera& camera, int width, int height,
                                const Model* model = nullptr);
// What `prepared` draws (sceneDraws), seen by its camera.
PixelSurfaces rasterizeSurfaces(const PreparedScene& prepared, int width, int height);

// The unit direction of the view ray through the centre of pixel (x, y), top row first.
glm::vec3 pixelRayDirection(const Camera& camera, int width, int height, int x, int y);

}  // namespace patina
