#include "accuracy/edge_cases.h"

#include <cmath>

#include <glm/glm.hpp>

namespace patina {

namespace {
Light directionalFrom(glm::vec3 toLight) {
    Light light;
    light.type = LightType::Directional;
    light.direction = -toLight;
    light.intensity = 3.0f;
    return light;
}

Light pointAt(glm::vec3 position, float range, glm::vec3 attenuation) {
    Light light;
    light.type = LightType::Point;
    light.position = position;
    light.range = range;
    light.attenuation = attenuation;
    light.intensity = 5.0f;
    return light;
}

Light hemisphere() {
    Light light;
    light.type = LightType::Hemisphere;
    light.sky = {0.3f, 0.4f, 0.6f};
    light.ground = {0.2f, 0.1f, 0.05f};
    return light;
}

Light sphereAt(glm::vec3 centre, float radius, float range) {
    Light light = pointAt(centre, range, {1, 0, 1});
    light.type = LightType::Sphere;
    light.sourceRadius = radius;
    return light;
}

Light tubeFrom(glm::vec3 start, glm::vec3 end, float radius) {
    Light light = pointAt(start, 5, {0, 0, 1});
    light.type = LightType::Tube;
    light.start = start;
    light.end = end;
    light.sourceRadius = radius;
    return light;
}

Material roughMaterial(float roughness, float metallic = 0.0f) {
    Material material;
    material.roughness = roughness;
    material.metallic = metallic;
    material.baseColor = {0.9f, 0.6f, 0.3f};
    return material;
}
}  // namespace

std::vector<EdgeCase> edgeCases() {
    const glm::vec3 up(0.0f, 0.0f, 1.0f);
    const float grazing[] = {0.0f, 1e-7f, 1e-5f, 1e-3f, 0.01f, 0.5f, 1.0f};
    std::vector<EdgeCase> cases;

    // Roughness 0 (D = 0/0 at NoH = 1) down to the fp32 floor, with mirror-aligned L and V
    // at every grazing angle: NoV and NoL = 0 included.
    for (float roughness : {0.0f, 1e-6f, 1e-4f, 1e-3f, 0.01f, 0.045f, 0.089f}) {
        EdgeCase edge{"roughness " + std::to_string(roughness), roughMaterial(roughness, 0.5f),
                      {directionalFrom(up), hemisphere()}, {}};
        for (float cosine : grazing) {
            const float sine = std::sqrt(1.0f - cosine * cosine);
            const glm::vec3 V(sine, 0.0f, cosine), L(-sine, 0.0f, cosine);
            edge.lights[0] = directionalFrom(L);
            edge.samples.push_back({glm::vec3(0.0f), up, V});
        }
        // NoH = 1 exactly: V = L = N.
        edge.samples.push_back({glm::vec3(0.0f), up, up});
        cases.push_back(edge);
    }
    for (float cosine : grazing) {
        const float sine = std::sqrt(1.0f - cosine * cosine);
        cases.push_back({"NoL " + std::to_string(cosine), roughMaterial(0.3f),
                         {directionalFrom({sine, 0.0f, cosine})},
                         {{glm::vec3(0.0f), up, glm::normalize(glm::vec3(-0.3f, 0.0f, 1.0f))}}});
        cases.push_back({"NoV " + std::to_string(cosine), roughMaterial(0.3f),
                         {directionalFrom(glm::normalize(glm::vec3(0.3f, 0.0f, 1.0f)))},
                         {{glm::vec3(0.0f), up, {-sine, 0.0f, cosine}}}});
    }
    // L = -V: H = 0/0. Needs V below the surface so that NoL > 0.
    const glm::vec3 below = glm::normalize(glm::vec3(0.2f, 0.1f, -0.9f));
    cases.push_back({"L = -V", roughMaterial(0.3f), {directionalFrom(-below)},
                     {{glm::vec3(0.0f), up, below}}});
    // VoH a rounding step past 1.
    cases.push_back({"V = L = N", roughMaterial(0.05f), {directionalFrom(up)},
                     {{glm::vec3(0.0f), up, up}}});
    // Zero normal: no direction to shade against.
    cases.push_back({"zero normal", roughMaterial(0.3f),
                     {directionalFrom(up), pointAt({0, 0, 1}, 5, {1, 0, 1}), hemisphere()},
                     {{glm::vec3(0.0f), glm::vec3(0.0f), up}}});
    // Zero view vector.
    cases.push_back({"zero view", roughMaterial(0.3f), {directionalFrom(up)},
                     {{glm::vec3(0.0f), up, glm::vec3(0.0f)}}});
    // A point light exactly at the shaded point, with and without a constant term.
    cases.push_back({"light at the surface", roughMaterial(0.3f),
                     {pointAt({1, 2, 3}, 5, {1, 0, 1}), pointAt({1, 2, 3}, 5, {0, 0, 1})},
                     {{glm::vec3(1, 2, 3), up, up}}});
    // Radius 0 (no window), all attenuation terms 0, and both together.
    cases.push_back({"range 0", roughMaterial(0.3f), {pointAt({0, 0, 2}, 0, {1, 0, 1})},
                     {{glm::vec3(0.0f), up, up}}});
    cases.push_back({"zero attenuation", roughMaterial(0.3f), {pointAt({0, 0, 2}, 5, {0, 0, 0})},
                     {{glm::vec3(0.0f), up, up}}});
    cases.push_back({"range 0 and zero attenuation", roughMaterial(0.3f),
                     {pointAt({0, 0, 1e-3f}, 0, {0, 0, 0})},
                     {{glm::vec3(0.0f), up, up}}});
    return cases;
}

std::vector<EdgeCase> areaLightEdgeCases() {
    const glm::vec3 up(0.0f, 0.0f, 1.0f);
    std::vector<EdgeCase> cases;
    const glm::vec3 grazingView = glm::normalize(glm::vec3(1.0f, 0.0f, 1e-4f));
    const std::pair<const char*, Light> areaLights[] = {
        {"sphere radius above the range", sphereAt({0, 0, 1}, 20, 12)},
        {"sphere radius 0", sphereAt({0, 0, 1}, 0, 5)},
        {"inside a sphere", sphereAt({0, 0, 0.1f}, 0.5f, 5)},
        {"sphere centre on the point", sphereAt({0, 0, 0}, 0.5f, 5)},
        {"sphere through the surface", sphereAt({0.3f, 0, -0.2f}, 0.5f, 5)},
        {"sphere behind the surface", sphereAt({0, 0, -2}, 0.5f, 5)},
        {"tube of length 0", tubeFrom({0, 0, 1}, {0, 0, 1}, 0.3f)},
        {"tube ends 1e-6 apart", tubeFrom({0, 0, 1}, {1e-6f, 0, 1}, 0.3f)},
        {"tube of radius 0", tubeFrom({-1, 0, 1}, {1, 0, 1}, 0)},
        {"tube through the point", tubeFrom({-1, 0, 0}, {1, 0, 0}, 0.1f)},
        {"tube through the surface", tubeFrom({-1, 0, -1}, {1, 0, 1}, 0.2f)},
        {"tube end on the point", tubeFrom({0, 0, 0}, {0, 0, 1}, 0.1f)},
        {"tube behind the surface", tubeFrom({-1, 0, -1}, {1, 0, -1}, 0.2f)},
    };
    for (const auto& [name, light] : areaLights) {
        for (float roughness : {0.0f, 0.5f}) {
            cases.push_back({std::string(name) + ", roughness " + std::to_string(roughness), roughMaterial(roughness),
                             {light},
                             {{glm::vec3(0.0f), up, up}, {glm::vec3(0.0f), up, grazingView},
                              {glm::vec3(0.0f), glm::vec3(0.0f), up}}});
        }
    }
    return cases;
}

}  // namespace patina
