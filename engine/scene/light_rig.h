#pragma once
// The lights made for one model, moved onto another of another size.
#include <vector>

#include "geometry/mesh.h"
#include "scene/light.h"
#include "scene/scene.h"

namespace patina {

// Scales the rig of positional lights (point, sphere, tube) by s = to.radius / from.radius about
// the models' centres: positions, tube ends, ranges and source radii by s; the intensity by s^2
// and the attenuation coefficients (a_c, a_l, a_q) by (s^2, s, 1), so that
// I / (a_c + a_l t + a_q t^2) at the scaled distance s t is what it was at t. The window
// (1 - (t/range)^4)^2 and a sphere's or tube's angular size depend on ratios only: every point
// of the new model is lit as the matching point of the old one (docs/SHADING.md S1). Directional,
// hemisphere and environment lights have no position and are left alone. A radius that is not
// positive and finite on either side leaves the rig as it is.
void moveLightRig(std::vector<Light>& lights, const BoundingSphere& from, const BoundingSphere& to);

// The sphere the camera frames and the rig is fitted to: `mesh` (the scene's model flattened,
// radius at least 1e-3) where the scene names a model file, else the built-in mesh's (about the
// origin, radius 1; the torus 1.05). `mesh` may be null: the built-in's.
BoundingSphere shapeBounds(const Scene& scene, const Mesh* mesh);

// The scene's shape replaced by one of `to`'s bounds, as opening a model does: the camera frames
// it as model-viewer frames a model it loads (frameAsModelViewer: from the front and a little
// above, whatever the camera looked at before) and the rig moves from `from` (the shape's
// before) onto it.
void fitSceneTo(Scene& scene, const BoundingSphere& from, const BoundingSphere& to);

}  // namespace patina
