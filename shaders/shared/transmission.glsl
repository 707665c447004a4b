// KHR_materials_transmission (Khronos, ratified 2021) and KHR_materials_volume (Khronos,
// ratified 2021), thin-walled, of the `gltf` model (docs/SHADING.md S7). The transmission
// replaces that fraction of the dielectric's diffuse by the specular BTDF through the surface
// (glTF 2.0 Appendix B with the extension's dielectric_brdf):
//   dielectric_brdf = fresnel_mix(specular_brdf, mix(diffuse_brdf, specular_btdf, transmission))
//   material        = mix(dielectric_brdf, metal_brdf, metallic)
// so the diffuse colour loses the factor (transmissionDiffuse) and what passes is tinted by
// baseColor: transmission (1 - metallic) baseColor (the extension's "tinted by the base color").
// Thin-walled: the light leaves the far side along the direction it entered, unrefracted, so
// the environment seen through is the one along -V and a light behind the surface is seen as
// its reflection in the surface plane (the BTDF is the reflection lobe mirrored, as the Khronos
// glTF-Sample-Viewer's punctual transmission does):
//   L' = L - 2 (N.L) N,  H = normalize(L' + V)
//   f_t = (1 - F(V.H)) D(N.H) Vis(N.V, N.L')  with glTF's GGX D, height-correlated Smith Vis
//         and Schlick's F of the dielectric's F0 (Appendix B), alpha = roughness^2
// (the extension scales alpha by clamp(2 ior - 2, 0, 1) for thin walls: 1 at Patina's ior 1.5).
// The light arrives with its cosine on the back side, |N.L| = N.L' (the viewer omits it).
// KHR_materials_volume's Beer-Lambert law over the thickness (thicknessFactor in the mesh's
// units, times the node's scale; the extension's section "Attenuation"):
//   T = attenuationColor ^ (thickness / attenuationDistance),  no attenuation at an infinite
//   distance (Patina writes 0 for it)
// Thin-walled: T applies once, along -V, without refraction (the extension refracts; Patina
// does not).
// Shared GLSL / C++ (brdf.glsl says how); include after brdf.glsl and lights.glsl. The GPU
// compiles the transmission in only for a material with one (shade.frag's PATINA_TRANSMISSION).

struct Transmission {
    vec3 color;     // transmission (1 - metallic) baseColor T: what passes, tinted and attenuated
    vec3 f0;        // the dielectric's F0 (0.08 specular, KHR_materials_specular's tint in)
    real weight;    // KHR_materials_specular's weight of its Fresnel (1 without)
    real alpha;     // the base's roughness^2: the wall's GGX
    real NoV;       // N.V, floored at MIN_N_DOT_V as the base's
    // KHR_materials_iridescence's film over the dielectric: its Fresnel at N.V and its strength
    // (0: none), which the reflection mixes in and so takes from what passes.
    vec3 film;
    real iridescence;
};

// KHR_materials_volume: T = c^(d / d_at) per channel; 1 where the distance is 0 or below
// (infinite) or there is no thickness. A colour of 0 stays finite (c floored at 1e-6).
PATINA_INLINE vec3 volumeAttenuation(vec3 attenuationColor, real attenuationDistance, real thickness) {
    if (!(attenuationDistance > 0.0f) || !(thickness > 0.0f)) {
        return vec3(1.0f);
    }
    return pow(max(attenuationColor, vec3(1e-6f)), vec3(thickness / attenuationDistance));
}

// `material` as deriveSurfaceMaterial made it (before transmissionDiffuse), `attenuation` the
// volume's T.
PATINA_INLINE Transmission deriveTransmission(SurfaceMaterial material, real transmission, vec3 attenuation, vec3 N,
                                              vec3 V) {
    real NoV = max(dot(N, V), MIN_N_DOT_V);
    vec3 film = vec3(0.0f);
    real iridescence = 0.0f;
#if defined(PATINA_IRIDESCENT_FIELDS) && !defined(PATINA_NO_THIN_FILM)
    if (material.iridescence > 0.0f) {
        film = filmFresnelAt(material, NoV).dielectric;
        iridescence = material.iridescence;
    }
#endif
    return Transmission(material.diffuseColor * (transmission * attenuation), material.dielectricF0,
                        material.specularWeight, material.alpha, NoV, film, iridescence);
}

// The diffuse that stays: mix(diffuse_brdf, specular_btdf, transmission)'s first term.
PATINA_INLINE SurfaceMaterial transmissionDiffuse(SurfaceMaterial material, real transmission) {
    SurfaceMaterial kept = material;
    kept.diffuseColor = material.diffuseColor * (1.0f - transmission);
    return kept;
}

// What the wall's reflection leaves to the light through it at V.H: 1 - w F with Schlick's F of
// the dielectric's F0 (glTF 2.0 Appendix B, whatever the model's own) weighted by
// KHR_materials_specular's w, a film's Fresnel mixed in by its strength (as dielectricFresnel
// mixes it), its largest channel (the extension's max_value: the transmission is fresnel_mix's
// base).
PATINA_INLINE vec3 transmissionKept(Transmission t, real VoH) {
    vec3 F = mix(F_Schlick90(t.f0 * t.weight, t.weight, VoH), t.film, t.iridescence);
    return vec3(minValue(vec3(1.0f) - F));
}

// f_t towards a light along unit L behind the surface (N.L < 0), times the colour, no cosine
// (1/sr); 0 for a light in front.
PATINA_INLINE vec3 transmissionBtdf(Transmission t, vec3 N, vec3 V, vec3 L) {
    real NoL = dot(N, L);
    if (!(NoL < 0.0f)) {
        return vec3(0.0f);
    }
    vec3 mirrored = L - 2.0f * NoL * N;
    vec3 H = safeNormalize(mirrored + V);
    real NoH = clamp(dot(N, H), 0.0f, 1.0f);
    real VoH = clamp(dot(V, H), 0.0f, 1.0f);
    real lobe = D_GGX(NoH, cross(N, H), t.alpha) * V_SmithGGXCorrelated(t.NoV, min(-NoL, 1.0f), t.alpha);
    return t.color * transmissionKept(t, VoH) * lobe;
}

// Light of `radiance` arriving along unit L with back-side arrival `illuminance` (|N.L| for a
// point): what passes towards V.
PATINA_INLINE vec3 transmissionFromDirection(vec3 radiance, real illuminance, vec3 L, Transmission t, vec3 N,
                                             vec3 V) {
    return radiance * (max(illuminance, 0.0f) * transmissionBtdf(t, N, V, L));
}

// Light without one direction seen through the wall along -V, `through` its radiance there
// (blurred by the wall's roughness), `weight` what the reflection leaves to what is beneath
// (the split sum's weight of the diffuse, ibl_model.glsl's transmittedEnvironmentWeight, or
// 1 - F(N.V) where there is no table).
PATINA_INLINE vec3 transmissionThrough(Transmission t, vec3 through, vec3 weight) {
    return t.color * weight * through;
}

PATINA_INLINE vec3 transmissionPointLight(PackedLight light, bool windowed, bool karis, Transmission t, vec3 P,
                                          vec3 N, vec3 V) {
    LightArrival arrival = pointLightArrival(light, windowed, karis, P);
    vec3 value = transmissionFromDirection(arrival.radiance, -dot(N, arrival.L), arrival.L, t, N, V);
    return arrival.present ? value : vec3(0.0f);
}

PATINA_INLINE vec3 transmissionDirectionalLight(PackedLight light, Transmission t, vec3 N, vec3 V) {
    return transmissionFromDirection(light.radiance, -dot(N, light.directionToLight), light.directionToLight, t, N,
                                     V);
}

// A hemisphere light seen through along -V: its sky or ground as hemisphereRadiance blends them
// at -V, weighted by 1 - F(N.V) (transmissionKept).
PATINA_INLINE vec3 transmissionHemisphereLight(PackedLight light, Transmission t, vec3 V) {
    return transmissionThrough(t, hemisphereRadiance(light, -V), transmissionKept(t, t.NoV));
}

// A sphere light through the wall as a point light at its centre (as sheen.glsl lights its lobe).
PATINA_INLINE vec3 transmissionSphereLight(PackedLight light, bool windowed, bool karis, Transmission t, vec3 P,
                                           vec3 N, vec3 V) {
    SphereArrival arrival = sphereLightArrival(light, windowed, karis, P);
    vec3 L = arrival.toCentre * arrival.inverseDistance;
    vec3 value = transmissionFromDirection(arrival.radiance, -dot(N, L), L, t, N, V);
    return arrival.present ? value : vec3(0.0f);
}

// A tube light towards its centre, lit by the line's irradiance on the back side.
PATINA_INLINE vec3 transmissionTubeLight(PackedLight light, bool windowed, bool karis, Transmission t, vec3 P, vec3 N,
                                         vec3 V) {
    TubeArrival arrival = tubeLightArrival(light, windowed, karis, P);
    return transmissionFromDirection(arrival.radiance, lineIrradianceCosine(-N, arrival.L0, arrival.L1),
                                     towardsPoint(arrival.toCentre), t, N, V);
}

// One light's transmitted light, whatever its type.
PATINA_INLINE vec3 transmissionLight(PackedLight light, Transmission t, vec3 P, vec3 N, vec3 V) {
    if (light.type == LIGHT_HEMISPHERE) {
        return transmissionHemisphereLight(light, t, V);
    }
    if (light.type == LIGHT_POINT) {
        return transmissionPointLight(light, true, false, t, P, N, V);
    }
    if (light.type == LIGHT_SPHERE) {
        return transmissionSphereLight(light, true, false, t, P, N, V);
    }
    if (light.type == LIGHT_TUBE) {
        return transmissionTubeLight(light, true, false, t, P, N, V);
    }
    return transmissionDirectionalLight(light, t, N, V);
}
