#pragma once
// What the ground truth draws of a staged scene: its draw items and the floor the display puts
// under the model, and whether what stands between a point and its light counts by itself.
#include <optional>
#include <vector>

#include "geometry/mesh.h"
#include "scene/prepared_scene.h"

namespace patina {

// The plane the display puts under the model (scene/ground.h, as the renderer places it): a
// floor or a shadow catcher; nothing for Ground::None.
std::optional<Mesh> groundOf(const PreparedScene& prepared);

// The scene's draw items (sceneDraws) and, where the display has a floor, the floor last, with
// its material (groundMaterial): `ground` is groundOf's plane and must outlive the draws. A
// shadow catcher is not drawn: the ground truth has no catcher (the model over its background).
std::vector<SceneDraw> referenceDraws(const PreparedScene& prepared, const std::optional<Mesh>& ground);

// Whether the scene is staged with shadows: an enabled light that casts them, or a ground to
// take them. Its ground truth then counts what blocks the light (ReferenceRenderOptions::visibility).
bool stagedWithShadows(const Scene& scene);

}  // namespace patina
