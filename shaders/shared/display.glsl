// Display transform: linear HDR -> exposure -> tone map -> sRGB (shared GLSL / C++).

const int TONEMAP_NONE = 0;      // clamp to [0, 1]
const int TONEMAP_ACES = 1;
const int TONEMAP_REINHARD = 2;
const int TONEMAP_PBR_NEUTRAL = 3;

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": a rational fit of the ACES RRT + ODT,
// x (a x + b) / (x (c x + d) + e) with a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14.
PATINA_INLINE vec3 tonemapAcesNarkowicz(vec3 x) {
    vec3 numerator = x * (2.51f * x + vec3(0.03f));
    vec3 denominator = x * (2.43f * x + vec3(0.59f)) + vec3(0.14f);
    return clamp(numerator / denominator, vec3(0.0f), vec3(1.0f));
}

// Reinhard et al. 2002, "Photographic Tone Reproduction for Digital Images", eq. 3: x / (1 + x).
PATINA_INLINE vec3 tonemapReinhard(vec3 x) {
    return x / (vec3(1.0f) + x);
}

// Khronos PBR Neutral (Khronos 3D Commerce, "PBR Neutral Tone Mapping", 2024): colours up to
// 0.8 pass through but for a small offset that lifts blacks a little less than they are,
// brighter ones compress towards 1 and desaturate towards white, so a highlight keeps its hue
// until it turns white. Constants and steps as published.
PATINA_INLINE vec3 tonemapPbrNeutral(vec3 color) {
    const real startCompression = 0.8f - 0.04f;
    const real desaturation = 0.15f;
    real x = min(color.x, min(color.y, color.z));
    real offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    color = color - vec3(offset);
    real peak = max(color.x, max(color.y, color.z));
    if (peak < startCompression) {
        return color;
    }
    const real d = 1.0f - startCompression;
    real newPeak = 1.0f - d * d / (peak + d - startCompression);
    color = color * (newPeak / peak);
    real g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
    return mix(color, vec3(newPeak), g);
}

// Luminance of a linear colour with the Rec. 709 primaries (ITU-R BT.709-6, part 1, item 3.2):
// the shaders' copy of common/luminance.h, which a test holds it to.
PATINA_INLINE real rec709Luminance(vec3 linear) {
    return 0.2126f * linear.x + 0.7152f * linear.y + 0.0722f * linear.z;
}

// IEC 61966-2-1 sRGB encoding of one channel in [0, 1].
PATINA_INLINE real srgbEncode(real linear) {
    if (linear <= 0.0031308f) {
        return 12.92f * linear;
    }
    return 1.055f * exp2(log2(linear) / 2.4f) - 0.055f;
}

// Inverse of srgbEncode (IEC 61966-2-1), for colour pickers that show sRGB and store linear.
PATINA_INLINE real srgbDecode(real encoded) {
    if (encoded <= 0.04045f) {
        return encoded / 12.92f;
    }
    return exp2(2.4f * log2((encoded + 0.055f) / 1.055f));
}

// A colour in [0, 1] (clamped), sRGB-encoded: what a colour field or swatch shows. The flat
// background is shown so, as a colour picked on screen rather than radiance in the scene:
// neither exposure nor the tone map applies to it. (The environment shown as background is
// radiance and goes through displayTransform like the mesh.)
PATINA_INLINE vec3 srgbColor(vec3 linear) {
    vec3 c = clamp(linear, vec3(0.0f), vec3(1.0f));
    return vec3(srgbEncode(c.x), srgbEncode(c.y), srgbEncode(c.z));
}

// Exposure in stops (x 2^exposure), then the tone map, then sRGB. Negative or NaN radiance
// (never produced by the shading guards, but possible from a bad HDR input) displays as 0.
PATINA_INLINE vec3 displayTransform(vec3 linear, real exposureStops, int tonemap) {
    vec3 exposed = max(linear * exp2(exposureStops), vec3(0.0f));
    vec3 mapped;
    if (tonemap == TONEMAP_ACES) {
        mapped = tonemapAcesNarkowicz(exposed);
    } else if (tonemap == TONEMAP_REINHARD) {
        mapped = clamp(tonemapReinhard(exposed), vec3(0.0f), vec3(1.0f));
    } else if (tonemap == TONEMAP_PBR_NEUTRAL) {
        mapped = clamp(tonemapPbrNeutral(exposed), vec3(0.0f), vec3(1.0f));
    } else {
        mapped = clamp(exposed, vec3(0.0f), vec3(1.0f));
    }
    return vec3(srgbEncode(mapped.x), srgbEncode(mapped.y), srgbEncode(mapped.z));
}
