#include "preview_scene.h"

#include <cmath>

#include <glm/trigonometric.hpp>

namespace patina::editor {

Scene previewScene(const Material& material) {
    Scene scene;
    scene.mesh = MeshKind::Sphere;
    scene.material = material;
    scene.camera.position = {0.0f, 0.0f, 3.1f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fovYDegrees = 45.0f;
    Light sky;
    sky.type = LightType::Hemisphere;
    sky.name = "sky";
    sky.sky = glm::vec3(0.9f);
    sky.ground = glm::vec3(0.25f);
    sky.intensity = 0.5f;
    scene.lights = {sky};
    // Rows at 15, 40 and 65 degrees above the view axis, each spread over 160 degrees around it.
    struct Row {
        float elevationDegrees;
        int lights;
        float intensity;
    };
    for (const Row row : {Row{15.0f, 7, 0.35f}, Row{40.0f, 6, 0.35f}, Row{65.0f, 3, 0.5f}}) {
        for (int i = 0; i < row.lights; ++i) {
            const float azimuth = glm::radians(-80.0f + 160.0f * (float(i) + 0.5f) / float(row.lights));
            const float elevation = glm::radians(row.elevationDegrees);
            Light box;
            box.type = LightType::Directional;
            box.name = "soft box";
            box.direction = -glm::vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                       std::cos(elevation) * std::cos(azimuth));
            box.intensity = row.intensity;
            scene.lights.push_back(box);
        }
    }
    scene.display.tonemap = Tonemap::PbrNeutral;
    scene.display.background = glm::vec3(0.18f);
    return scene;
}

}  // namespace patina::editor
