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
           lights.size() == other.lights.size() &&
           (lights.empty() ||
            std::memcmp(lights.data(), other.lights.data(), lights.size() * sizeof(shader::PackedLight)) == 0);
}

}  // namespace patina
