// Patina's light types (shared GLSL / C++ like brdf.glsl; include after it). shadeLight, which
// needs the BRDF model, is in brdf_model.glsl.
// The same PackedLight struct is a std140 uniform block on the GPU and a plain array on the CPU
// (engine/scene/light_packing.cpp fills it).

const int LIGHT_POINT = 0;
const int LIGHT_DIRECTIONAL = 1;
const int LIGHT_HEMISPHERE = 2;

// Largest light count the single-pass uniform block holds (64 * 96 bytes = 6 KiB of the
// 16 KiB every GL 3.3 implementation guarantees).
const int MAX_LIGHTS = 64;

// A window of 1/x^2-style attenuation that never divides by less than this; it only acts when
// a_c + a_l t + a_q t^2 < 1e-4 (all three zero, or a light at the surface with a_c = 0).
const real MIN_ATTENUATION_DENOMINATOR = 1e-4f;
// Below this squared distance a point light sits on the shaded point and L has no direction.
const real MIN_LIGHT_DISTANCE_SQUARED = 1e-12f;

// No swizzles here (C++ has none): each vec3 is followed by the scalar that fills its std140
// slot, so a light is six 16-byte rows in both languages.
struct PackedLight {
    vec3 radiance;           // colour * intensity
    int type;                // LIGHT_*
    vec3 position;           // point
    real inverseRange;      // point: 1 / range, 0 for no window (range 0)
    vec3 directionToLight;   // directional: -normalize(direction)
    real unused0;
    vec3 attenuation;        // point: a_c, a_l, a_q
    real unused1;
    vec3 sky;                // hemisphere: sky colour * colour * intensity
    real unused2;
    vec3 ground;             // hemisphere: ground colour * colour * intensity
    real unused3;
};

// a_c, a_l, a_q of Karis 2013's falloff denominator d^2 + 1 (eq. 9), every Light's default.
// Shaders take these as a constant where a light has exactly them (specialised per light,
// single when every point light has them: PATINA_KARIS_POINTS): llvmpipe turns each uniform
// scalar a fragment shader reads into a per-lane gather, and these are three
// (docs/PERFORMANCE.md).
const vec3 KARIS_ATTENUATION = vec3(1.0f, 0.0f, 1.0f);

// Windowed distance attenuation (spec section 1, after Karis 2013 eq. 9, with the general
// a_c + a_l t + a_q t^2 denominator): clamp(1 - (t/range)^4, 0, 1)^2 / (a_c + a_l t + a_q t^2).
// Takes 1/range, packed on the CPU: no division, and no branch for "no window", which
// inverseRange = 0 gives exactly (t * 0 = 0, window 1), so a loop over lights of both kinds
// runs one straight path.
PATINA_INLINE real pointLightAttenuation(real t, real inverseRange, vec3 coefficients) {
    real ratio = t * inverseRange;
    real ratio2 = ratio * ratio;
    real w = clamp(1.0f - ratio2 * ratio2, 0.0f, 1.0f);
    real window = w * w;
    real denominator = coefficients.x + coefficients.y * t + coefficients.z * t * t;
    return window / max(denominator, MIN_ATTENUATION_DENOMINATOR);
}

// Hemisphere light: mix(ground, sky, clamp(N . up, 0, 1)) seen with L = N (NoL = 1), diffuse only.
PATINA_INLINE vec3 hemisphereRadiance(PackedLight light, vec3 N) {
    real skyWeight = clamp(N.y, 0.0f, 1.0f);
    return mix(light.ground, light.sky, skyWeight);
}

// Unit normal, or zero for a zero (or non-finite-length) normal so every light adds nothing
// but the hemisphere's ground term, instead of NaN from normalize(0).
PATINA_INLINE vec3 safeNormalize(vec3 v) {
    real lengthSquared = dot(v, v);
    if (!(lengthSquared > 0.0f)) {
        return vec3(0.0f);
    }
    return v * inversesqrt(lengthSquared);
}
