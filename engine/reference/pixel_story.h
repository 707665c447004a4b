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
#include "shading/shading.h"

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
    std::string model;      // the BRDF model it is shaded with (shading/brdf_models.h)
    glm::vec3 position{0.0f}, view{0.0f};
    // Every channel's input at the pixel, under every light and the environment (channels.glsl):
    // the normals, UVs and tangent, the material after its maps, D, G and F towards the key
    // light (0 without one), the radiance (linear, before exposure).
    shader::ChannelInputs inputs{};
    std::string keyLight;   // its name, "" without one
    std::vector<LightShare> lights;            // each enabled light but the environment
    std::optional<LightShare> environment;     // the enabled environment light's split sum
    std::array<uint8_t, 3> display{};          // after exposure, tone map and sRGB, as a PNG holds it
    // KHR_materials_anisotropy's stretch where the part has one (after its map): the unit world
    // direction t it runs along (turned from the tangent, or from the fallback's where the mesh
    // has none: `inputs.tangent` is then 0), its strength and the roughness along and across it.
    struct Stretch {
        glm::vec3 direction{0.0f};
        float strength = 0.0f, alphaT = 0.0f, alphaB = 0.0f;
    };
    std::optional<Stretch> anisotropy;
};

// Pixel (x, y) of a surfaces.width x surfaces.height image of `prepared`, rows top first;
// nullopt where no item is (the background).
std::optional<PixelStory> pixelStory(const PreparedScene& prepared, const PixelSurfaces& surfaces, int x, int y);

}  // namespace patina
