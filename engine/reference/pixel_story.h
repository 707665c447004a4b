#pragma once
// The inspector's pixel read-out (docs/INSPECTOR.md): everything that gives one pixel its
// colour, from the CPU twin at the surface under the pixel's centre (channel_image.h) through the
// shared shader code. `patina inspect` prints it as JSON; the editor's hover and pins show it.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "reference/pixel_surfaces.h"
#include "scene/prepared_scene.h"

namespace patina {

// One light's share of the pixel's radiance (occlusion applied where the renderer applies it).
struct LightShare {
    std::string name;
    std::string type;   // lightTypeName
    glm::vec3 diffuse{0.0f}, specular{0.0f};
};

struct PixelStory {
    int x = 0, y = 0;
    std::string item;       // the draw item's name (a model's node and part), "" for a built-in mesh
    std::string material;   // its material's name, "" where it has none
    glm::vec3 position{0.0f}, geometryNormal{0.0f}, normal{0.0f}, view{0.0f};
    glm::vec2 uv0{0.0f}, uv1{0.0f};
    glm::vec4 tangent{0.0f};
    // The material after its maps: channels.glsl's ChannelInputs.
    glm::vec3 baseColor{0.0f}, f0{0.0f}, diffuseColor{0.0f}, emission{0.0f};
    float alpha = 1.0f, roughness = 0.0f, metallic = 0.0f, specular = 0.0f, occlusion = 1.0f;
    float NoV = 0.0f, D = 0.0f, G = 0.0f;   // D, G and F towards the key light (none: 0)
    glm::vec3 F{0.0f};
    std::string keyLight;   // its name, "" without one
    std::vector<LightShare> lights;            // each enabled light but the environment
    std::optional<LightShare> environment;     // the enabled environment light's split sum
    glm::vec3 radiance{0.0f};                  // linear, before exposure
    std::array<uint8_t, 3> display{};          // after exposure, tone map and sRGB, as a PNG holds it
};

// Pixel (x, y) of a surfaces.width x surfaces.height image of `prepared`, rows top first;
// nullopt where no item is (the background).
std::optional<PixelStory> pixelStory(const PreparedScene& prepared, const PixelSurfaces& surfaces, int x, int y);

}  // namespace patina
