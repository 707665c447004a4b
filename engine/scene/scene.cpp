#include "scene/scene.h"

#include "common/enum_names.h"

namespace patina {

std::string_view tonemapName(Tonemap tonemap) {
    switch (tonemap) {
    case Tonemap::None: return "none";
    case Tonemap::Aces: return "aces";
    case Tonemap::Reinhard: return "reinhard";
    case Tonemap::PbrNeutral: return "pbr-neutral";
    }
    return "none";
}

std::optional<Tonemap> tonemapFromName(std::string_view name) {
    static const Tonemap all[] = {Tonemap::None, Tonemap::Aces, Tonemap::Reinhard, Tonemap::PbrNeutral};
    return enumFromName(name, all, tonemapName);
}

Scene defaultScene() {
    Scene scene;
    scene.material.name = "terracotta";

    Light key;
    key.type = LightType::Point;
    key.name = "warm key";
    key.color = {1.0f, 0.78f, 0.55f};
    key.intensity = 16.0f;
    key.position = {2.2f, 2.0f, 2.4f};
    key.range = 12.0f;
    key.attenuation = {1.0f, 0.0f, 1.0f};

    Light fill;
    fill.type = LightType::Directional;
    fill.name = "cool fill";
    fill.color = {0.55f, 0.7f, 1.0f};
    fill.intensity = 2.0f;
    fill.direction = {1.0f, -0.35f, -0.6f};

    Light sky;
    sky.type = LightType::Hemisphere;
    sky.name = "sky";
    sky.intensity = 0.8f;
    sky.sky = {0.22f, 0.3f, 0.45f};
    sky.ground = {0.12f, 0.09f, 0.06f};

    scene.lights = {key, fill, sky};
    return scene;
}

}  // namespace patina
