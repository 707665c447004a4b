#include "scene/light_rig.h"

#include <algorithm>
#include <cmath>

#include "scene/camera_placement.h"

namespace patina {

namespace {
bool usableRadius(float radius) {
    return std::isfinite(radius) && radius > 0.0f;
}
}  // namespace

void moveLightRig(std::vector<Light>& lights, const BoundingSphere& from, const BoundingSphere& to) {
    if (!usableRadius(from.radius) || !usableRadius(to.radius)) {
        return;
    }
    const float s = to.radius / from.radius;
    auto place = [&](glm::vec3 p) { return to.center + (p - from.center) * s; };
    for (Light& light : lights) {
        if (light.type != LightType::Point && light.type != LightType::Sphere && light.type != LightType::Tube) {
            continue;
        }
        light.position = place(light.position);
        light.start = place(light.start);
        light.end = place(light.end);
        light.range *= s;   // 0 (no window) stays 0
        light.sourceRadius *= s;
        light.intensity *= s * s;
        light.attenuation *= glm::vec3(s * s, s, 1.0f);
    }
}

BoundingSphere shapeBounds(const Scene& scene, const Mesh* mesh) {
    if (scene.meshFile.empty() || !mesh) {
        return {glm::vec3(0.0f), scene.mesh == MeshKind::Torus ? 1.05f : 1.0f};
    }
    const BoundingSphere bounds = boundingSphere(*mesh);
    return {bounds.center, std::max(bounds.radius, 1e-3f)};
}

void fitSceneTo(Scene& scene, const BoundingSphere& from, const BoundingSphere& to) {
    frameAsModelViewer(scene.camera, to);
    moveLightRig(scene.lights, from, to);
}

}  // namespace patina
