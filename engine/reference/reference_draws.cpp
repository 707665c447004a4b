#include "reference/reference_draws.h"

#include <algorithm>

#include "scene/ground.h"

namespace patina {

std::optional<Mesh> groundOf(const PreparedScene& prepared) {
    if (prepared.scene.display.ground == Ground::None) {
        return std::nullopt;
    }
    return groundMesh(groundUnder(boundingBox(*prepared.mesh)));
}

std::vector<SceneDraw> referenceDraws(const PreparedScene& prepared, const std::optional<Mesh>& ground) {
    std::vector<SceneDraw> draws = sceneDraws(prepared);
    if (ground) {
        SceneDraw floor;
        floor.mesh = &*ground;
        floor.primitive = -1;
        floor.material = groundMaterial(prepared.scene.display);
        floor.doubleSided = false;   // seen from above only, as the renderer draws it
        draws.push_back(floor);
    }
    return draws;
}

int32_t catcherDraw(const PreparedScene& prepared, size_t drawCount) {
    const bool caught = prepared.scene.display.ground == Ground::Shadow && drawCount == sceneDraws(prepared).size() + 1;
    return caught ? int32_t(drawCount) - 1 : -1;
}

bool stagedWithShadows(const Scene& scene) {
    return scene.display.ground != Ground::None ||
           std::any_of(scene.lights.begin(), scene.lights.end(),
                       [](const Light& light) { return light.enabled && light.shadows; });
}

}  // namespace patina
