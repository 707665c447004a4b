#include "state/light_list.h"

#include <algorithm>

#include "state/editor_state.h"
#include "scene/camera_control.h"
#include "shading/shading.h"

namespace patina::editor {

namespace {
constexpr const char* kOneEnvironment = "A scene has one environment at most: change the one in the light list.";

// A point of the view: `depth` of the way from the camera to what it looks at, `right` and
// `up` fractions of the view's half height there (inside any view at least as wide as high).
glm::vec3 pointInView(const Camera& camera, float right, float up, float depth) {
    const glm::vec3 at = camera.position + depth * (camera.target - camera.position);
    return unprojectAtDepthOf(camera, glm::vec2(2.0f), glm::vec2(1.0f + right, 1.0f - up), at);
}
}  // namespace

void addLight(Document& document, Interaction& interaction, Prompts& prompts, LightType type) {
    if (document.scene.lights.size() >= size_t(shader::MAX_LIGHTS)) {
        prompts.error = "A scene holds at most " + std::to_string(shader::MAX_LIGHTS) + " lights.";
        return;
    }
    if (type == LightType::Environment && document.environmentIndex() >= 0) {
        prompts.error = kOneEnvironment;
        interaction.selectedLight = document.environmentIndex();
        return;
    }
    Light light;
    light.type = type;
    light.name = std::string(lightTypeName(type)) + " " + std::to_string(document.scene.lights.size() + 1);
    // Point, sphere and tube lights start up and to the left between the camera and what it
    // looks at, wherever the camera is, so there is a handle to drag at once (a tube used to
    // start above the picture).
    if (type == LightType::Point || type == LightType::Sphere) {
        light.position = pointInView(document.scene.camera, -0.45f, 0.45f, 0.65f);
        light.range = 10.0f;
        light.intensity = 5.0f;
        if (type == LightType::Sphere) {   // a point light keeps every other type's default
            light.sourceRadius = 0.25f;
        }
    } else if (type == LightType::Tube) {
        light.start = pointInView(document.scene.camera, -0.75f, 0.5f, 0.65f);
        light.end = pointInView(document.scene.camera, 0.05f, 0.5f, 0.65f);
        light.range = 10.0f;
        light.intensity = 8.0f;
        light.sourceRadius = 0.05f;
    } else if (type == LightType::Directional) {
        light.direction = {-0.5f, -0.7f, -0.5f};
        light.intensity = 2.0f;
    } else if (type == LightType::Hemisphere) {
        light.sky = {0.3f, 0.4f, 0.6f};
        light.ground = {0.1f, 0.08f, 0.06f};
    } else {
        light.name = "studio";   // builtin:studio, the default source
    }
    applyEdit(document, [&](Document& d) { d.scene.lights.push_back(light); });
    interaction.selectedLight = int(document.scene.lights.size()) - 1;
}

void duplicateLight(Document& document, Interaction& interaction, Prompts& prompts, int index) {
    if (!document.hasLight(index) || document.scene.lights.size() >= size_t(shader::MAX_LIGHTS)) {
        return;
    }
    Light copy = document.scene.lights[size_t(index)];
    if (copy.type == LightType::Environment) {
        prompts.error = kOneEnvironment;
        return;
    }
    copy.name += " copy";
    applyEdit(document, [&](Document& d) { d.scene.lights.insert(d.scene.lights.begin() + index + 1, copy); });
    interaction.selectedLight = index + 1;
}

void deleteLight(Document& document, Interaction& interaction, int index) {
    if (!document.hasLight(index)) {
        return;
    }
    applyEdit(document, [&](Document& d) { d.scene.lights.erase(d.scene.lights.begin() + index); });
    if (interaction.soloLight == index) {
        interaction.soloLight = -1;
    } else if (interaction.soloLight > index) {
        --interaction.soloLight;
    }
    interaction.selectedLight = std::min(interaction.selectedLight, int(document.scene.lights.size()) - 1);
}

void moveLight(Document& document, Interaction& interaction, int index, int delta) {
    const int target = index + delta;
    if (!document.hasLight(index) || !document.hasLight(target)) {
        return;
    }
    applyEdit(document, [&](Document& d) {
        std::swap(d.scene.lights[size_t(index)], d.scene.lights[size_t(target)]);
    });
    if (interaction.selectedLight == index) {
        interaction.selectedLight = target;
    }
    if (interaction.soloLight == index) {
        interaction.soloLight = target;
    } else if (interaction.soloLight == target) {
        interaction.soloLight = index;
    }
}

Light* editedEnvironment(Document& document) {
    const int index = document.environmentIndex();
    return index < 0 ? nullptr : &document.scene.lights[size_t(index)];
}


}  // namespace patina::editor
