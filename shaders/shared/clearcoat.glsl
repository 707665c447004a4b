// KHR_materials_clearcoat (Khronos, ratified 2020), the clear coat of the `gltf` model
// (docs/SHADING.md S5): a clear dielectric layer of index 1.5 over the material, layered as the
// extension's fresnel_coat:
//   coated  = mix(material, clearcoat_brdf, clearcoat fr_c)
//           = material (1 - clearcoat fr_c) + clearcoat fr_c D(alpha_c; N_c) V(alpha_c; N_c)
//   fr_c    = 0.04 + 0.96 (1 - |V.N_c|)^5     (Schlick 1994 eq. 15 by N_c.V, as the extension writes it)
//   alpha_c = clearcoatRoughness^2; D GGX (Walter et al. 2007 eq. 33), V the height-correlated
//   Smith visibility (Heitz 2014 eq. 99): glTF 2.0 Appendix B's specular_brdf on the coat's normal.
// The coat's Fresnel reads the view alone, so the base's weight 1 - clearcoat fr_c is one number
// per pixel: it multiplies what every light and the environment give the base, and the coat's
// own lobe is added light by light. Shared GLSL / C++ (brdf.glsl says how); include after
// brdf.glsl and lights.glsl. The GPU compiles it in only for a material with a coat
// (shade.frag's PATINA_CLEARCOAT).

const real CLEARCOAT_F0 = 0.04f;   // ((1.5 - 1) / (1.5 + 1))^2: the extension's fixed index of 1.5

struct Clearcoat {
    real factor;      // clearcoatFactor times its map's R: the layer's weight
    real roughness;   // clearcoatRoughnessFactor times its map's G, after MIN_PERCEPTUAL_ROUGHNESS
    real alpha;       // roughness^2
    vec3 normal;      // N_c: the coat's normal map's, else the geometric normal (unit)
    real NoV;         // N_c.V, floored at MIN_N_DOT_V as the base's
    real fresnel;     // fr_c
};

// fr_c of the extension: 0.04 + 0.96 (1 - |V.N_c|)^5, as repeated products.
PATINA_INLINE real clearcoatFresnel(real VoN) {
    real m = clamp(1.0f - abs(VoN), 0.0f, 1.0f);
    real m2 = m * m;
    return CLEARCOAT_F0 + (1.0f - CLEARCOAT_F0) * (m2 * m2 * m);
}

PATINA_INLINE Clearcoat deriveClearcoat(real factor, real roughness, vec3 normal, vec3 V) {
    real r = max(roughness, MIN_PERCEPTUAL_ROUGHNESS);
    real VoN = dot(normal, V);
    return Clearcoat(factor, r, r * r, normal, max(VoN, MIN_N_DOT_V), clearcoatFresnel(VoN));
}

// What of the base leaves through the coat: 1 - clearcoat fr_c.
PATINA_INLINE real clearcoatBaseWeight(Clearcoat coat) {
    return 1.0f - coat.factor * coat.fresnel;
}

// R_c, the coat's mirror direction.
PATINA_INLINE vec3 clearcoatReflection(Clearcoat coat, vec3 V) {
    return 2.0f * dot(coat.normal, V) * coat.normal - V;   // reflect(-V, N_c)
}

// The coated radiance: `base`, what the material beneath gives (every light, the environment,
// its emission), seen through the coat, plus `coat`, the coat's own lobe from the same light:
// the extension's mix(material, clearcoat_brdf, clearcoat fr_c) once the lights are summed.
PATINA_INLINE vec3 clearcoatOver(vec3 base, vec3 coat, Clearcoat layer) {
    return base * clearcoatBaseWeight(layer) + coat;
}

// The coat's layer term clearcoat fr_c D V towards unit L (1/sr, no cosine); 0 where L = -V
// (no half vector, as evaluateBrdf's guard).
PATINA_INLINE real clearcoatBrdf(Clearcoat coat, vec3 V, vec3 L) {
    vec3 LplusV = L + V;
    real lengthSquared = dot(LplusV, LplusV);
    if (lengthSquared <= 0.0f) {
        return 0.0f;
    }
    vec3 H = LplusV * inversesqrt(lengthSquared);
    real NoH = clamp(dot(coat.normal, H), 0.0f, 1.0f);
    real NoL = clamp(dot(coat.normal, L), 0.0f, 1.0f);
    real D = D_GGX(NoH, cross(coat.normal, H), coat.alpha);
    return coat.factor * coat.fresnel * D * V_SmithGGXCorrelated(coat.NoV, NoL, coat.alpha);
}

// The coat's radiance towards V from `radiance` arriving along unit L, with N_c.L: nothing from
// behind the coat (a select, as shadeFromDirection's).
PATINA_INLINE vec3 clearcoatFromDirection(vec3 radiance, vec3 L, Clearcoat coat, vec3 V) {
    real NoL = dot(coat.normal, L);
    vec3 value = radiance * (min(NoL, 1.0f) * clearcoatBrdf(coat, V, L));
    return NoL > 0.0f ? value : vec3(0.0f);
}

PATINA_INLINE vec3 clearcoatPointLight(PackedLight light, bool windowed, bool karis, Clearcoat coat, vec3 P, vec3 V) {
    LightArrival arrival = pointLightArrival(light, windowed, karis, P);
    vec3 value = clearcoatFromDirection(arrival.radiance, arrival.L, coat, V);
    return arrival.present ? value : vec3(0.0f);
}

PATINA_INLINE vec3 clearcoatDirectionalLight(PackedLight light, Clearcoat coat, vec3 V) {
    return clearcoatFromDirection(light.radiance, light.directionToLight, coat, V);
}

// A sphere light on the coat: Karis 2013's representative point (eq. 11) about the coat's own
// reflection, normalised by (alpha_c / alpha_c')^2 (eq. 14), as sphereLightSharesWith's specular.
PATINA_INLINE vec3 clearcoatSphereLight(PackedLight light, bool windowed, bool karis, Clearcoat coat, vec3 P, vec3 V) {
    SphereArrival arrival = sphereLightArrival(light, windowed, karis, P);
    RepresentativePoint point =
        sphereRepresentative(arrival, light.sourceRadius, clearcoatReflection(coat, V), coat.alpha, defaultAreaLightMethod());
    vec3 value = clearcoatFromDirection(arrival.radiance * point.normalization, point.L, coat, V);
    return arrival.present ? value : vec3(0.0f);
}

// A tube light on the coat: the segment's representative point (Karis 2013 eqs. 14-17) about the
// coat's own reflection, as tubeLightSharesWith's specular.
PATINA_INLINE vec3 clearcoatTubeLight(PackedLight light, bool windowed, bool karis, Clearcoat coat, vec3 P, vec3 V) {
    TubeArrival arrival = tubeLightArrival(light, windowed, karis, P);
    RepresentativePoint point =
        tubeRepresentative(arrival, light.sourceRadius, clearcoatReflection(coat, V), coat.alpha, defaultAreaLightMethod());
    return clearcoatFromDirection(arrival.radiance * point.normalization, point.L, coat, V);
}

// One light's coat term, whatever its type. A hemisphere light is diffuse only (docs/SHADING.md
// S1): the coat reflects none of it, only weighs the base beneath.
PATINA_INLINE vec3 clearcoatLight(PackedLight light, Clearcoat coat, vec3 P, vec3 V) {
    if (light.type == LIGHT_HEMISPHERE) {
        return vec3(0.0f);
    }
    if (light.type == LIGHT_POINT) {
        return clearcoatPointLight(light, true, false, coat, P, V);
    }
    if (light.type == LIGHT_SPHERE) {
        return clearcoatSphereLight(light, true, false, coat, P, V);
    }
    if (light.type == LIGHT_TUBE) {
        return clearcoatTubeLight(light, true, false, coat, P, V);
    }
    return clearcoatDirectionalLight(light, coat, V);
}

// Under an environment, the split sum as the Khronos glTF Sample Viewer draws the coat: the
// prefiltered radiance LD(R_c, clearcoatRoughness) times the coat's directional albedo
// 0.04 A + B, (A, B) the model's split-sum table at (N_c.V, clearcoatRoughness) (Karis 2013
// eq. 8), weighted by clearcoat. R_c is the mirror direction about N_c.
PATINA_INLINE vec3 clearcoatSplitSum(Clearcoat coat, vec3 prefiltered, vec2 ab) {
    return coat.factor * prefiltered * (CLEARCOAT_F0 * ab.x + ab.y);
}

