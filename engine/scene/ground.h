#pragma once
// The plane under the model (DisplaySettings::ground, docs/LIGHTING.md "The ground"): level
// with the model's lowest point, centred under it and wide enough that its edge lies well
// outside the shadows it takes.
#include "geometry/mesh.h"
#include "scene/scene.h"
#include "shading/material_parameters.h"

namespace patina {

struct GroundPlane {
    glm::vec3 centre{0.0f};   // on the plane, under the middle of the model's box
    float halfSize = 1.0f;    // half the square's side
    bool operator==(const GroundPlane&) const = default;
};

// How far the ground reaches past the model, in radii of the model's bounding sphere.
inline constexpr float kGroundRadii = 6.0f;

// The ground under a model whose world-space box is `bounds` (a built-in mesh, or a model's
// draws flattened); a unit square at y = 0 for an empty box.
GroundPlane groundUnder(const BoundingBox& bounds);

// The plane as two triangles facing +y (counter-clockwise seen from above), with its normal,
// UVs and tangent: drawn as any other primitive.
Mesh groundMesh(const GroundPlane& plane);

// The same plane as a grid of cells x cells squares (its vertices row by row from -x -z, each
// square two triangles facing +y): what carries the ambient occlusion baked at its vertices
// (scene/ambient_occlusion.h), the contact shadow a plane of four corners could not hold.
Mesh groundGrid(const GroundPlane& plane, int cells);

// The floor's material (Ground::Floor): a dielectric of the display's ground colour and
// roughness, shaded as glTF's.
MaterialParameters groundMaterial(const DisplaySettings& display);

}  // namespace patina
