#include "reference/pixel_story.h"

#include <cmath>

#include "reference/channel_image.h"
#include "scene/channel.h"
#include "scene/light_packing.h"
#include "shading/channel_inputs.h"

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

void copyInputs(PixelStory& story, const shader::ChannelInputs& c) {
    story.geometryNormal = c.geometryNormal;
    story.normal = c.shadingNormal;
    story.uv0 = c.uv0;
    story.uv1 = c.uv1;
    story.tangent = c.tangent;
    story.baseColor = c.baseColor;
    story.alpha = c.alpha;
    story.roughness = c.roughness;
    story.metallic = c.metallic;
    story.specular = c.specular;
    story.f0 = c.f0;
    story.diffuseColor = c.diffuseColor;
    story.occlusion = c.occlusion;
    story.emission = c.emission;
    story.NoV = c.NoV;
    story.D = c.D;
    story.G = c.G;
    story.F = c.F;
    story.radiance = c.radiance;
}

// Each enabled light's lobes: the gather over that light alone (and none for the environment's,
// which channelWithEnvironment gives apart).
void shareLights(PixelStory& story, const PreparedScene& prepared, const PixelSurfaces& surfaces, int sample) {
    const std::vector<Light>& lights = prepared.scene.lights;
    const std::vector<size_t> order = enabledLightOrder(lights);
    for (size_t packed = 0; packed < order.size(); ++packed) {
        const Light& light = lights[order[packed]];
        const shader::ChannelInputs alone = sampleChannelInputs(prepared, surfaces, size_t(sample), {light});
        story.lights.push_back({light.name, std::string(lightTypeName(light.type)), alone.diffuse,
                                alone.specularLighting});
    }
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
    nameItem(story, prepared, draws[size_t(surfaces.drawOfSample[size_t(sample)])]);
    const ChannelLights lights = channelLights(prepared.scene.lights, {});
    const shader::ChannelInputs inputs = *pixelChannelInputs(prepared, surfaces, lights, x, y);
    copyInputs(story, inputs);
    const ProbeSample& surface = surfaces.samples[size_t(sample)];
    story.position = surface.position;
    story.view = surface.toViewer;
    if (lights.key >= 0) {
        story.keyLight = prepared.scene.lights[enabledLightOrder(prepared.scene.lights)[size_t(lights.key)]].name;
    }
    shareLights(story, prepared, surfaces, sample);
    if (const Light* environment = enabledEnvironment(prepared.scene)) {
        story.environment = LightShare{environment->name, "environment", inputs.environmentDiffuse,
                                       inputs.environmentSpecular};
    }
    const glm::vec3 shown = shader::displayTransform(story.radiance, prepared.scene.display.exposure,
                                                     tonemapShaderIndex(prepared.scene.display.tonemap));
    for (int c = 0; c < 3; ++c) {
        story.display[size_t(c)] = uint8_t(std::lround(std::clamp(shown[c], 0.0f, 1.0f) * 255.0f));
    }
    return story;
}

}  // namespace patina
