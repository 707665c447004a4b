#include "reference/channel_image.h"

#include <algorithm>

#include "environment/environment.h"
#include "scene/light_packing.h"

namespace patina {

// The maps' material, alpha, occlusion, emission, UVs and tangent where the frame has maps (the
// item's factors, alpha 1, where it has none), else the item's factors and alpha.
ChannelPoint channelPoint(const PixelSurfaces& surfaces, const std::vector<SceneDraw>& draws, size_t i) {
    const ProbeSample& sample = surfaces.samples[i];
    const size_t draw = size_t(surfaces.drawOfSample[i]);
    const bool mapped = !surfaces.sampleMaterials.empty();
    const MaterialParameters& material = mapped ? surfaces.sampleMaterials[i] : surfaces.materials[draw];
    ChannelPoint point = channelPointOf(material);
    point.alpha = mapped ? surfaces.alpha[i] : draws[draw].alpha;
    if (mapped) {
        point.occlusion = surfaces.occlusion[i];
        point.emission = surfaces.emission[i];
        point.uv0 = surfaces.coordinates[i].uv0;
        point.uv1 = surfaces.coordinates[i].uv1;
        point.tangent = surfaces.coordinates[i].tangent;
    }
    if (!surfaces.tangents.empty()) {
        point.anisotropyTangent = surfaces.tangents[i];
    }
    point.geometryNormal = surfaces.geometryNormals[i];
    point.N = shader::safeNormalize(sample.normal);
    point.V = sample.toViewer;
    point.P = sample.position;
    return point;
}

std::optional<ChannelEnvironment> channelEnvironment(const PreparedScene& prepared) {
    const Light* light = enabledEnvironment(prepared.scene);
    if (!light) {
        return std::nullopt;
    }
    const std::shared_ptr<const Environment> shown = environmentShown(prepared.environment, light->source);
    ChannelEnvironment environment;
    environment.prefiltered = [shown](glm::vec3 d, float lod) { return sampleCube(shown->prefiltered, d, lod); };
    environment.maxLod = shown->maxLod();
    environment.irradiance = [shown, read = irradianceReader(*shown)](glm::vec3 n, float lod) { return read(n, lod); };
    environment.intensity = light->intensity;
    environment.rotationDegrees = light->rotationDegrees;
    return environment;
}

HdrImage channelImage(const PreparedScene& prepared, const PixelSurfaces& surfaces, const ChannelRequest& request) {
    const ChannelLights lights = channelLights(prepared.scene.lights, request);
    const std::vector<shader::PackedLight> packed = packEnabledLights(prepared.scene.lights);
    const std::vector<SceneDraw> draws = sceneDraws(prepared);
    const std::optional<ChannelEnvironment> environment = channelEnvironment(prepared);
    HdrImage image{surfaces.width, surfaces.height,
                   std::vector<float>(size_t(surfaces.width) * size_t(surfaces.height) * 3, 0.0f)};
    for (size_t pixel = 0; pixel < surfaces.sampleOfPixel.size(); ++pixel) {
        const int32_t i = surfaces.sampleOfPixel[pixel];
        if (i < 0) {
            continue;
        }
        const BrdfModelId model = draws[size_t(surfaces.drawOfSample[size_t(i)])].material.model;
        const ChannelPoint point = channelPoint(surfaces, draws, size_t(i));
        const shader::ChannelInputs inputs =
            gatherChannelInputs(model, point, packed, lights.asked, lights.key, environment ? &*environment : nullptr);
        const glm::vec3 value =
            shader::channelValue(request.channel, inputs, channelPointLayers(point), channelPbrRanges(request));
        std::copy(&value.x, &value.x + 3, &image.rgb[pixel * 3]);
    }
    return image;
}

}  // namespace patina
