#pragma once
// PBR validation, as Substance's PBR Validate does it (Allegorithmic, "The PBR Guide" vol. 2,
// "Base Color" and "Metal Reflectance"; the PBR Validate filter's ranges): a dielectric's albedo
// darker than charcoal or brighter than fresh snow, or a metal reflecting less than any measured
// metal, is not a material light meets in the world. The value checked is the base colour's
// luminance (Rec. 709, of the linear colour) in sRGB 0-255: the lightness the ranges are given in.
// The verdict is shaders/shared/channels.glsl's pbrVerdict, which the pbr-validation channel
// draws with.
#include <cstddef>

#include <glm/vec3.hpp>

#include "model/model.h"

namespace patina {

struct PbrRanges {
    int dielectricMin = 30;    // albedo, sRGB
    int dielectricMax = 240;
    int metalMin = 155;        // reflectance, sRGB: 60% (strict: 180, 70%)
    static PbrRanges strict() { return {50, 240, 180}; }
    // As the shaders take them (channels.glsl's pbrVerdict).
    glm::vec3 asVector() const { return glm::vec3(float(dielectricMin), float(dielectricMax), float(metalMin)); }
};

enum class PbrVerdict { Ok, DielectricTooDark, DielectricTooBright, MetalTooDark };

// A surface is judged a metal from metallic 0.5 up (a texel between the two is a transition a
// mask blends; a whole material there is flagged as partly metal by the caller).
// A dielectric that transmits (KHR_materials_transmission, `transmission` > 0) passes that share
// of its base colour's light through: its bright end is judged on the share it reflects,
// c_base (1 - transmission), its dark end on the whole colour (channels.glsl's pbrVerdict).
struct PbrCheck {
    bool metal = false;
    int value = 0;   // the luminance, sRGB-encoded, 0-255
    int reflected = 0;   // the same of c_base (1 - transmission): `value` for an opaque part
    PbrVerdict verdict = PbrVerdict::Ok;
};
PbrCheck checkBaseColor(glm::vec3 linearBaseColor, float metallic, float transmission, const PbrRanges& ranges);

// The texels of `material`'s base colour map, each as the shader reads it (the factor times the
// sRGB-decoded texel; metallic the factor times the metallic-roughness map's blue, the
// transmission the factor times its map's red, at the same place, nearest), counted by verdict.
// All zero for a material without a base colour map.
struct PbrTally {
    size_t texels = 0, dielectricDark = 0, dielectricBright = 0, metalDark = 0;
    size_t flagged() const { return dielectricDark + dielectricBright + metalDark; }
};
PbrTally checkBaseColorTexels(const Model& model, const ModelMaterial& material, const PbrRanges& ranges);

}  // namespace patina
