#include "reference/pixel_story.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "reference/channel_image.h"
#include "shading/brdf_models.h"
#include "scene/channel.h"
#include "scene/light_packing.h"

namespace patina {

namespace {
void nameItem(PixelStory& story, const PreparedScene& prepared, const SceneDraw& draw) {
    if (!prepared.model || draw.item < 0) {
        return;
    }
    const DrawItem& item = prepared.model->draws[size_t(draw.item)];
    story.item = item.node;
    story.material = item.material >= 0 ? prepared.model->materials[size_t(item.material)].name : "glTF default";
}
}  // namespace

std::optional<PixelStory> pixelStory(const PreparedScene& prepared, const PixelSurfaces& surfaces, int x, int y) {
    const int32_t sample = surfaces.sampleOfPixel[size_t(y) * size_t(surfaces.width) + size_t(x)];
    if (sample < 0) {
        return std::nullopt;
    }
    PixelStory story;
    story.x = x;
    story.y = y;
    const std::vector<SceneDraw> draws = sceneDraws(prepared);
    const SceneDraw& draw = draws[size_t(surfaces.drawOfSample[size_t(sample)])];
    nameItem(story, prepared, draw);
    const ProbeSample& surface = surfaces.samples[size_t(sample)];
    story.position = surface.position;
    story.view = surface.toViewer;

    const std::vector<Light>& lights = prepared.scene.lights;
    const std::vector<size_t> order = enabledLightOrder(lights);
    const std::vector<shader::PackedLight> packed = packEnabledLights(lights);
    const ChannelLights channel = channelLights(lights, {});
    const ChannelPoint point = channelPoint(surfaces, draws, size_t(sample));
    const BrdfModelId model = draw.material.model;
    story.model = std::string(brdfModel(model).name);
    const std::optional<ChannelEnvironment> environment = channelEnvironment(prepared);
    story.inputs = gatherChannelInputs(model, point, packed, -1, channel.key, environment ? &*environment : nullptr);
    if (point.anisotropyStrength > 0.0f) {   // as channelMaterial stretches the lobe
        const shader::ChannelLayers layers = channelPointLayers(point);
        const glm::vec4 t = layers.anisotropyTangent;
        const shader::SurfaceMaterial m = shader::withAnisotropy(
            shader::deriveSurfaceMaterial(point.baseColor, point.roughness, point.specular, point.metallic),
            story.inputs.shadingNormal, glm::vec3(t), t.w, layers.anisotropy.x, layers.anisotropy.y,
            layers.anisotropy.z);
        story.anisotropy = PixelStory::Stretch{m.anisotropicT, m.anisotropy, m.alphaT, m.alphaB};
    }
    if (channel.key >= 0) {
        story.keyLight = lights[order[size_t(channel.key)]].name;
    }
    // Each enabled light's lobes: the same gather over that light alone, in the scene's order
    // (the lights panel's), not the packing's (area lights last).
    std::vector<size_t> byScene(packed.size());
    std::iota(byScene.begin(), byScene.end(), size_t(0));
    std::sort(byScene.begin(), byScene.end(), [&](size_t a, size_t b) { return order[a] < order[b]; });
    for (size_t i : byScene) {
        const shader::ChannelInputs alone = gatherChannelInputs(model, point, {packed[i]}, -1, -1, nullptr);
        const Light& light = lights[order[i]];
        story.lights.push_back({light.name, std::string(lightTypeName(light.type)), alone.diffuse,
                                alone.specularLighting});
    }
    if (const Light* light = enabledEnvironment(prepared.scene)) {
        story.environment =
            LightShare{light->name, "environment", story.inputs.environmentDiffuse, story.inputs.environmentSpecular};
    }
    const glm::vec3 shown = shader::displayTransform(story.inputs.radiance, prepared.scene.display.exposure,
                                                     tonemapShaderIndex(prepared.scene.display.tonemap));
    for (int c = 0; c < 3; ++c) {
        story.display[size_t(c)] = uint8_t(std::lround(std::clamp(shown[c], 0.0f, 1.0f) * 255.0f));
    }
    return story;
}

}  // namespace patina
