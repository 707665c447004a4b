// KHR_materials_sheen (Khronos, ratified 2021), the sheen of the `gltf` model (docs/SHADING.md
// S6): a layer of fibres over the material, layered by the extension's albedo scaling:
//   f       = f_sheen + f_base * sheenAlbedoScaling
//   f_sheen = sheenColor D(alpha) V(N.V, N.L)                (the extension's F = 1)
//   D       = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi)   (Estevez & Kulla 2017, "Production
//             Friendly Microfacet Sheen BRDF", eq. 2: the "Charlie" distribution), alpha = r^2
//   V       = 1 / (4 (N.L + N.V - N.L N.V))                   (Neubelt & Pettineo 2013, "Crafting a
//             Next-Gen Material Pipeline for The Order: 1886", eq. 4; Ashikhmin & Premoze 2007's
//             form, the extension's simpler visibility, not Estevez & Kulla's fitted Lambda)
//   sheenAlbedoScaling = min(1 - max3(sheenColor) E(N.V), 1 - max3(sheenColor) E(N.L))
// E(mu, r): the sheen lobe's directional albedo, integral of D V N.L over the hemisphere, from
// the table engine/shading/sheen_table.cpp integrates (Estevez & Kulla 2017 section 3's albedo
// scaling). Under an environment and a hemisphere light (no L) E(N.V) alone, as the extension
// allows, and the lobe lit by the irradiance at N (see sheenIrradianceShare).
// This visibility is not energy conserving (the extension says so): at grazing views of a
// smooth sheen E passes 1 (5.7 at r = 0.045, N.V = 0.01). Where it does, the lobe is scaled by
// 1 / E(N.V), so that its albedo is 1 at most, and the scaling reads E capped at 1: a sheen over
// a white base then reflects at most what arrives (tests/shading/test_sheen.cpp's furnace).
// Shared GLSL / C++ (brdf.glsl says how); include after brdf.glsl and lights.glsl. The includer
// defines sheenTexel(x, y), the table at N.V = x / 31, r = y / 31 (a texelFetch on the GPU, the
// table on the CPU), as energy_table.glsl's energyTexel. The GPU compiles the sheen in only for a
// material with one (shade.frag's PATINA_SHEEN).

const int SHEEN_TABLE_SIZE = 32;   // N.V and r at i / 31, i = 0..31

// 1/alpha grows without bound as r goes to 0: D's factor 2 + 1/alpha overflows and
// sin^(1/alpha) collapses onto the horizon, where L lies below it (N.L = -N.V for H there), so
// the lobe is 0 times infinity. The base's roughness floor (1/alpha = 494 at 0.045) keeps D's
// peak at 79 in fp32 and the table's first row a lobe that can be integrated.
PATINA_INLINE real sheenPerceptualRoughness(real roughness) {
    return max(roughness, MIN_PERCEPTUAL_ROUGHNESS);
}

// The Charlie distribution at N.H for alpha (Estevez & Kulla 2017 eq. 2), sin^2 = 1 - N.H^2.
PATINA_INLINE real sheenDistribution(real NoH, real alpha) {
    real inverseAlpha = 1.0f / alpha;
    real sin2h = max(1.0f - NoH * NoH, 0.0f);
    return (2.0f + inverseAlpha) * pow(sin2h, 0.5f * inverseAlpha) / (2.0f * PATINA_PI);
}

// Neubelt & Pettineo 2013 eq. 4: 1 / (4 (N.L + N.V - N.L N.V)); positive while N.V > 0.
PATINA_INLINE real sheenVisibility(real NoV, real NoL) {
    return 1.0f / (4.0f * (NoL + NoV - NoL * NoV));
}

// E(N.V, r), bilinear in the table as energy_table.glsl interpolates its own.
PATINA_INLINE real sheenAlbedo(real NoV, real roughness) {
    TableCoordinate c = tableCoordinate(NoV, roughness, SHEEN_TABLE_SIZE);
    real bottom = mix(sheenTexel(c.x0, c.y0), sheenTexel(c.x0 + 1, c.y0), c.fx);
    real top = mix(sheenTexel(c.x0, c.y0 + 1), sheenTexel(c.x0 + 1, c.y0 + 1), c.fx);
    return mix(bottom, top, c.fy);
}

struct Sheen {
    vec3 color;          // sheenColorFactor times its map's RGB
    real roughness;      // sheenRoughnessFactor times its map's A, after the floor
    real alpha;          // roughness^2
    real NoV;            // N.V, floored at MIN_N_DOT_V as the base's
    real strength;       // max3(color)
    real albedo;         // E(N.V) capped at 1
    real lobeScale;      // E(N.V) capped at 1 over E(N.V): 1 unless the lobe would pass 1
};

PATINA_INLINE Sheen deriveSheen(vec3 color, real roughness, vec3 N, vec3 V) {
    real r = sheenPerceptualRoughness(roughness);
    real NoV = max(dot(N, V), MIN_N_DOT_V);
    real E = sheenAlbedo(NoV, r);
    real capped = min(E, 1.0f);
    return Sheen(color, r, r * r, NoV, max(max(color.x, color.y), color.z), capped, E > 1.0f ? capped / E : 1.0f);
}

// What of the base a light along L reaches: the extension's sheenAlbedoScaling.
PATINA_INLINE real sheenBaseWeight(Sheen sheen, real NoL) {
    real albedoL = min(sheenAlbedo(clamp(NoL, 0.0f, 1.0f), sheen.roughness), 1.0f);
    return 1.0f - sheen.strength * max(sheen.albedo, albedoL);
}

// The same with E(N.V) alone: under the environment and hemisphere lights, and for the light
// through a thin wall beneath the sheen (KHR_materials_transmission): the extension's albedo
// scaling weighs everything under the fibres, and that light leaves them towards V.
PATINA_INLINE real sheenViewWeight(Sheen sheen) {
    return 1.0f - sheen.strength * sheen.albedo;
}

// f_sheen towards unit L (1/sr, no cosine): 0 where L = -V (no half vector) or below N.
PATINA_INLINE vec3 sheenBrdf(Sheen sheen, vec3 N, vec3 V, vec3 L) {
    vec3 LplusV = L + V;
    real lengthSquared = dot(LplusV, LplusV);
    real NoL = dot(N, L);
    if (lengthSquared <= 0.0f || NoL <= 0.0f) {
        return vec3(0.0f);
    }
    real NoH = clamp(dot(N, LplusV * inversesqrt(lengthSquared)), 0.0f, 1.0f);
    real lobe = sheenDistribution(NoH, sheen.alpha) * sheenVisibility(sheen.NoV, min(NoL, 1.0f));
    return sheen.color * (lobe * sheen.lobeScale);
}

// One light's sheen: what the sheen adds and what the base beneath is weighed by.
struct SheenShare {
    vec3 sheen;
    real baseWeight;
};

// The sheened radiance of one light: f_base's share weighed, f_sheen's added.
PATINA_INLINE vec3 sheenOver(vec3 base, SheenShare share) {
    return base * share.baseWeight + share.sheen;
}

// Light of `radiance` arriving along unit L with cosine-weighted arrival `illuminance` (N.L for
// a point): the lobe towards L, the base weighed by E at N.L; nothing from behind the surface.
PATINA_INLINE SheenShare sheenFromDirection(vec3 radiance, real illuminance, vec3 L, Sheen sheen, vec3 N, vec3 V) {
    real NoL = dot(N, L);
    vec3 value = radiance * (illuminance * sheenBrdf(sheen, N, V, L));
    return SheenShare(NoL > 0.0f ? value : vec3(0.0f), sheenBaseWeight(sheen, NoL));
}

// Light without one direction, of irradiance `irradiance` at N (an environment's, a hemisphere
// light's): the lobe's albedo E(N.V) times sheenColor times irradiance / pi (the lobe as a
// diffuse reflector of its albedo), the base weighed by E(N.V).
PATINA_INLINE SheenShare sheenIrradianceShare(Sheen sheen, vec3 irradiance) {
    return SheenShare(sheen.color * (sheen.albedo / PATINA_PI) * irradiance, sheenViewWeight(sheen));
}

PATINA_INLINE SheenShare sheenPointLight(PackedLight light, bool windowed, bool karis, Sheen sheen, vec3 P, vec3 N,
                                         vec3 V) {
    LightArrival arrival = pointLightArrival(light, windowed, karis, P);
    SheenShare share = sheenFromDirection(arrival.radiance, min(dot(N, arrival.L), 1.0f), arrival.L, sheen, N, V);
    return arrival.present ? share : SheenShare(vec3(0.0f), 1.0f);
}

PATINA_INLINE SheenShare sheenDirectionalLight(PackedLight light, Sheen sheen, vec3 N, vec3 V) {
    return sheenFromDirection(light.radiance, min(dot(N, light.directionToLight), 1.0f), light.directionToLight, sheen,
                              N, V);
}

PATINA_INLINE SheenShare sheenHemisphereLight(PackedLight light, Sheen sheen, vec3 N) {
    return sheenIrradianceShare(sheen, hemisphereRadiance(light, N));
}

// A sphere light: the lobe and the scaling towards its centre, lit as the base's diffuse is
// (the centre as a point light): the sheen's lobe is broad, not about the mirror direction.
PATINA_INLINE SheenShare sheenSphereLight(PackedLight light, bool windowed, bool karis, Sheen sheen, vec3 P, vec3 N,
                                          vec3 V) {
    SphereArrival arrival = sphereLightArrival(light, windowed, karis, P);
    vec3 L = arrival.toCentre * arrival.inverseDistance;
    SheenShare share = sheenFromDirection(arrival.radiance, min(dot(N, L), 1.0f), L, sheen, N, V);
    return arrival.present ? share : SheenShare(vec3(0.0f), 1.0f);
}

// A tube light: the lobe and the scaling towards its centre, lit by the line's irradiance as
// the base's diffuse is (lineIrradianceCosine).
PATINA_INLINE SheenShare sheenTubeLight(PackedLight light, bool windowed, bool karis, Sheen sheen, vec3 P, vec3 N,
                                        vec3 V) {
    TubeArrival arrival = tubeLightArrival(light, windowed, karis, P);
    return sheenFromDirection(arrival.radiance, lineIrradianceCosine(N, arrival.L0, arrival.L1),
                              towardsPoint(arrival.toCentre), sheen, N, V);
}

// One light's sheen, whatever its type.
PATINA_INLINE SheenShare sheenLight(PackedLight light, Sheen sheen, vec3 P, vec3 N, vec3 V) {
    if (light.type == LIGHT_HEMISPHERE) {
        return sheenHemisphereLight(light, sheen, N);
    }
    if (light.type == LIGHT_POINT) {
        return sheenPointLight(light, true, false, sheen, P, N, V);
    }
    if (light.type == LIGHT_SPHERE) {
        return sheenSphereLight(light, true, false, sheen, P, N, V);
    }
    if (light.type == LIGHT_TUBE) {
        return sheenTubeLight(light, true, false, sheen, P, N, V);
    }
    return sheenDirectionalLight(light, sheen, N, V);
}
