// One BRDF model: the terms brdf.glsl offers, chosen at compile time (Filament's dispatch
// style), then evaluateBrdf and shadeLight built from them. Shared GLSL / C++; include after
// brdf.glsl, lights.glsl, energy_table.glsl and brdf_terms.glsl (the terms' names). Every
// permutation compiles only the terms it uses:
//   PATINA_D, PATINA_V, PATINA_F, PATINA_FD, PATINA_MS   one of brdf_terms.glsl's names each
//   PATINA_NO_DIFFUSE (defined or not): c_diff = 0, no diffuse term (specialised shaders)
// The defaults are the seed model, "epic". glTF 2.0's Appendix B BRDF ("gltf") is D_GGX,
// V_SMITH_CORRELATED, F_SCHLICK_POW5, FD_LAMBERT_FRESNEL_MIX and, under an environment,
// MS_FDEZ_AGUERA.
#ifndef PATINA_D
#define PATINA_D PATINA_D_GGX
#endif
#ifndef PATINA_V
#define PATINA_V PATINA_V_SCHLICK_KARIS
#endif
#ifndef PATINA_F
#define PATINA_F PATINA_F_SCHLICK_SG
#endif
#ifndef PATINA_FD
#define PATINA_FD PATINA_FD_LAMBERT
#endif
#ifndef PATINA_MS
#define PATINA_MS PATINA_MS_NONE
#endif

PATINA_INLINE real distribution(real NoH, vec3 NxH, real alpha) {
#if PATINA_D == PATINA_D_GGX_STANDARD
    return D_GGX_Standard(NoH, alpha);
#else
    return D_GGX(NoH, NxH, alpha);
#endif
}

PATINA_INLINE real visibility(real NoV, real NoL, SurfaceMaterial material) {
#if PATINA_V == PATINA_V_SCHLICK_ALPHA_HALF
    return V_SchlickGGX(NoV, NoL, material.alpha * 0.5f);
#elif PATINA_V == PATINA_V_SMITH_SEPARABLE
    return V_SmithGGX(NoV, NoL, material.alpha);
#elif PATINA_V == PATINA_V_SMITH_CORRELATED
    return V_SmithGGXCorrelated(NoV, NoL, material.alpha);
#elif PATINA_V == PATINA_V_HAMMON
    return V_SmithGGXCorrelated_Fast(NoV, NoL, material.alpha);
#else
    return V_SchlickGGX(NoV, NoL, k_Karis(material.roughness));
#endif
}

// The visibility under an environment. Karis: k = (r + 1)^2 / 8 "is only used for analytic
// light sources; applied to image-based lighting the results at glancing angles will be much
// too dark", so a model with that remap takes k = alpha / 2 there; the others keep their own.
PATINA_INLINE real environmentVisibility(real NoV, real NoL, SurfaceMaterial material) {
#if PATINA_V == PATINA_V_SCHLICK_KARIS
    return V_SchlickGGX(NoV, NoL, material.alpha * 0.5f);
#else
    return visibility(NoV, NoL, material);
#endif
}

// F with F0 and F90 (SurfaceMaterial's f0 and f90; 1 but for KHR_materials_specular's weight).
PATINA_INLINE vec3 fresnel(vec3 f0, real f90, real VoH) {
#if PATINA_F == PATINA_F_SCHLICK_POW5
    return F_Schlick90(f0, f90, VoH);
#elif PATINA_F == PATINA_F_DIELECTRIC_EXACT
    return F_DielectricExact90(f0, f90, VoH);
#else
    return F_SchlickSphericalGaussian90(f0, f90, VoH);
#endif
}

// The base's F at V.H: the model's Fresnel of f0 and f90, with KHR_materials_iridescence's film
// mixed in by its strength (the extension's "Iridescence BRDF": mix(F, F_film, iridescence), the
// film's Fresnel at N.V over the dielectric and the metal, mixed by metallic as the lobes are).
PATINA_INLINE vec3 surfaceFresnel(SurfaceMaterial material, real NoV, real VoH) {
    vec3 F = fresnel(material.f0, material.f90, VoH);
#if defined(PATINA_IRIDESCENT_FIELDS) && !defined(PATINA_NO_THIN_FILM)
    if (material.iridescence > 0.0f) {
        IridescentFresnel film = filmFresnelAt(material, NoV);
        F = mix(F, mix(film.dielectric, film.metal, material.metallic), material.iridescence);
    }
#endif
    return F;
}

// The dielectric's F alone at V.H (KHR_materials_specular's weight, the film's Fresnel over the
// dielectric mixed in): what the layer beneath it loses.
PATINA_INLINE vec3 dielectricFresnel(SurfaceMaterial material, real NoV, real VoH) {
    real w = material.specularWeight;
    vec3 F = fresnel(material.dielectricF0 * w, w, VoH);
#if defined(PATINA_IRIDESCENT_FIELDS) && !defined(PATINA_NO_THIN_FILM)
    if (material.iridescence > 0.0f) {
        F = mix(F, filmFresnelAt(material, NoV).dielectric, material.iridescence);
    }
#endif
    return F;
}

PATINA_INLINE vec3 diffuse(SurfaceMaterial material, real NoV, real NoL, real LoH) {
#if defined(PATINA_NO_DIFFUSE)
    // Set only for a material whose c_diff is exactly 0 (pure metal or black base): the terms
    // would multiply by 0.
    return vec3(0.0f);
#elif PATINA_FD == PATINA_FD_BURLEY
    return Fd_Burley(material.diffuseColor, material.roughness, NoV, NoL, LoH);
#elif PATINA_FD == PATINA_FD_LAMBERT_FRESNEL_MIX
    // glTF 2.0, Appendix B.3.5 (fresnel_mix): the dielectric's diffuse keeps what its specular
    // layer does not reflect, (1 - F_dielectric(VoH)) c_diff / pi, with the dielectric's own F0
    // (not the metallic mix: the metal lobe has no diffuse to weigh). LoH = VoH. With
    // KHR_materials_specular the Fresnel is RGB and weighted: the diffuse keeps 1 - its largest
    // channel, 1 - max_value(w F) (the extension's fresnel_mix).
    return Fd_Lambert(material.diffuseColor) * (1.0f - maxValue(dielectricFresnel(material, NoV, LoH)));
#else
    return Fd_Lambert(material.diffuseColor);
#endif
}

// Turquin 2019, "Practical multiple scattering compensation for microfacet models", eq. 18 in
// Filament's form: sp *= 1 + F0 (1 / E(NoV) - 1), E the single-scattering directional albedo
// with F = 1, from the model's own table (energy_table.glsl; include it first).
PATINA_INLINE vec3 energyCompensation(vec3 f0, real NoV, real roughness) {
#if PATINA_MS == PATINA_MS_TURQUIN
    real albedo = max(energyTableLookup(NoV, roughness), 1e-4f);
    return vec3(1.0f) + f0 * (1.0f / albedo - 1.0f);
#else
    return vec3(1.0f);
#endif
}

// The specular lobe's D and Vis: the model's own, or where the material has
// KHR_materials_anisotropy's stretch (alpha_t > 0) the extension's D and height-correlated V
// (brdf.glsl), which replace them as the extension defines them on glTF's BRDF.
struct LobeShape {
    real D;
    real Vis;
};
PATINA_INLINE LobeShape stretchedTerms(SurfaceMaterial material, real modelD, real modelVis, real NoV, real NoL,
                                       real NoH, vec3 H, vec3 V, vec3 L) {
#ifdef PATINA_ANISOTROPIC_FIELDS
    if (material.alphaT > 0.0f) {
        vec3 T = material.anisotropicT;
        vec3 B = material.anisotropicB;
        return LobeShape(D_GGX_Anisotropic(NoH, dot(T, H), dot(B, H), material.alphaT, material.alphaB),
                         V_SmithGGXCorrelated_Anisotropic(NoV, NoL, dot(T, V), dot(B, V), dot(T, L), dot(B, L),
                                                          material.alphaT, material.alphaB));
    }
#endif
    return LobeShape(modelD, modelVis);
}

// f = d + sp for unit N, V, L on the lit side (NoL > 0); the caller skips NoL <= 0.
// `underEnvironment` takes environmentVisibility (the ground truth of image-based lighting).
PATINA_INLINE BrdfValue evaluateBrdfFor(SurfaceMaterial material, vec3 N, vec3 V, vec3 L, bool underEnvironment) {
    vec3 LplusV = L + V;
    real lengthSquared = dot(LplusV, LplusV);
    real NoV = max(dot(N, V), MIN_N_DOT_V);
    real NoL = clamp(dot(N, L), 0.0f, 1.0f);
    // L = -V: H is 0/0. Only reachable with V below the surface; no half vector, no specular.
    if (lengthSquared <= 0.0f) {
        return BrdfValue(diffuse(material, NoV, NoL, 0.0f), vec3(0.0f));
    }
    vec3 H = LplusV * inversesqrt(lengthSquared);
    real NoH = clamp(dot(N, H), 0.0f, 1.0f);
    real VoH = clamp(dot(V, H), 0.0f, 1.0f);
    LobeShape shape = stretchedTerms(material, distribution(NoH, cross(N, H), material.alpha),
                                     underEnvironment ? environmentVisibility(NoV, NoL, material)
                                                      : visibility(NoV, NoL, material),
                                     NoV, NoL, NoH, H, V, L);
    vec3 F = surfaceFresnel(material, NoV, VoH);
    vec3 specular = (shape.D * shape.Vis) * F * energyCompensation(material.f0, NoV, material.roughness);
    // LoH = VoH: H bisects L and V.
    return BrdfValue(diffuse(material, NoV, NoL, VoH), specular);
}

// Under analytic lights.
PATINA_INLINE BrdfValue evaluateBrdf(SurfaceMaterial material, vec3 N, vec3 V, vec3 L) {
    return evaluateBrdfFor(material, N, V, L, false);
}

// Outgoing radiance towards V from a light of radiance `radiance` in unit direction L.
// Back-facing light contributes nothing; that is a select, not a branch: a SIMD rasteriser
// (llvmpipe, or a GPU's warp) runs the BRDF for every lane anyway, and the select costs less
// than the branch's mask bookkeeping. evaluateBrdf clamps NoL, so the unselected value is
// finite for the models' own guards; a select discards it even if it were not.
PATINA_INLINE vec3 shadeFromDirection(vec3 radiance, vec3 L, SurfaceMaterial material, vec3 N, vec3 V) {
    real NoL = dot(N, L);
    BrdfValue f = evaluateBrdf(material, N, V, L);
    vec3 value = radiance * min(NoL, 1.0f) * (f.diffuse + f.specular);
    return NoL > 0.0f ? value : vec3(0.0f);
}

// A light's outgoing radiance split by lobe: what the inspector's channels show (shadeLight is
// their sum, the area lights' exactly so).
struct LightShares {
    vec3 diffuse;
    vec3 specular;
};

// shadeFromDirection's two lobes apart.
PATINA_INLINE LightShares sharesFromDirection(vec3 radiance, vec3 L, SurfaceMaterial material, vec3 N, vec3 V) {
    real NoL = dot(N, L);
    BrdfValue f = evaluateBrdf(material, N, V, L);
    vec3 arriving = radiance * min(NoL, 1.0f);
    if (NoL > 0.0f) {
        return LightShares(arriving * f.diffuse, arriving * f.specular);
    }
    return LightShares(vec3(0.0f), vec3(0.0f));
}

// Each light type on its own, so a shader specialised to a scene (shade.frag's
// PATINA_SPECIALISED) compiles only the types it has; shadeLight picks one at run time.
// `windowed` false skips the window's arithmetic: a constant, for a specialised shader whose
// light has range 0 (true is right for every light: 1/range = 0 gives window 1). `karis`
// true takes KARIS_ATTENUATION for the light's coefficients instead of reading them: only for
// a light that has exactly those (hasKarisAttenuation, light_packing.h).
// lightFalloff and pointLightArrival: lights.glsl.
PATINA_INLINE vec3 shadePointLight(PackedLight light, bool windowed, bool karis, SurfaceMaterial material,
                                   vec3 P, vec3 N, vec3 V) {
    LightArrival arrival = pointLightArrival(light, windowed, karis, P);
    vec3 value = shadeFromDirection(arrival.radiance, arrival.L, material, N, V);
    return arrival.present ? value : vec3(0.0f);
}

PATINA_INLINE vec3 shadeDirectionalLight(PackedLight light, SurfaceMaterial material, vec3 N, vec3 V) {
    return shadeFromDirection(light.radiance, light.directionToLight, material, N, V);
}

// Diffuse only, seen with L = N.
PATINA_INLINE vec3 shadeHemisphereLight(PackedLight light, SurfaceMaterial material, vec3 N, vec3 V) {
    real NoV = max(dot(N, V), MIN_N_DOT_V);
    vec3 H = safeNormalize(N + V);
    return hemisphereRadiance(light, N) * diffuse(material, NoV, 1.0f, clamp(dot(N, H), 0.0f, 1.0f));
}

// The specular lobe alone towards V from radiance arriving along unit L, with the cosine;
// nothing from behind the surface (a select, as shadeFromDirection's).
PATINA_INLINE vec3 specularFromDirection(vec3 radiance, vec3 L, SurfaceMaterial material, vec3 N, vec3 V) {
    real NoL = dot(N, L);
    vec3 value = radiance * min(NoL, 1.0f) * evaluateBrdf(material, N, V, L).specular;
    return NoL > 0.0f ? value : vec3(0.0f);
}

// The diffuse lobe alone for light of `radiance` whose cosine-weighted arrival is `illuminance`
// (NoL for a point; an area light's own), the lobe evaluated towards unit L (Burley reads it).
PATINA_INLINE vec3 diffuseFromDirection(vec3 radiance, real illuminance, vec3 L, SurfaceMaterial material, vec3 N,
                                        vec3 V) {
    return radiance * illuminance * evaluateBrdf(material, N, V, L).diffuse;
}

// A sphere light (Karis 2013, "Area lights"): the point light's falloff at the centre's distance
// d; specular from the representative point of eq. 11 with the normalisation (alpha / alpha')^2
// of eq. 14; diffuse from the centre as a point light (exact while the sphere is above the
// horizon), or with `method.exactSphereDiffuse` Frostbite's horizon-clipped illuminance.
// `windowed` and `karis` as for shadePointLight. Source radius 0 gives the point light.
PATINA_INLINE LightShares sphereLightSharesWith(PackedLight light, bool windowed, bool karis, AreaLightMethod method,
                                                SurfaceMaterial material, vec3 P, vec3 N, vec3 V) {
    SphereArrival arrival = sphereLightArrival(light, windowed, karis, P);
    vec3 radiance = arrival.radiance;
    real inverseDistance = arrival.inverseDistance;
    vec3 toCentreUnit = arrival.toCentre * inverseDistance;
    real NoL = dot(N, toCentreUnit);
    real s = light.sourceRadius;
    real illuminance = method.exactSphereDiffuse
                           ? sphereIlluminance_Frostbite(NoL, s * s * inverseDistance * inverseDistance)
                           : clamp(NoL, 0.0f, 1.0f);
    vec3 diffuse = diffuseFromDirection(radiance, illuminance, toCentreUnit, material, N, V);

    vec3 R = 2.0f * dot(N, V) * N - V;   // reflect(-V, N)
    RepresentativePoint point = sphereRepresentative(arrival, s, R, material.alpha, method);
    vec3 specular = specularFromDirection(radiance * point.normalization, point.L, material, N, V);
    // The centre on the shaded point has no direction: no light, as for a point light.
    if (arrival.present) {
        return LightShares(diffuse, specular);
    }
    return LightShares(vec3(0.0f), vec3(0.0f));
}

PATINA_INLINE vec3 shadeSphereLightWith(PackedLight light, bool windowed, bool karis, AreaLightMethod method,
                                        SurfaceMaterial material, vec3 P, vec3 N, vec3 V) {
    LightShares shares = sphereLightSharesWith(light, windowed, karis, method, material, P, N, V);
    return shares.diffuse + shares.specular;
}

// A tube light (Karis 2013, "Tube lights"): the capsule of radius s around the segment from
// `position` to `tubeEnd`, of total intensity. Falloff and diffuse from the line irradiance of
// the two ends (lineIrradianceDistanceSquared, lineIrradianceCosine); specular from the point of
// the segment closest to the reflected ray (eqs. 15-17), then the sphere's representative point
// around it, normalised by the line's alpha / alpha' (eq. 16) with the segment's length and the
// sphere's (alpha / alpha')^2 (eq. 14), both at the distance of the tube's centre. Length 0 gives
// the sphere light.
PATINA_INLINE LightShares tubeLightSharesWith(PackedLight light, bool windowed, bool karis, AreaLightMethod method,
                                              SurfaceMaterial material, vec3 P, vec3 N, vec3 V) {
    TubeArrival arrival = tubeLightArrival(light, windowed, karis, P);
    vec3 radiance = arrival.radiance;
    vec3 towardsCentre = towardsPoint(arrival.toCentre);
    vec3 diffuse =
        diffuseFromDirection(radiance, lineIrradianceCosine(N, arrival.L0, arrival.L1), towardsCentre, material, N, V);

    vec3 R = 2.0f * dot(N, V) * N - V;   // reflect(-V, N)
    RepresentativePoint point = tubeRepresentative(arrival, light.sourceRadius, R, material.alpha, method);
    vec3 specular = specularFromDirection(radiance * point.normalization, point.L, material, N, V);
    return LightShares(diffuse, specular);
}

PATINA_INLINE vec3 shadeTubeLightWith(PackedLight light, bool windowed, bool karis, AreaLightMethod method,
                                      SurfaceMaterial material, vec3 P, vec3 N, vec3 V) {
    LightShares shares = tubeLightSharesWith(light, windowed, karis, method, material, P, N, V);
    return shares.diffuse + shares.specular;
}

// The renderer's variant (defaultAreaLightMethod, lights.glsl).
PATINA_INLINE vec3 shadeSphereLight(PackedLight light, bool windowed, bool karis, SurfaceMaterial material, vec3 P,
                                    vec3 N, vec3 V) {
    return shadeSphereLightWith(light, windowed, karis, defaultAreaLightMethod(), material, P, N, V);
}

PATINA_INLINE vec3 shadeTubeLight(PackedLight light, bool windowed, bool karis, SurfaceMaterial material, vec3 P,
                                  vec3 N, vec3 V) {
    return shadeTubeLightWith(light, windowed, karis, defaultAreaLightMethod(), material, P, N, V);
}

// Outgoing radiance towards V from one light at point P with unit normal N (zero allowed).
PATINA_INLINE vec3 shadeLight(PackedLight light, SurfaceMaterial material, vec3 P, vec3 N, vec3 V) {
    if (light.type == LIGHT_HEMISPHERE) {
        return shadeHemisphereLight(light, material, N, V);
    }
    if (light.type == LIGHT_POINT) {
        return shadePointLight(light, true, false, material, P, N, V);
    }
    if (light.type == LIGHT_SPHERE) {
        return shadeSphereLight(light, true, false, material, P, N, V);
    }
    if (light.type == LIGHT_TUBE) {
        return shadeTubeLight(light, true, false, material, P, N, V);
    }
    return shadeDirectionalLight(light, material, N, V);
}

// One light's outgoing radiance by lobe (the inspector's channels: not on the product's paths,
// which sum the lobes as they go). A hemisphere light is diffuse only.
PATINA_INLINE LightShares lightShares(PackedLight light, SurfaceMaterial material, vec3 P, vec3 N, vec3 V) {
    if (light.type == LIGHT_HEMISPHERE) {
        return LightShares(shadeHemisphereLight(light, material, N, V), vec3(0.0f));
    }
    if (light.type == LIGHT_SPHERE) {
        return sphereLightSharesWith(light, true, false, defaultAreaLightMethod(), material, P, N, V);
    }
    if (light.type == LIGHT_TUBE) {
        return tubeLightSharesWith(light, true, false, defaultAreaLightMethod(), material, P, N, V);
    }
    if (light.type == LIGHT_POINT) {
        LightArrival arrival = pointLightArrival(light, true, false, P);
        LightShares shares = sharesFromDirection(arrival.radiance, arrival.L, material, N, V);
        if (arrival.present) {
            return shares;
        }
        return LightShares(vec3(0.0f), vec3(0.0f));
    }
    return sharesFromDirection(light.radiance, light.directionToLight, material, N, V);
}

// The specular lobe's D, G and F towards one light, for the inspector's channels: L is the unit
// direction to the light's centre (a tube's midpoint, a directional light's direction), not the
// representative point, so that the three read as the textbook terms. G = Vis 4 NoL NoV.
struct InspectedTerms {
    real D;
    real G;
    vec3 F;
};

PATINA_INLINE InspectedTerms inspectedTerms(PackedLight light, SurfaceMaterial material, vec3 P, vec3 N, vec3 V) {
    vec3 toLight = light.type == LIGHT_DIRECTIONAL ? light.directionToLight
                   : light.type == LIGHT_TUBE      ? real(0.5f) * (light.position + light.tubeEnd) - P
                                                   : light.position - P;
    vec3 L = safeNormalize(toLight);
    vec3 H = safeNormalize(L + V);
    real NoV = max(dot(N, V), MIN_N_DOT_V);
    real NoL = clamp(dot(N, L), 0.0f, 1.0f);
    real NoH = clamp(dot(N, H), 0.0f, 1.0f);
    // An anisotropic lobe's own D and V (stretchedTerms), as the lights draw it.
    LobeShape shape = stretchedTerms(material, distribution(NoH, cross(N, H), material.alpha),
                                     visibility(NoV, NoL, material), NoV, NoL, NoH, H, V, L);
    return InspectedTerms(shape.D, shape.Vis * real(4.0f) * NoL * NoV,
                          surfaceFresnel(material, NoV, clamp(dot(V, H), 0.0f, 1.0f)));
}
