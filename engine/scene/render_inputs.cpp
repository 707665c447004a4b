#include "scene/render_inputs.h"

#include <cstring>

#include "scene/light_packing.h"

namespace patina {

RenderInputs renderInputs(const PreparedScene& prepared) {
    const Scene& scene = prepared.scene;
    RenderInputs inputs;
    inputs.mesh = prepared.mesh;
    inputs.model = prepared.model;
    if (prepared.model) {   // a built-in mesh draws none of them
        inputs.modelMaterials = scene.modelMaterials;
    }
    inputs.material = scene.material;
    inputs.cameraPosition = scene.camera.position;
    inputs.cameraTarget = scene.camera.target;
    inputs.fovYDegrees = scene.camera.fovYDegrees;
    inputs.lights = packEnabledLights(scene.lights);
    // Whether each casts shadows, in the row the renderer fills with its map (any value but 0).
    const std::vector<size_t> order = enabledLightOrder(scene.lights);
    for (size_t i = 0; i < inputs.lights.size(); ++i) {
        inputs.lights[i].shadowMap = scene.lights[order[i]].shadows ? 1.0f : 0.0f;
    }
    inputs.exposure = scene.display.exposure;
    inputs.tonemap = scene.display.tonemap;
    inputs.background = scene.display.background;
    if (const Light* environment = enabledEnvironment(scene)) {
        inputs.environment = prepared.environment;
        inputs.environmentSource = environment->source;
        inputs.environmentIntensity = environment->intensity;
        inputs.environmentRotation = environment->rotationDegrees;
    }
    inputs.backgroundFromEnvironment = scene.display.backgroundFromEnvironment;
    inputs.backgroundBlur = scene.display.backgroundBlur;
    inputs.ground = scene.display.ground;
    inputs.groundColor = scene.display.groundColor;
    inputs.groundRoughness = scene.display.groundRoughness;
    inputs.occlusion = prepared.occlusion;
    return inputs;
}

bool RenderInputs::operator==(const RenderInputs& other) const {
    return mesh == other.mesh && model == other.model && modelMaterials == other.modelMaterials &&
           material == other.material &&
           cameraPosition == other.cameraPosition && cameraTarget == other.cameraTarget &&
           fovYDegrees == other.fovYDegrees && exposure == other.exposure && tonemap == other.tonemap &&
           background == other.background && environment == other.environment &&
           environmentSource == other.environmentSource && environmentIntensity == other.environmentIntensity &&
           environmentRotation == other.environmentRotation &&
           backgroundFromEnvironment == other.backgroundFromEnvironment && backgroundBlur == other.backgroundBlur &&
           ground == other.ground && groundColor == other.groundColor && groundRoughness == other.groundRoughness &&
           occlusion == other.occlusion &&
           lights.size() == other.lights.size() &&
           (lights.empty() ||
            std::memcmp(lights.data(), other.lights.data(), lights.size() * sizeof(shader::PackedLight)) == 0);
}

}  // namespace patina
