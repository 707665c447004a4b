#include "scene/scene.h"

#include "common/enum_names.h"
#include "environment/builtin_environments.h"
#include "shading/shading.h"

namespace patina {

std::string_view tonemapName(Tonemap tonemap) {
    switch (tonemap) {
    case Tonemap::None: return "none";
    case Tonemap::AcesNarkowicz: return "aces-narkowicz";
    case Tonemap::Reinhard: return "reinhard";
    case Tonemap::PbrNeutral: return "pbr-neutral";
    case Tonemap::AcesHill: return "aces-hill";
    case Tonemap::Agx: return "agx";
    }
    return "none";
}

int tonemapShaderIndex(Tonemap tonemap) {
    switch (tonemap) {
    case Tonemap::AcesNarkowicz: return shader::TONEMAP_ACES_NARKOWICZ;
    case Tonemap::Reinhard: return shader::TONEMAP_REINHARD;
    case Tonemap::PbrNeutral: return shader::TONEMAP_PBR_NEUTRAL;
    case Tonemap::AcesHill: return shader::TONEMAP_ACES_HILL;
    case Tonemap::Agx: return shader::TONEMAP_AGX;
    case Tonemap::None: break;
    }
    return shader::TONEMAP_NONE;
}

std::optional<Tonemap> tonemapFromName(std::string_view name) {
    if (name == "aces") {
        return Tonemap::AcesNarkowicz;   // the name before Hill's fit came: files and scripts keep their look
    }
    return enumFromName(name, kTonemaps, tonemapName);
}

std::string tonemapNames() {
    return enumNameList(kTonemaps, tonemapName);
}

std::string_view groundName(Ground ground) {
    switch (ground) {
    case Ground::None: return "none";
    case Ground::Shadow: return "shadow";
    case Ground::Floor: return "floor";
    }
    return "none";
}

std::optional<Ground> groundFromName(std::string_view name) {
    return enumFromName(name, kGrounds, groundName);
}

std::string groundNames() {
    return enumNameList(kGrounds, groundName);
}

const Light* enabledEnvironment(const std::vector<Light>& lights) {
    for (const Light& light : lights) {
        if (light.enabled && light.type == LightType::Environment) {
            return &light;
        }
    }
    return nullptr;
}

Scene defaultScene() {
    Scene scene;
    scene.material.name = "terracotta";

    Light key;
    key.type = LightType::Point;
    key.name = "warm key";
    key.color = {1.0f, 0.78f, 0.55f};
    // Up and to the right, between the camera and the sphere: inside the view, so its gizmo can
    // be seen and grabbed, and as bright on the sphere as the old key from outside the view.
    key.intensity = 5.0f;
    key.position = {0.6f, 0.8f, 1.6f};
    key.range = 12.0f;
    key.attenuation = {1.0f, 0.0f, 1.0f};

    Light fill;
    fill.type = LightType::Directional;
    fill.name = "cool fill";
    fill.color = {0.55f, 0.7f, 1.0f};
    fill.intensity = 2.0f;
    fill.direction = {1.0f, -0.35f, -0.6f};

    // The studio all around (Karis 2013's image-based lighting): what makes a metal read as metal.
    Light studio;
    studio.type = LightType::Environment;
    studio.name = "studio";
    studio.intensity = 0.8f;
    studio.source = builtinSource("studio");

    // A faint sky above and warm ground below (Karis's hemisphere light, diffuse only): every
    // light type of the model in one scene, each switchable.
    Light sky;
    sky.type = LightType::Hemisphere;
    sky.name = "sky";
    sky.intensity = 0.3f;
    sky.sky = {0.22f, 0.3f, 0.45f};
    sky.ground = {0.12f, 0.09f, 0.06f};

    scene.lights = {key, fill, studio, sky};
    // A tone map that keeps the highlights of metals and the key light (PBR Neutral leaves
    // colours below 0.8 as they are): one look wherever the default scene is shown.
    scene.display.tonemap = Tonemap::PbrNeutral;
    return scene;
}

}  // namespace patina
