// The inspector's debug channels (docs/INSPECTOR.md): what the shader computed at a pixel, as
// data. Shared GLSL / C++ like brdf.glsl (include after it, clearcoat.glsl, sheen.glsl,
// transmission.glsl and display.glsl): shade.frag with PATINA_CHANNEL
// writes channelValue instead of the radiance, and the CPU twin (engine/reference/channels.h)
// calls the same function on the same inputs, so the two cannot drift.

// The channels, in docs/INSPECTOR.md's order (engine/shading/channels.h names them).
const int CHANNEL_BASE_COLOR = 0;
const int CHANNEL_ALPHA = 1;
const int CHANNEL_METALLIC = 2;
const int CHANNEL_ROUGHNESS = 3;
const int CHANNEL_SPECULAR = 4;
const int CHANNEL_F0 = 5;
const int CHANNEL_DIFFUSE_COLOR = 6;
const int CHANNEL_OCCLUSION = 7;
const int CHANNEL_EMISSIVE = 8;
const int CHANNEL_UV0 = 9;
const int CHANNEL_UV1 = 10;
const int CHANNEL_GEOMETRY_NORMAL = 11;
const int CHANNEL_SHADING_NORMAL = 12;
const int CHANNEL_TANGENT = 13;
const int CHANNEL_BITANGENT_SIGN = 14;
const int CHANNEL_NOV = 15;
const int CHANNEL_D = 16;
const int CHANNEL_G = 17;
const int CHANNEL_F = 18;
const int CHANNEL_DIFFUSE = 19;
const int CHANNEL_SPECULAR_LIGHTING = 20;
const int CHANNEL_ENVIRONMENT_DIFFUSE = 21;
const int CHANNEL_ENVIRONMENT_SPECULAR = 22;
const int CHANNEL_LIGHT = 23;
const int CHANNEL_INVALID = 24;
const int CHANNEL_PBR_VALIDATION = 25;
const int CHANNEL_CLEARCOAT = 26;   // the layers' own light (docs/SHADING.md S5, S6, S7)
const int CHANNEL_SHEEN = 27;
const int CHANNEL_TRANSMISSION = 28;
const int CHANNEL_COUNT = 29;

// Everything a pixel's channels read. The material is after its maps (factor times texel) and
// before the roughness floor; F0 and the diffuse colour are deriveSurfaceMaterial's. The lighting
// is linear radiance towards the viewer: `diffuse` and `specularLighting` are every light's and
// the environment's lobes (occlusion applied), so diffuse + specularLighting + emission is the
// radiance the pixel shows.
struct ChannelInputs {
    vec3 baseColor;
    real alpha;
    real metallic;
    real roughness;
    real specular;
    vec3 specularTint;     // KHR_materials_specular's (withSpecular; 1 without)
    real specularWeight;
    vec3 f0;               // the lobe's F0, mix(w F0_dielectric, c_base, m)
    vec3 diffuseColor;
    real occlusion;
    vec3 emission;
    vec2 uv0;
    vec2 uv1;
    vec3 geometryNormal;   // unit, interpolated, reversed on a double-sided back face
    vec3 shadingNormal;    // after the normal map
    vec4 tangent;          // xyz unit, w the bitangent's sign; 0 where there is none
    real NoV;              // max(N.V, MIN_N_DOT_V) with the shading normal, as the BRDF reads it
    real D;                // the key light's (inspectedTerms, brdf_model.glsl)
    real G;
    vec3 F;
    vec3 diffuse;
    vec3 specularLighting;
    vec3 environmentDiffuse;
    vec3 environmentSpecular;
    vec3 light;            // the one light asked for, both lobes
    vec3 radiance;         // what the pixel shows, before exposure
    // The layers (ChannelLayers): the coat's own lobe (clearcoat fr_c D V, every light and the
    // environment's split sum), the sheen's (f_sheen, every light and the environment's
    // irradiance share) and the light through the wall (transmission.glsl's f_t from every light
    // behind, the environment along -V), as they add to the radiance; 0 for a part without the
    // layer. The base's lobes above are what the base reflects beneath them (a transmission's
    // diffuse reduced by transmissionDiffuse), and the transmission what passes the wall as it
    // adds beneath the coat (channelFinished weighs it by a sheen's albedo scaling).
    vec3 clearcoat;
    vec3 sheen;
    vec3 transmission;
    vec3 layeredLighting;   // every light's and the environment's base and sheen, the sheen's albedo scaling applied
};

// The layers over the inspected surface, derived as shade.frag derives them (deriveClearcoat on
// the coat's normal, deriveSheen and deriveTransmission on the shading normal), and whether the
// part has each; `transmissionFactor` the diffuse's share that passes (transmissionDiffuse).
struct ChannelLayers {
    bool coated;
    Clearcoat coat;
    bool sheened;
    Sheen sheen;
    bool transmits;
    real transmissionFactor;
    Transmission transmission;
    // KHR_materials_iridescence's film on the base (withIridescence's three; strength 0: none).
    real iridescence;
    real iridescenceIor;
    real iridescenceThickness;
    // KHR_materials_anisotropy's stretch of the base's lobe (withAnisotropy's arguments, where the
    // part has the layer): (cos, sin) of its direction and its strength, after the map, and the
    // tangent it turns from (w = 0: none, the fallback's).
    bool anisotropic;
    vec3 anisotropy;
    vec4 anisotropyTangent;
};

// A part without layers (the fields are not read).
PATINA_INLINE ChannelLayers noChannelLayers() {
    return ChannelLayers(false, Clearcoat(0.0f, 0.0f, 0.0f, vec3(0.0f), 1.0f, 0.0f), false,
                         Sheen(vec3(0.0f), 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f), false, 0.0f,
                         Transmission(vec3(0.0f), vec3(0.0f), 1.0f, 1.0f, 1.0f, vec3(0.0f), 0.0f), 0.0f, 1.3f,
                         0.0f, false,
                         vec3(1.0f, 0.0f, 0.0f), vec4(0.0f));
}

// One light's light through the wall (transmission.glsl's transmissionLight; a hemisphere
// light's occluded as the renderer occludes it); 0 without a transmission.
PATINA_INLINE vec3 channelTransmissionOfLight(ChannelInputs c, ChannelLayers layers, PackedLight light, vec3 P,
                                              vec3 V) {
    if (!layers.transmits) {
        return vec3(0.0f);
    }
    vec3 through = transmissionLight(light, layers.transmission, P, c.shadingNormal, V);
    return light.type == LIGHT_HEMISPHERE ? c.occlusion * through : through;
}

// One light's layers at P over `base`, that light's lobes on the base (occlusion applied): the
// sheen's lobe added and the base weighed by the sheen's albedo scaling (sheen.glsl's sheenLight,
// a hemisphere light's occluded as the renderer occludes it), the coat's lobe added
// (clearcoat.glsl's clearcoatLight), the light through the wall added beside the base
// (channelTransmissionOfLight). The coat's weight on the base is channelFinished's.
PATINA_INLINE ChannelInputs channelLayersOfLight(ChannelInputs c, ChannelLayers layers, PackedLight light, vec3 base,
                                                 vec3 P, vec3 V) {
    if (layers.sheened) {
        SheenShare share = sheenLight(light, layers.sheen, P, c.shadingNormal, V);
        if (light.type == LIGHT_HEMISPHERE) {
            share.sheen = c.occlusion * share.sheen;
        }
        c.sheen = c.sheen + share.sheen;
        base = sheenOver(base, share);
    }
    if (layers.coated) {
        c.clearcoat = c.clearcoat + clearcoatLight(light, layers.coat, P, V);
    }
    c.transmission = c.transmission + channelTransmissionOfLight(c, layers, light, P, V);
    c.layeredLighting = c.layeredLighting + base;
    return c;
}

// Whether the channel holds signed unit vectors (normals, tangent, handedness).
PATINA_INLINE bool channelIsSigned(int channel) {
    return channel == CHANNEL_GEOMETRY_NORMAL || channel == CHANNEL_SHADING_NORMAL || channel == CHANNEL_TANGENT ||
           channel == CHANNEL_BITANGENT_SIGN;
}

// A channel's value as a display shows it, data not light: no exposure, no tone map; a signed
// vector as v / 2 + 1/2; clamped to [0, 1] with NaN as 0; sRGB-encoded only when asked (for
// looking at colours). The GPU's display image and `render --channel`'s PNG both.
PATINA_INLINE real shownChannelComponent(real value, bool signedValue, bool srgb) {
    real v = signedValue ? value * 0.5f + 0.5f : value;
    v = v >= 0.0f ? min(v, 1.0f) : 0.0f;   // NaN fails the test
    return srgb ? srgbEncode(v) : v;
}

PATINA_INLINE vec3 shownChannel(int channel, vec3 value, bool srgb) {
    bool signedValue = channelIsSigned(channel);
    return vec3(shownChannelComponent(value.x, signedValue, srgb), shownChannelComponent(value.y, signedValue, srgb),
                shownChannelComponent(value.z, signedValue, srgb));
}

// 1 where any component of v is NaN, infinite or negative, respectively.
PATINA_INLINE vec3 invalidRadiance(vec3 v) {
    bool nan = isnan(v.x) || isnan(v.y) || isnan(v.z);
    bool infinite = isinf(v.x) || isinf(v.y) || isinf(v.z);
    bool negative = v.x < 0.0f || v.y < 0.0f || v.z < 0.0f;
    return vec3(nan ? 1.0f : 0.0f, infinite ? 1.0f : 0.0f, negative ? 1.0f : 0.0f);
}

// PBR validation, as Substance's PBR Validate judges a base colour (Allegorithmic, "The PBR
// Guide" vol. 2, "Base Color" and "Metal Reflectance"; model/pbr_validation.h has the ranges and
// the batch check, which calls these): the colour's luminance, sRGB-encoded to 0-255, against a
// dielectric's range (charcoal to fresh snow) or the darkest measured metal's reflectance. A
// surface is a metal from metallic 0.5 up. `ranges`: (dielectric min, dielectric max, metal min).
const int PBR_OK = 0;
const int PBR_DIELECTRIC_TOO_DARK = 1;
const int PBR_DIELECTRIC_TOO_BRIGHT = 2;
const int PBR_METAL_TOO_DARK = 3;

// The lightness the ranges are given in: 255 sRGB(Y), rounded to a whole step.
PATINA_INLINE real pbrLightness(vec3 linearBaseColor) {
    return floor(255.0f * srgbEncode(clamp(rec709Luminance(linearBaseColor), 0.0f, 1.0f)) + 0.5f);
}

// A thin wall's transmission (KHR_materials_transmission) passes that share of the base colour's
// light through the surface: it is not albedo, which the dielectric's upper bound is about
// (a clear glass is white and absorbs nothing). So the bright end judges `reflectedLightness`,
// the lightness of c_base (1 - transmission), and the dark end the whole colour's.
PATINA_INLINE int pbrVerdict(real lightness, real reflectedLightness, bool metal, vec3 ranges) {
    if (metal) {
        return lightness < ranges.z ? PBR_METAL_TOO_DARK : PBR_OK;
    }
    return lightness < ranges.x           ? PBR_DIELECTRIC_TOO_DARK
           : reflectedLightness > ranges.y ? PBR_DIELECTRIC_TOO_BRIGHT
                                           : PBR_OK;
}

// The channel's flag colours: only 0s and 1s, so they survive sRGB encoding and 8 bits exactly
// and no grey (an accepted pixel) is one of them.
PATINA_INLINE vec3 pbrVerdictColour(int verdict) {
    if (verdict == PBR_DIELECTRIC_TOO_DARK) return vec3(0.0f, 0.0f, 1.0f);     // blue: darker than charcoal
    if (verdict == PBR_DIELECTRIC_TOO_BRIGHT) return vec3(1.0f, 0.0f, 0.0f);   // red: brighter than snow
    return vec3(1.0f, 1.0f, 0.0f);                                              // yellow: too dark a metal
}

// CHANNEL_PBR_VALIDATION: a flagged pixel in its verdict's colour; an accepted one grey, the
// lightness the check read (lightness / 255, so the PNG's byte is the number). `transmission`:
// the share a thin wall passes (pbrVerdict), 0 for an opaque part.
PATINA_INLINE vec3 pbrValidationValue(vec3 baseColor, real metallic, real transmission, vec3 ranges) {
    real lightness = pbrLightness(baseColor);
    int verdict = pbrVerdict(lightness, pbrLightness((1.0f - transmission) * baseColor), metallic >= 0.5f, ranges);
    return verdict == PBR_OK ? vec3(lightness / 255.0f) : pbrVerdictColour(verdict);
}

// The channel's value: a colour or vector as it is (normals in [-1, 1], UVs as (u, v, 0)), a
// scalar in all three components. `pbrRanges`: CHANNEL_PBR_VALIDATION's (pbrVerdict), which
// reads the layers' transmission.
PATINA_INLINE vec3 channelValue(int channel, ChannelInputs c, ChannelLayers layers, vec3 pbrRanges) {
    if (channel == CHANNEL_BASE_COLOR) return c.baseColor;
    if (channel == CHANNEL_ALPHA) return vec3(c.alpha);
    if (channel == CHANNEL_METALLIC) return vec3(c.metallic);
    if (channel == CHANNEL_ROUGHNESS) return vec3(c.roughness);
    if (channel == CHANNEL_SPECULAR) return vec3(c.specular);
    if (channel == CHANNEL_F0) return c.f0;
    if (channel == CHANNEL_DIFFUSE_COLOR) return c.diffuseColor;
    if (channel == CHANNEL_OCCLUSION) return vec3(c.occlusion);
    if (channel == CHANNEL_EMISSIVE) return c.emission;
    if (channel == CHANNEL_UV0) return vec3(c.uv0.x, c.uv0.y, 0.0f);
    if (channel == CHANNEL_UV1) return vec3(c.uv1.x, c.uv1.y, 0.0f);
    if (channel == CHANNEL_GEOMETRY_NORMAL) return c.geometryNormal;
    if (channel == CHANNEL_SHADING_NORMAL) return c.shadingNormal;
    if (channel == CHANNEL_TANGENT) return vec3(c.tangent.x, c.tangent.y, c.tangent.z);
    if (channel == CHANNEL_BITANGENT_SIGN) return vec3(c.tangent.w);
    if (channel == CHANNEL_NOV) return vec3(c.NoV);
    if (channel == CHANNEL_D) return vec3(c.D);
    if (channel == CHANNEL_G) return vec3(c.G);
    if (channel == CHANNEL_F) return c.F;
    if (channel == CHANNEL_DIFFUSE) return c.diffuse;
    if (channel == CHANNEL_SPECULAR_LIGHTING) return c.specularLighting;
    if (channel == CHANNEL_ENVIRONMENT_DIFFUSE) return c.environmentDiffuse;
    if (channel == CHANNEL_ENVIRONMENT_SPECULAR) return c.environmentSpecular;
    if (channel == CHANNEL_LIGHT) return c.light;
    if (channel == CHANNEL_PBR_VALIDATION) {
        return pbrValidationValue(c.baseColor, c.metallic, layers.transmits ? layers.transmissionFactor : 0.0f,
                                  pbrRanges);
    }
    if (channel == CHANNEL_CLEARCOAT) return c.clearcoat;
    if (channel == CHANNEL_SHEEN) return c.sheen;
    if (channel == CHANNEL_TRANSMISSION) return c.transmission;
    return invalidRadiance(c.radiance);
}
