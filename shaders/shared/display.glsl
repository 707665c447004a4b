// Display transform: linear HDR -> exposure -> tone map -> sRGB (shared GLSL / C++).

const int TONEMAP_NONE = 0;      // clamp to [0, 1]
const int TONEMAP_ACES_NARKOWICZ = 1;
const int TONEMAP_REINHARD = 2;
const int TONEMAP_PBR_NEUTRAL = 3;
const int TONEMAP_ACES_HILL = 4;
const int TONEMAP_AGX = 5;

// A 3 x 3 matrix given by its rows times a column vector: written so, the published row-major
// matrices read the same here as on paper, in GLSL and in C++ alike.
PATINA_INLINE vec3 byRows(vec3 row0, vec3 row1, vec3 row2, vec3 v) {
    return vec3(dot(row0, v), dot(row1, v), dot(row2, v));
}

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": a rational fit of the ACES RRT + ODT,
// x (a x + b) / (x (c x + d) + e) with a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14.
PATINA_INLINE vec3 tonemapAcesNarkowicz(vec3 x) {
    vec3 numerator = x * (2.51f * x + vec3(0.03f));
    vec3 denominator = x * (2.43f * x + vec3(0.59f)) + vec3(0.14f);
    return clamp(numerator / denominator, vec3(0.0f), vec3(1.0f));
}

// Stephen Hill's fit of the ACES 1.0 RRT + sRGB ODT (Pettineo's BakingLab, ACES.hlsl, 2016) as
// three.js applies it (ACESFilmicToneMapping) and the Khronos glTF Sample Viewer does ("ACES
// Hill exposure boost"): x / 0.6 (three.js pull request 19621: Narkowicz's exposure, so that it
// reads as bright as his fit), the input matrix M_in (sRGB -> XYZ -> D65 to D60 -> AP1 -> RRT
// saturation), the rational fit (x (x + 0.0245786) - 0.000090537) / (x (0.983729 x + 0.432951)
// + 0.238081), the output matrix M_out (ODT saturation -> XYZ -> D60 to D65 -> sRGB), clamp.
// The matrices' rows sum to 1 (M_out's last to 0.99999): a grey stays grey (0.18 -> 0.2131,
// sRGB 127.2 of 255).
PATINA_INLINE vec3 tonemapAcesHill(vec3 x) {
    vec3 c = x / 0.6f;
    c = byRows(vec3(0.59719f, 0.35458f, 0.04823f), vec3(0.07600f, 0.90834f, 0.01566f),
               vec3(0.02840f, 0.13383f, 0.83777f), c);
    vec3 numerator = c * (c + vec3(0.0245786f)) - vec3(0.000090537f);
    vec3 denominator = c * (0.983729f * c + vec3(0.4329510f)) + vec3(0.238081f);
    c = numerator / denominator;
    c = byRows(vec3(1.60475f, -0.53108f, -0.07367f), vec3(-0.10208f, 1.10813f, -0.00605f),
               vec3(-0.00327f, -0.07276f, 1.07602f), c);
    return clamp(c, vec3(0.0f), vec3(1.0f));
}

// Sobotka's AgX (github.com/sobotka/AgX, Blender 4's default view transform) with its base look,
// in the minimal form three.js applies (AgXToneMapping): Wrensch's polynomial fit of the sigmoid
// ("Minimal AgX Implementation", iolite-engine.com) with Filament's matrices for a
// Rec. 2020 working space (github.com/google/filament pull request 7236), as Blender's AgX works
// in Rec. 2020 too. Steps: linear Rec. 709 -> Rec. 2020 (ITU-R BT.2087's matrix, 4 digits), the
// inset matrix, log2 encoded between -12.47393 and +4.026069 stops (0.18 x 2^-10 and 0.18 x 2^6.5)
// and clamped, the sixth-order contrast fit, the outset matrix, the 2.2 power (the look's display
// encoding undone), Rec. 2020 -> Rec. 709 (ITU-R BT.2407's matrix, 4 digits), clamp. The inset's
// and outset's rows sum to 1: a grey stays grey (0.18 -> 0.2145, sRGB 127.6 of 255).
PATINA_INLINE vec3 agxContrast(vec3 x) {
    vec3 x2 = x * x;
    vec3 x4 = x2 * x2;
    return 15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 + 0.1191f * x -
           vec3(0.00232f);
}

PATINA_INLINE vec3 tonemapAgx(vec3 x) {
    const real minEv = -12.47393f;
    const real maxEv = 4.026069f;
    vec3 v = byRows(vec3(0.6274f, 0.3293f, 0.0433f), vec3(0.0691f, 0.9195f, 0.0113f),
                    vec3(0.0164f, 0.0880f, 0.8956f), x);
    v = byRows(vec3(0.856627153315983f, 0.0951212405381588f, 0.0482516061458583f),
               vec3(0.137318972929847f, 0.761241990602591f, 0.101439036467562f),
               vec3(0.11189821299995f, 0.0767994186031903f, 0.811302368396859f), max(v, vec3(0.0f)));
    v = (log2(max(v, vec3(1e-10f))) - vec3(minEv)) / (maxEv - minEv);
    v = agxContrast(clamp(v, vec3(0.0f), vec3(1.0f)));
    v = byRows(vec3(1.1271005818144368f, -0.11060664309660323f, -0.016493938717834573f),
               vec3(-0.1413297634984383f, 1.157823702216272f, -0.016493938717834257f),
               vec3(-0.14132976349843826f, -0.11060664309660294f, 1.2519364065950405f), v);
    v = pow(max(v, vec3(0.0f)), vec3(2.2f));
    v = byRows(vec3(1.6605f, -0.5876f, -0.0728f), vec3(-0.1246f, 1.1329f, -0.0083f),
               vec3(-0.0182f, -0.1006f, 1.1187f), v);
    return clamp(v, vec3(0.0f), vec3(1.0f));
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
    if (tonemap == TONEMAP_ACES_NARKOWICZ) {
        mapped = tonemapAcesNarkowicz(exposed);
    } else if (tonemap == TONEMAP_ACES_HILL) {
        mapped = tonemapAcesHill(exposed);
    } else if (tonemap == TONEMAP_AGX) {
        mapped = tonemapAgx(exposed);
    } else if (tonemap == TONEMAP_REINHARD) {
        mapped = clamp(tonemapReinhard(exposed), vec3(0.0f), vec3(1.0f));
    } else if (tonemap == TONEMAP_PBR_NEUTRAL) {
        mapped = clamp(tonemapPbrNeutral(exposed), vec3(0.0f), vec3(1.0f));
    } else {
        mapped = clamp(exposed, vec3(0.0f), vec3(1.0f));
    }
    return vec3(srgbEncode(mapped.x), srgbEncode(mapped.y), srgbEncode(mapped.z));
}
