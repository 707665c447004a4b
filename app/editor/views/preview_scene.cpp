#include "views/preview_scene.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "environment/builtin_environments.h"

namespace patina::editor {

Scene previewScene(const Material& material) {
    Scene scene;
    scene.mesh = MeshKind::Sphere;
    scene.material = material;
    scene.camera.position = {0.0f, 0.0f, 3.1f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fovYDegrees = 45.0f;
    // The studio all around (what makes a metal read as metal: it reflects something), and one
    // key light above and to the left for a highlight whose size shows the roughness.
    Light studio;
    studio.type = LightType::Environment;
    studio.name = "studio";
    studio.source = builtinSource("studio");
    Light key;
    key.type = LightType::Directional;
    key.name = "key";
    key.intensity = 1.5f;
    key.direction = -glm::normalize(glm::vec3(-0.5f, 0.8f, 0.6f));
    scene.lights = {studio, key};
    scene.display.tonemap = Tonemap::PbrNeutral;
    scene.display.background = glm::vec3(0.18f);
    return scene;
}

}  // namespace patina::editor
