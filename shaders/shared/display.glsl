// Display transform: linear HDR -> exposure -> tone map -> sRGB (shared GLSL / C++).

const int TONEMAP_NONE = 0;      // clamp to [0, 1]
const int TONEMAP_ACES = 1;
const int TONEMAP_REINHARD = 2;

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

// Exposure in stops (x 2^exposure), then the tone map, then sRGB. Negative or NaN radiance
// (never produced by the shading guards, but possible from a bad HDR input) displays as 0.
PATINA_INLINE vec3 displayTransform(vec3 linear, real exposureStops, int tonemap) {
    vec3 exposed = max(linear * exp2(exposureStops), vec3(0.0f));
    vec3 mapped;
    if (tonemap == TONEMAP_ACES) {
        mapped = tonemapAcesNarkowicz(exposed);
    } else if (tonemap == TONEMAP_REINHARD) {
        mapped = clamp(tonemapReinhard(exposed), vec3(0.0f), vec3(1.0f));
    } else {
        mapped = clamp(exposed, vec3(0.0f), vec3(1.0f));
    }
    return vec3(srgbEncode(mapped.x), srgbEncode(mapped.y), srgbEncode(mapped.z));
}
