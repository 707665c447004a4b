#pragma once
// What the ground truth draws of a staged scene: its draw items and the floor the display puts
// under the model, and whether what stands between a point and its light counts by itself.
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/mesh.h"
#include "scene/prepared_scene.h"

namespace patina {

// The plane the display puts under the model (scene/ground.h, as the renderer places it): a
// floor or a shadow catcher; nothing for Ground::None.
std::optional<Mesh> groundOf(const PreparedScene& prepared);

// The scene's draw items (sceneDraws) and, where the display has a ground, the ground last,
// with its material (groundMaterial): a floor, or the shadow catcher (drawn by renderReference
// as the background darkened by the share of that material's light its shadows leave). `ground`
// is groundOf's plane and must outlive the draws.
std::vector<SceneDraw> referenceDraws(const PreparedScene& prepared, const std::optional<Mesh>& ground);

// The shadow catcher's index among `drawCount` items made by referenceDraws, or -1: a scene
// without one, or items made without the ground (sceneDraws').
int32_t catcherDraw(const PreparedScene& prepared, size_t drawCount);

// Whether the scene is staged with shadows: an enabled light that casts them, or a ground to
// take them. Its ground truth then counts what blocks the light (ReferenceRenderOptions::visibility).
bool stagedWithShadows(const Scene& scene);

}  // namespace patina
