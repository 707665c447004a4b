// Patina's BRDF: the "epic" model of Karis 2013, "Real Shading in Unreal Engine 4".
// This file is both GLSL 3.30 and C++20 (through GLM, see engine/shading.h), so the GPU,
// the lobe plot and the tests evaluate the same code. Keep to the common subset: float
// literals with an f suffix, no overloads, no inout, no swizzles, structs built with
// constructor syntax, and PATINA_INLINE before each function (C++ `inline`, empty in GLSL).

const float PATINA_PI = 3.14159265358979f;

// Perceptual roughness below this makes D = 0/0 at NoH = 1 (alpha^2 = 0). 0.045 is the fp32
// floor used by Frostbite and Filament; it lies below 0.05, so well-defined inputs are unchanged.
const float MIN_PERCEPTUAL_ROUGHNESS = 0.045f;
// sp divides by NoV; a normal that faces away from the camera (smooth normals at the
// silhouette) would make it 0 or negative. 1e-4 is the usual floor (spec section 2).
const float MIN_N_DOT_V = 1e-4f;

struct SurfaceMaterial {
    vec3 diffuseColor;   // c_diff = (1 - m) c_base
    vec3 f0;             // c_spec: reflectance at normal incidence
    float roughness;     // perceptual r, after the floor above
    float alpha;         // r^2
};

struct BrdfValue {
    vec3 diffuse;        // 1/sr, no cosine factor
    vec3 specular;
};

// Karis 2013, p. 3 ("Material model"): c_diff, c_spec = mix(0.08 s, c_base, m), alpha = r^2.
PATINA_INLINE SurfaceMaterial deriveSurfaceMaterial(vec3 baseColor, float roughness, float specular, float metallic) {
    float r = max(roughness, MIN_PERCEPTUAL_ROUGHNESS);
    return SurfaceMaterial((1.0f - metallic) * baseColor,
                           mix(vec3(0.08f * specular), baseColor, metallic),
                           r, r * r);
}

// Lambert: c_diff / pi (Karis 2013, eq. 1).
PATINA_INLINE vec3 Fd_Lambert(vec3 diffuseColor) {
    return diffuseColor / PATINA_PI;
}

// Walter et al. 2007 / Trowbridge-Reitz; Karis 2013, eq. 3:
// D = alpha^2 / (pi (NoH^2 (alpha^2 - 1) + 1)^2).
// Written as alpha^2 / (pi (NoH^2 alpha^2 + |N x H|^2)^2): the same value, but 1 - NoH^2 taken
// as |N x H|^2 keeps its digits near NoH = 1, where fp32 cancellation costs 2% at alpha = 0.002
// (the Lagrange form, as in Filament's D_GGX).
PATINA_INLINE float D_GGX(float NoH, vec3 NxH, float alpha) {
    float oneMinusNoHSquared = dot(NxH, NxH);
    float a = NoH * alpha;
    float k = alpha / (oneMinusNoHSquared + a * a);
    return k * k * (1.0f / PATINA_PI);
}

// Schlick-GGX geometry with Karis's remap k = (r + 1)^2 / 8 (Karis 2013, eq. 4), returned as the
// visibility V = G1(NoL) G1(NoV) / (4 NoL NoV). Since G1(x) / x = 1 / (x (1 - k) + k), the
// division by NoL NoV cancels exactly: V stays finite as NoV or NoL go to 0.
PATINA_INLINE float V_SchlickGGX(float NoV, float NoL, float roughness) {
    float k = (roughness + 1.0f) * (roughness + 1.0f) / 8.0f;
    float gv = NoV * (1.0f - k) + k;
    float gl = NoL * (1.0f - k) + k;
    return 0.25f / (gv * gl);
}

// Schlick Fresnel with the spherical-Gaussian exponent (Karis 2013, eq. 5):
// F = F0 + (1 - F0) 2^((-5.55473 VoH - 6.98316) VoH). VoH is clamped to [0, 1] by the caller,
// so rounding past 1 cannot flip the sign of the exponent's meaning.
PATINA_INLINE vec3 F_SchlickSphericalGaussian(vec3 f0, float VoH) {
    float fresnel = exp2((-5.55473f * VoH - 6.98316f) * VoH);
    return f0 + (vec3(1.0f) - f0) * fresnel;
}

// f = d + sp for unit N, V, L on the lit side (NoL > 0); the caller skips NoL <= 0.
PATINA_INLINE BrdfValue evaluateBrdf(SurfaceMaterial material, vec3 N, vec3 V, vec3 L) {
    vec3 diffuse = Fd_Lambert(material.diffuseColor);
    vec3 LplusV = L + V;
    float lengthSquared = dot(LplusV, LplusV);
    // L = -V: H is 0/0. Only reachable with V below the surface; no half vector, no specular.
    if (lengthSquared <= 0.0f) {
        return BrdfValue(diffuse, vec3(0.0f));
    }
    vec3 H = LplusV * inversesqrt(lengthSquared);
    float NoV = max(dot(N, V), MIN_N_DOT_V);
    float NoL = clamp(dot(N, L), 0.0f, 1.0f);
    float NoH = clamp(dot(N, H), 0.0f, 1.0f);
    float VoH = clamp(dot(V, H), 0.0f, 1.0f);
    float D = D_GGX(NoH, cross(N, H), material.alpha);
    float Vis = V_SchlickGGX(NoV, NoL, material.roughness);
    vec3 F = F_SchlickSphericalGaussian(material.f0, VoH);
    return BrdfValue(diffuse, (D * Vis) * F);
}
