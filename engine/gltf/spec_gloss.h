#pragma once
// KHR_materials_pbrSpecularGlossiness (archived; superseded by KHR_materials_specular) read as
// metallic-roughness by the Khronos conversion: the extension's own example,
// extensions/2.0/Archived/KHR_materials_pbrSpecularGlossiness/examples/convert-between-workflows
// (ConvertToMetallicRoughness), in linear values, per texel where the material has maps.
// docs/FORMATS.md ("Specular-glossiness") writes the formulas out.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "model/model.h"

namespace patina::gltf {

struct SpecularGlossiness {
    glm::vec3 diffuse{1.0f};   // linear
    float alpha = 1.0f;
    glm::vec3 specular{1.0f};   // linear F0
    float glossiness = 1.0f;
};

struct MetallicRoughness {
    glm::vec3 baseColor{1.0f};   // linear
    float alpha = 1.0f;
    float metallic = 0.0f;
    float roughness = 1.0f;
};

// sqrt(0.299 r^2 + 0.587 g^2 + 0.114 b^2): the example's perceived brightness.
float perceivedBrightness(glm::vec3 c);

// The metallic m where the dielectric (F0 0.04) and the metal (F0 the base colour) mixed by m
// reflect `specular` while the diffuse reflects `diffuse` (both perceived brightnesses): the
// root of 0.04 m^2 + b m + c = 0, b = diffuse (1 - maxSpecular) / 0.96 + specular - 0.08,
// c = 0.04 - specular; 0 for a specular below a dielectric's 0.04.
float solveMetallic(float diffuse, float specular, float oneMinusSpecularStrength);

MetallicRoughness metallicRoughnessFrom(const SpecularGlossiness& material);

// A material of the file that uses the extension, as read: its factors. Its two maps are the
// material's own slots until converted, decoded with the other maps: baseColor holds the
// diffuse map (sRGB RGBA, multiplies diffuse and alpha), metallicRoughness the
// specular-glossiness map (sRGB RGB the specular, linear A the glossiness).
struct SpecGlossMaterial {
    int material = 0;
    SpecularGlossiness factors;
};

// Sets each listed material's factors and maps to the conversion's: factors alone convert
// once; where there are maps the conversion runs per texel of the larger map (the other read
// at the same place) into two new images of `model`, a base colour map and a
// metallic-roughness one, the factors then 1. Adds a note for each material converted. Maps
// whose baking would take the model's decoded images past `budget` bytes (docs/FORMATS.md's
// limit) convert by their factors alone, which the note says.
void convertSpecularGlossiness(Model& model, const std::vector<SpecGlossMaterial>& materials,
                               uint64_t budget = uint64_t(512) << 20);

}  // namespace patina::gltf
