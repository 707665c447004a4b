#pragma once
// The ambient occlusion of a model and of the ground under it (DisplaySettings::ambientOcclusion,
// docs/LIGHTING.md "Ambient occlusion"), baked once per model at its vertices by rays
// (geometry/ambient_occlusion.h): each vertex's cosine-weighted share of the sky that neither the
// model nor the ground hides. The renderer multiplies it into the file's occlusion map, on the
// environment's and the hemisphere lights' light only. assets/ keeps it per model and ground.
#include <cstddef>
#include <vector>

#include "geometry/ambient_occlusion.h"
#include "geometry/mesh.h"
#include "model/model.h"

namespace patina {

// The ground's grid under a model (scene/ground.h groundGrid): cells a side. 192 over the
// ground's 12 radii: a cell about a sixteenth of the model's radius, fine enough that the
// contact shadow's steep edge interpolates within a few per cent of the ground truth.
inline constexpr int kOcclusionGroundCells = 192;

struct AmbientOcclusion {
    // Per draw item of the model (its `draws` order), a value per vertex of the item's primitive,
    // the item placed in the world; for a built-in mesh one entry, the mesh's.
    std::vector<std::vector<float>> items;
    // Baked with a ground under the model (any but Ground::None): the ground hides the lower
    // sky, and its grid (groundGrid under the model's box) has a value per vertex.
    bool withGround = false;
    Mesh ground;
    std::vector<float> groundValues;
};

// The occlusion of `world` (the built-in mesh, or a model's draws flattened: the occluders and
// the box the ground lies under) at the vertices of `model`'s draw items, or of `world` itself
// for none (`rays` a vertex), and with `ground` at the ground's grid too (twice `rays.side`: four
// times the rays, as a plain floor shows noise that a model's detail hides). Throws std::runtime_error where Embree
// cannot build.
AmbientOcclusion bakeAmbientOcclusion(const Mesh& world, const Model* model, bool ground, const OcclusionRays& rays = {});

// The values of draw item `item` (-1: the one mesh, entry 0) where they are one per vertex of a
// mesh of `vertices`; null otherwise (an occlusion baked for another shape draws none).
const std::vector<float>* itemOcclusion(const AmbientOcclusion& occlusion, int item, size_t vertices);

}  // namespace patina
