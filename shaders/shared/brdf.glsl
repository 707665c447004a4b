// Patina's BRDF: the "epic" model of Karis 2013, "Real Shading in Unreal Engine 4".
// This file is both GLSL 3.30 and C++20 (through GLM, see engine/shading/shading.h), so the GPU,
// the lobe plot and the tests evaluate the same code. Keep to the common subset: float
// literals with an f suffix, no overloads, no inout, no swizzles, structs built with
// constructor syntax, and PATINA_INLINE before each function (C++ `inline`, empty in GLSL).
// Scalars are `real`, as pbrt's are `Float`: `#define real float` in GLSL (gl/program.cpp),
// `using real = ...` in each C++ namespace that compiles this (float, double or emulated half).

const real PATINA_PI = 3.14159265358979f;

// Perceptual roughness below this makes D = 0/0 at NoH = 1 (alpha^2 = 0). 0.045 is the fp32
// floor used by Frostbite and Filament; it lies below 0.05, so well-defined inputs are unchanged.
// In half precision (PATINA_HALF_PRECISION) the floor is 0.089, as Filament's for mobile: at
// 0.045 the peak of D, 1 / (pi alpha^2) = 7.8e4, would overflow fp16's 65504.
#ifdef PATINA_HALF_PRECISION
const real MIN_PERCEPTUAL_ROUGHNESS = 0.089f;
const real MAX_HALF = 65504.0f;
#else
const real MIN_PERCEPTUAL_ROUGHNESS = 0.045f;
#endif
// sp divides by NoV; a normal that faces away from the camera (smooth normals at the
// silhouette) would make it 0 or negative. 1e-4 is the usual floor (docs/SHADING.md S2).
const real MIN_N_DOT_V = 1e-4f;

// KHR_materials_anisotropy's fields are compiled into a program only where a material has the
// layer (PATINA_ANISOTROPY, shaders/stages/shade.frag); C++ always has them (the CPU twin and
// the ground truth choose at run time, alphaT > 0).
#if defined(PATINA_ANISOTROPY) || defined(__cplusplus)
#ifndef PATINA_ANISOTROPIC_FIELDS
#define PATINA_ANISOTROPIC_FIELDS
#endif
#endif
// KHR_materials_iridescence's likewise (PATINA_IRIDESCENCE; iridescence.glsl). The fp16 instance
// has the fields but no thin film: its models are compiled with PATINA_NO_THIN_FILM
// (engine/shading/brdf_models.cpp).
#if defined(PATINA_IRIDESCENCE) || defined(__cplusplus)
#ifndef PATINA_IRIDESCENT_FIELDS
#define PATINA_IRIDESCENT_FIELDS
#endif
#endif

struct SurfaceMaterial {
    vec3 diffuseColor;   // c_diff = (1 - m) c_base
    vec3 f0;             // c_spec: reflectance at normal incidence
    real roughness;     // perceptual r, after the floor above
    real alpha;         // r^2
    // The two lobes glTF 2.0's Appendix B mixes by metallic, kept apart for the models that
    // weigh them apart (PATINA_FD_LAMBERT_FRESNEL_MIX, PATINA_MS_FDEZ_AGUERA); the others read
    // only the four above.
    vec3 dielectricF0;   // 0.08 s: the dielectric's F0 alone (0.04 at s = 0.5, ior 1.5), times
                         // withSpecular's tint; before its weight
    vec3 baseColor;      // c_base: the metal's F0
    real metallic;      // m
    // KHR_materials_specular's weight of the dielectric's Fresnel (withSpecular; 1 without):
    // the dielectric's F is w F_Schlick(F0), and the lobe's F90 = mix(w, 1, m), with `f0` above
    // mix(w F0, c_base, m), so that F = f0 + (f90 - f0)(1 - V.H)^5 is glTF's mix of the two.
    real specularWeight;
    real f90;
#ifdef PATINA_ANISOTROPIC_FIELDS
    // KHR_materials_anisotropy (withAnisotropy): the unit directions of the lobe's stretch in
    // the surface, t and b = N x t, and the roughness along each, alpha_t >= alpha_b. alpha_t 0
    // is none (deriveSurfaceMaterial's): the isotropic terms are evaluated.
    vec3 anisotropicT;
    vec3 anisotropicB;
    real alphaT;
    real alphaB;
    real anisotropy;    // the strength, in [0, 1]
#endif
#ifdef PATINA_IRIDESCENT_FIELDS
    // KHR_materials_iridescence (withIridescence): the film's strength (0: none), ior and
    // thickness in nm.
    real iridescence;
    real iridescenceIor;
    real iridescenceThickness;
    // The film's Fresnel at this pixel's N.V over the dielectric and the metal, on the GPU
    // (iridescence.glsl's withFilmAt, once a pixel); C++ evaluates it where it is asked for.
    vec3 filmDielectric;
    vec3 filmMetal;
#endif
};

struct BrdfValue {
    vec3 diffuse;        // 1/sr, no cosine factor
    vec3 specular;
};

// The specular lobe's factors, sp = D * Vis * F (for plots and tests).
struct SpecularTerms {
    real D;
    real Vis;           // G / (4 NoL NoV)
    vec3 F;
};

// Karis 2013, p. 3 ("Material model"): a dielectric's F0 is 0.08 s (0.04 at the default s = 0.5,
// ior 1.5). The one definition: glTF's import and export convert through it.
const real F0_PER_SPECULAR = 0.08f;

// Karis 2013, p. 3 ("Material model"): c_diff, c_spec = mix(0.08 s, c_base, m), alpha = r^2.
PATINA_INLINE SurfaceMaterial deriveSurfaceMaterial(vec3 baseColor, real roughness, real specular, real metallic) {
    real r = max(roughness, MIN_PERCEPTUAL_ROUGHNESS);
    return SurfaceMaterial((1.0f - metallic) * baseColor,
                           mix(vec3(F0_PER_SPECULAR * specular), baseColor, metallic),
                           r, r * r, vec3(F0_PER_SPECULAR * specular), baseColor, metallic, 1.0f, 1.0f
#ifdef PATINA_ANISOTROPIC_FIELDS
                           , vec3(0.0f), vec3(0.0f), 0.0f, 0.0f, 0.0f
#endif
#ifdef PATINA_IRIDESCENT_FIELDS
                           , 0.0f, 1.3f, 0.0f, vec3(0.0f), vec3(0.0f)
#endif
    );
}

// KHR_materials_specular (Khronos, ratified 2021) and KHR_materials_ior, on glTF 2.0's
// Appendix B: the dielectric's F0 tinted and its Fresnel weighted,
//   dielectric_f0  = min(F0(ior) specularColor, 1) specular,  dielectric_f90 = specular
// (the extension's "Implementation"). Patina's F0(ior) specularColor is 0.08 s `tint` (glTF
// import: gltf/material.h), so the tint's largest channel is 1 up to F0 0.08 and beyond it carries
// what s cannot; `weight` is specularFactor. The metal's lobe keeps F0 = c_base, F90 = 1.
// A tint of 1 and a weight of 1 leave deriveSurfaceMaterial's values exactly as they were.
PATINA_INLINE SurfaceMaterial withSpecular(SurfaceMaterial material, vec3 tint, real weight) {
    material.dielectricF0 = min(material.dielectricF0 * tint, vec3(1.0f));
    material.specularWeight = weight;
    material.f0 = mix(material.dielectricF0 * weight, material.baseColor, material.metallic);
    // w + (1 - w) m, not mix(w, 1, m): exactly 1 at w = 1 whatever m.
    material.f90 = weight + (1.0f - weight) * material.metallic;
    return material;
}

// KHR_materials_anisotropy: the lobe stretched along t, the tangent frame's direction
// (cos rotation, sin rotation) turned counter-clockwise from the tangent (the texture's direction
// already turned in, where it has one): t = cos T + sin B in the frame (T, B = N x T w) made
// orthogonal to the shading normal N; alpha_t = mix(alpha, 1, strength^2), alpha_b = alpha (the
// extension's "Implementation"). `tangent` xyz with `w`, the mesh's; one of no length takes
// fallbackAnisotropyTangent.
// A mesh without tangents (the built-in shapes): the direction round the y axis, y x N, which
// turns smoothly over the surface (a sphere's lines of latitude); within half a degree of +-y,
// where it has no direction, the x axis made orthogonal to N.
PATINA_INLINE vec3 fallbackAnisotropyTangent(vec3 N) {
    vec3 around = vec3(N.z, 0.0f, -N.x);   // cross((0, 1, 0), N)
    return dot(around, around) > 1e-4f ? around : vec3(1.0f, 0.0f, 0.0f) - N * N.x;
}

PATINA_INLINE SurfaceMaterial withAnisotropy(SurfaceMaterial material, vec3 N, vec3 tangent, real w, real cosRotation,
                                             real sinRotation, real strength) {
#ifdef PATINA_ANISOTROPIC_FIELDS
    vec3 T = tangent - N * dot(N, tangent);
    if (dot(T, T) < 1e-12f) {
        T = fallbackAnisotropyTangent(N);
        w = 1.0f;
    }
    T = normalize(T);
    vec3 B = cross(N, T) * real(w < 0.0f ? -1.0f : 1.0f);
    vec3 t = normalize(cosRotation * T + sinRotation * B);
    material.anisotropicT = t;
    material.anisotropicB = cross(N, t);
    material.alphaT = mix(material.alpha, real(1.0f), strength * strength);
    material.alphaB = material.alpha;
    material.anisotropy = strength;
#endif
    return material;
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
PATINA_INLINE real D_GGX(real NoH, vec3 NxH, real alpha) {
    real oneMinusNoHSquared = dot(NxH, NxH);
    real a = NoH * alpha;
    real k = alpha / (oneMinusNoHSquared + a * a);
#ifdef PATINA_HALF_PRECISION
    // k itself can pass 65504 below the floor's peak; cap as docs/SHADING.md S2 does.
    return min(min(k, 256.0f) * min(k, 256.0f) * (1.0f / PATINA_PI), MAX_HALF);
#else
    return k * k * (1.0f / PATINA_PI);
#endif
}

// Anisotropic GGX (Burley 2012, "Physically-Based Shading at Disney", eq. 13; Heitz 2014,
// eq. 85 with alpha_x = alpha_t, alpha_y = alpha_b):
// D = 1 / (pi alpha_t alpha_b ((ToH / alpha_t)^2 + (BoH / alpha_b)^2 + NoH^2)^2),
// written as a^2 w^2 w^2 / pi with a^2 = alpha_t alpha_b, w^2 = a^2 / |(alpha_b ToH, alpha_t BoH, a^2 NoH)|^2.
PATINA_INLINE real D_GGX_Anisotropic(real NoH, real ToH, real BoH, real alphaT, real alphaB) {
    real a2 = alphaT * alphaB;
    vec3 f = vec3(alphaB * ToH, alphaT * BoH, a2 * NoH);
    real w2 = a2 / dot(f, f);
    return a2 * w2 * w2 * (1.0f / PATINA_PI);
}

// Heitz 2014, eq. 99 (height-correlated Smith) with the anisotropic Lambda of eq. 86,
// Lambda(o) = (-1 + sqrt(1 + (alpha_t^2 To^2 + alpha_b^2 Bo^2) / No^2)) / 2:
// V = 0.5 / (NoL |(alpha_t ToV, alpha_b BoV, NoV)| + NoV |(alpha_t ToL, alpha_b BoL, NoL)|).
// alpha_t = alpha_b gives V_SmithGGXCorrelated.
PATINA_INLINE real V_SmithGGXCorrelated_Anisotropic(real NoV, real NoL, real ToV, real BoV, real ToL, real BoL,
                                                    real alphaT, real alphaB) {
    real lambdaV = NoL * length(vec3(alphaT * ToV, alphaB * BoV, NoV));
    real lambdaL = NoV * length(vec3(alphaT * ToL, alphaB * BoL, NoL));
    return 0.5f / (lambdaV + lambdaL);
}

// Visibility terms: V = G / (4 NoL NoV), written so the division cancels where it can.

// Schlick-GGX geometry G1(x) = x / (x (1 - k) + k) (Karis 2013, eq. 4). Since G1(x) / x =
// 1 / (x (1 - k) + k), the division by NoL NoV cancels exactly: V stays finite as NoV or NoL -> 0.
PATINA_INLINE real V_SchlickGGX(real NoV, real NoL, real k) {
    real gv = NoV * (1.0f - k) + k;
    real gl = NoL * (1.0f - k) + k;
    return 0.25f / (gv * gl);
}

// Karis's remap of k for analytic lights: k = (r + 1)^2 / 8 (Karis 2013, eq. 4).
PATINA_INLINE real k_Karis(real roughness) {
    return (roughness + 1.0f) * (roughness + 1.0f) / 8.0f;
}

// Smith GGX, separable (Walter et al. 2007, eq. 34): G1(x) = 2x / (x + sqrt(a^2 + (1 - a^2) x^2)),
// so V = 1 / ((NoL + sqrt(...NoL)) (NoV + sqrt(...NoV))).
PATINA_INLINE real V_SmithGGX(real NoV, real NoL, real alpha) {
    real a2 = alpha * alpha;
    real gv = NoV + sqrt(a2 + (1.0f - a2) * NoV * NoV);
    real gl = NoL + sqrt(a2 + (1.0f - a2) * NoL * NoL);
    return 1.0f / (gv * gl);
}

// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", eq. 99
// (height-correlated Smith GGX): V = 0.5 / (NoL sqrt(NoV^2 (1 - a^2) + a^2) + NoV sqrt(NoL^2 (1 - a^2) + a^2)).
// NoV and NoL both 0 would be 0/0; the callers floor NoV at MIN_N_DOT_V.
PATINA_INLINE real V_SmithGGXCorrelated(real NoV, real NoL, real alpha) {
    real a2 = alpha * alpha;
    real lambdaV = NoL * sqrt(NoV * NoV * (1.0f - a2) + a2);
    real lambdaL = NoV * sqrt(NoL * NoL * (1.0f - a2) + a2);
    return 0.5f / (lambdaV + lambdaL);
}

// Hammon 2017, "PBR Diffuse Lighting for GGX+Smith Microsurfaces": the height-correlated V
// approximated as 0.5 / mix(2 NoL NoV, NoL + NoV, alpha) (UE4 Vis_SmithJointApprox).
PATINA_INLINE real V_SmithGGXCorrelated_Fast(real NoV, real NoL, real alpha) {
    return 0.5f / mix(2.0f * NoL * NoV, NoL + NoV, alpha);
}

// Schlick Fresnel with the spherical-Gaussian exponent (Karis 2013, eq. 5):
// F = F0 + (1 - F0) 2^((-5.55473 VoH - 6.98316) VoH). VoH is clamped to [0, 1] by the caller.
// With the reflectance at grazing incidence F90 (withSpecular's f90; 1 in the paper).
PATINA_INLINE vec3 F_SchlickSphericalGaussian90(vec3 f0, real f90, real VoH) {
    real fresnel = exp2((-5.55473f * VoH - 6.98316f) * VoH);
    return f0 + (vec3(f90) - f0) * fresnel;
}

PATINA_INLINE vec3 F_SchlickSphericalGaussian(vec3 f0, real VoH) {
    return F_SchlickSphericalGaussian90(f0, 1.0f, VoH);
}

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering", eq. 15:
// F = F0 + (1 - F0) (1 - VoH)^5, as repeated products (no pow of a possibly negative base).
// With F90 as glTF 2.0 Appendix B.3.4 writes it, F = F0 + (F90 - F0)(1 - V.H)^5 (withSpecular's
// f90; 1 in Schlick's form).
PATINA_INLINE vec3 F_Schlick90(vec3 f0, real f90, real VoH) {
    real m = clamp(1.0f - VoH, 0.0f, 1.0f);
    real m2 = m * m;
    return f0 + (vec3(f90) - f0) * (m2 * m2 * m);
}

PATINA_INLINE vec3 F_Schlick(vec3 f0, real VoH) {
    return F_Schlick90(f0, 1.0f, VoH);
}

// max_value of KHR_materials_specular: an RGB Fresnel's largest channel, the share a layer
// beneath loses ("to avoid inverse colors and ensure energy conservation").
PATINA_INLINE real maxValue(vec3 color) {
    return max(color.x, max(color.y, color.z));
}

// The smallest channel: 1 - max_value(F) where what is left is written 1 - F.
PATINA_INLINE real minValue(vec3 color) {
    return min(color.x, min(color.y, color.z));
}

// Exact Fresnel reflectance of a dielectric for unpolarised light (Walter et al. 2007, eq. 22),
// with eta from F0 = ((eta - 1) / (eta + 1))^2. F0 near 1 (metals) would make eta infinite:
// sqrt(F0) is capped at 0.9999 (eta <= 19999), where F is 1 to within 1e-4 anyway.
PATINA_INLINE real F_DielectricExact1(real f0, real c) {
    real s = min(sqrt(max(f0, 0.0f)), 0.9999f);
    real eta = (1.0f + s) / (1.0f - s);
    real g2 = eta * eta - 1.0f + c * c;   // > 0 for eta >= 1: no total internal reflection
    real g = sqrt(g2);
    real a = (g - c) / (g + c);
    real b = (c * (g + c) - 1.0f) / (c * (g - c) + 1.0f);
    return 0.5f * a * a * (1.0f + b * b);
}

PATINA_INLINE vec3 F_DielectricExact(vec3 f0, real VoH) {
    return vec3(F_DielectricExact1(f0.x, VoH), F_DielectricExact1(f0.y, VoH), F_DielectricExact1(f0.z, VoH));
}

// A Fresnel weighted to F90 < 1 (withSpecular): f90 times the exact Fresnel of F0 / f90, so that
// both ends scale as Schlick's do (an approximation of the weight, not a physical Fresnel).
PATINA_INLINE vec3 F_DielectricExact90(vec3 f0, real f90, real VoH) {
    if (f90 >= 1.0f) {
        return F_DielectricExact(f0, VoH);
    }
    return f90 > 0.0f ? f90 * F_DielectricExact(f0 / f90, VoH) : vec3(0.0f);
}

// Burley 2012, "Physically-Based Shading at Disney", eq. 3 (not energy conserving: albedo 1.04
// at mu = 1, r = 1): (c / pi)(1 + (FD90 - 1)(1 - NoL)^5)(1 + (FD90 - 1)(1 - NoV)^5),
// FD90 = 0.5 + 2 r LoH^2.
PATINA_INLINE vec3 Fd_Burley(vec3 diffuseColor, real roughness, real NoV, real NoL, real LoH) {
    real fd90 = 0.5f + 2.0f * roughness * LoH * LoH;
    real mv = clamp(1.0f - NoV, 0.0f, 1.0f);
    real ml = clamp(1.0f - NoL, 0.0f, 1.0f);
    real lightScatter = 1.0f + (fd90 - 1.0f) * (ml * ml * ml * ml * ml);
    real viewScatter = 1.0f + (fd90 - 1.0f) * (mv * mv * mv * mv * mv);
    return diffuseColor * (lightScatter * viewScatter / PATINA_PI);
}

// GGX D in its standard form (Karis 2013, eq. 3), for comparison: 1 - NoH^2 cancels in fp32
// near NoH = 1 (2% at alpha = 0.002). D_GGX above is the guarded form.
PATINA_INLINE real D_GGX_Standard(real NoH, real alpha) {
    real a2 = alpha * alpha;
    real base = NoH * NoH * (a2 - 1.0f) + 1.0f;
    return a2 / (PATINA_PI * base * base);
}

// Where (NoV, r) falls in a table of `size` x `size` values at i / (size - 1): the lower
// texel and the weights of the next, for the tables' own bilinear lookups (this one and
// ibl_model.glsl's environment BRDF).
struct TableCoordinate {
    int x0;
    int y0;
    real fx;
    real fy;
};

PATINA_INLINE TableCoordinate tableCoordinate(real NoV, real roughness, int size) {
    real x = clamp(NoV, 0.0f, 1.0f) * real(size - 1);
    real y = clamp(roughness, 0.0f, 1.0f) * real(size - 1);
    int x0 = min(int(x), size - 2);
    int y0 = min(int(y), size - 2);
    return TableCoordinate(x0, y0, x - real(x0), y - real(y0));
}
