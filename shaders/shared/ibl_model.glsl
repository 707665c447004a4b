// Image-based lighting, the parts that depend on the BRDF model: its environment BRDF table
// and the split sum (Karis 2013, "Image-based lighting", eqs. 6-8). Shared GLSL / C++; include
// after energy_table.glsl, brdf_model.glsl and ibl.glsl. The includer defines environmentBrdfTexel(x, y), the
// model's (A, B) at NoV = x / 63, r = y / 63 (a texelFetch on the GPU, the table on the CPU), so
// both sides interpolate with the same arithmetic, as energy_table.glsl does.
const int ENVIRONMENT_BRDF_SIZE = 64;

// Fc, the weight of (1 - F0) in the model's Fresnel: F = F0 (1 - Fc) + Fc. The exact dielectric
// Fresnel is not of this form; its table takes Schlick's (1 - VoH)^5 (docs/LIGHTING.md measures it).
PATINA_INLINE real fresnelWeight(real VoH) {
#if PATINA_F == PATINA_F_SCHLICK_SG
    return exp2((-5.55473f * VoH - 6.98316f) * VoH);
#else
    real m = clamp(1.0f - VoH, 0.0f, 1.0f);
    real m2 = m * m;
    return m2 * m2 * m;
#endif
}

// (A, B) of Karis 2013 eq. 8 (listing IntegrateBRDF): the specular lobe with F split out,
// V = (sqrt(1 - NoV^2), 0, NoV) about N = +Z, H from the shared GGX sampler;
// G_Vis = G VoH / (NoH NoV) = Vis 4 NoL VoH / NoH with Vis = G / (4 NoL NoV).
PATINA_INLINE vec2 integrateEnvironmentBrdf(real NoV, real roughness, uint samples) {
    SurfaceMaterial material = deriveSurfaceMaterial(vec3(1.0f), roughness, 0.5f, 0.0f);
    NoV = max(NoV, MIN_N_DOT_V);
    vec3 N = vec3(0.0f, 0.0f, 1.0f);
    vec3 V = vec3(sqrt(max(1.0f - NoV * NoV, 0.0f)), 0.0f, NoV);
    real a = 0.0f;
    real b = 0.0f;
    for (uint i = 0u; i < samples; ++i) {
        vec3 H = importanceSampleGGX(hammersley(i, samples), material.alpha, N);
        real VoH = clamp(dot(V, H), 0.0f, 1.0f);
        vec3 L = 2.0f * VoH * H - V;
        real NoL = L.z;
        real NoH = H.z;
        if (NoL > 0.0f && NoH > 0.0f) {
            real gVis = environmentVisibility(NoV, min(NoL, 1.0f), material) * 4.0f * NoL * VoH / NoH;
            real fc = fresnelWeight(VoH);
            a += (1.0f - fc) * gVis;
            b += fc * gVis;
        }
    }
    return vec2(a, b) / real(samples);
}

// Bilinear lookup in the model's table, placed as the energy table's (energy_table.glsl).
PATINA_INLINE vec2 environmentBrdfLookup(real NoV, real roughness) {
    TableCoordinate c = tableCoordinate(NoV, roughness, ENVIRONMENT_BRDF_SIZE);
    vec2 bottom = mix(environmentBrdfTexel(c.x0, c.y0), environmentBrdfTexel(c.x0 + 1, c.y0), c.fx);
    vec2 top = mix(environmentBrdfTexel(c.x0, c.y0 + 1), environmentBrdfTexel(c.x0 + 1, c.y0 + 1), c.fx);
    return mix(bottom, top, c.fy);
}

// Fdez-Aguera 2019, "A Multiple-Scattering Microfacet Model for Real-Time Image-based
// Lighting" (JCGT 8(1)), for one Fresnel lobe of F0 `f0` at (NoV, r) with the model's table
// (A, B): the single-scattered energy FssEss = k_S A + B with the roughness-dependent Fresnel
// k_S = F0 + (max(1 - r, F0) - F0)(1 - NoV)^5 (sec. 3), and the multiple-scattered energy
// Fms Ems = Ems FssEss F_avg / (1 - F_avg Ems), Ems = 1 - (A + B), F_avg = F0 + (1 - F0) / 21
// (sec. 4-5, eqs. 12-16). Their sum is the lobe's directional albedo; 1 - it is what a layer
// beneath it receives.
struct ScatteredEnergy {
    vec3 single;     // FssEss
    vec3 multiple;   // Fms Ems
};

// KHR_materials_specular's weight w (1 without) scales the lobe's Fresnel, so FssEss and F_avg
// both (as the Khronos glTF-Sample-Viewer's IBL applies its specularWeight); `f0` before it.
PATINA_INLINE ScatteredEnergy scatteredEnergy(vec3 f0, real weight, vec2 ab, real NoV, real roughness) {
    real m = clamp(1.0f - NoV, 0.0f, 1.0f);
    real m5 = m * m * m * m * m;
    vec3 kS = f0 + (max(vec3(1.0f - roughness), f0) - f0) * m5;
    vec3 single = weight * (kS * ab.x + vec3(ab.y));
    real ems = 1.0f - (ab.x + ab.y);
    vec3 average = weight * (f0 + (vec3(1.0f) - f0) * (1.0f / 21.0f));
    return ScatteredEnergy(single, ems * single * average / (vec3(1.0f) - average * ems));
}

// KHR_materials_iridescence's lobe under the environment: the film's Fresnel F is evaluated once,
// at N.V (the extension's "Iridescence BRDF"), so over the lobe it is a constant and its
// single-scattered energy is F (A + B), the lobe's albedo times F; the multiple-scattered is
// Fdez-Aguera's with F as F_avg (eqs. 12-16), as scatteredEnergy's with Schlick's.
PATINA_INLINE ScatteredEnergy filmScatteredEnergy(vec3 film, vec2 ab) {
    vec3 single = film * (ab.x + ab.y);
    real ems = 1.0f - (ab.x + ab.y);
    return ScatteredEnergy(single, ems * single * film / (vec3(1.0f) - film * ems));
}

PATINA_INLINE ScatteredEnergy mixedEnergy(ScatteredEnergy a, ScatteredEnergy b, real t) {
    return ScatteredEnergy(mix(a.single, b.single, t), mix(a.multiple, b.multiple, t));
}

// glTF's two lobes' energies at (N.V, r) (the gltf models, PATINA_FD_LAMBERT_FRESNEL_MIX): the
// dielectric's (KHR_materials_specular's F0 and weight) and the metal's, each with the film's
// mixed in by its strength (the extension's mix(F, F_film, iridescence)), the multiple-scattered
// only with PATINA_MS_FDEZ_AGUERA.
struct LobeEnergies {
    ScatteredEnergy dielectric;
    ScatteredEnergy metal;
};

PATINA_INLINE LobeEnergies lobeEnergies(SurfaceMaterial material, vec2 ab, real NoV) {
    ScatteredEnergy dielectric =
        scatteredEnergy(material.dielectricF0, material.specularWeight, ab, NoV, material.roughness);
    ScatteredEnergy metal = scatteredEnergy(material.baseColor, 1.0f, ab, NoV, material.roughness);
#if defined(PATINA_IRIDESCENT_FIELDS) && !defined(PATINA_NO_THIN_FILM)
    if (material.iridescence > 0.0f) {
        IridescentFresnel film = filmFresnelAt(material, NoV);
        dielectric = mixedEnergy(dielectric, filmScatteredEnergy(film.dielectric, ab), material.iridescence);
        metal = mixedEnergy(metal, filmScatteredEnergy(film.metal, ab), material.iridescence);
    }
#endif
#if PATINA_MS != PATINA_MS_FDEZ_AGUERA
    dielectric.multiple = vec3(0.0f);
    metal.multiple = vec3(0.0f);
#endif
    return LobeEnergies(dielectric, metal);
}

// The split sum: LD (F0 A + B) for the specular (Karis 2013, eq. 8), with the model's Turquin
// compensation taken from the same table (E = A + B), plus the Lambert diffuse c_diff / pi E(N)
// from the irradiance map. Models with Burley's diffuse take Lambert's here.
// glTF's two lobes (PATINA_FD_LAMBERT_FRESNEL_MIX: the gltf models) are mixed by metallic
// instead, each with the single-scattered energy of Fdez-Aguera's roughness-dependent Fresnel
// (scatteredEnergy) from LD and, with PATINA_MS_FDEZ_AGUERA, the multiple-scattered from the
// irradiance (it leaves the surface diffusely, sec. 5); the dielectric's diffuse is weighted by
// 1 - its specular albedo, as fresnel_mix weighs it per light.
// Its two lobes apart (the inspector's channels); splitSum is their sum.
PATINA_INLINE LightShares splitSumShares(SurfaceMaterial material, real NoV, vec3 prefiltered, vec3 irradiance) {
    vec2 ab = environmentBrdfLookup(NoV, material.roughness);
#if PATINA_FD == PATINA_FD_LAMBERT_FRESNEL_MIX
    LobeEnergies lobes = lobeEnergies(material, ab, NoV);
    vec3 single = mix(lobes.dielectric.single, lobes.metal.single, material.metallic);
    vec3 multiple = mix(lobes.dielectric.multiple, lobes.metal.multiple, material.metallic);
    vec3 specular = prefiltered * single + Fd_Lambert(multiple) * irradiance;
    // 1 - the largest channel's albedo, as fresnel_mix weighs the diffuse by max_value (equal
    // channels but for KHR_materials_specular's colour and a film's).
    real beneath = minValue(vec3(1.0f) - lobes.dielectric.single - lobes.dielectric.multiple);
#if defined(PATINA_NO_DIFFUSE)
    return LightShares(vec3(0.0f), specular);
#else
    return LightShares(Fd_Lambert(material.diffuseColor) * beneath * irradiance, specular);
#endif
#else
    // F = f0 (1 - Fc) + f90 Fc: the table's A and B weigh f0 and f90 (1 but for a specular weight).
    vec3 specular = prefiltered * (material.f0 * ab.x + vec3(material.f90 * ab.y));
    vec3 compensated = material.f0;   // the F0 Turquin's compensation scales by
#if defined(PATINA_IRIDESCENT_FIELDS) && !defined(PATINA_NO_THIN_FILM)
    // As lobeEnergies: the film's F at N.V times the lobe's albedo A + B, mixed in by its
    // strength; these models' diffuse takes nothing for the specular.
    if (material.iridescence > 0.0f) {
        IridescentFresnel film = filmFresnelAt(material, NoV);
        vec3 F = mix(film.dielectric, film.metal, material.metallic);
        specular = mix(specular, prefiltered * F * (ab.x + ab.y), material.iridescence);
        compensated = mix(compensated, F, material.iridescence);
    }
#endif
#if PATINA_MS == PATINA_MS_TURQUIN
    real albedo = max(ab.x + ab.y, 1e-4f);
    specular *= vec3(1.0f) + compensated * (1.0f / albedo - 1.0f);
#endif
#if defined(PATINA_NO_DIFFUSE)
    return LightShares(vec3(0.0f), specular);
#else
    return LightShares(Fd_Lambert(material.diffuseColor) * irradiance, specular);
#endif
#endif
}

// KHR_materials_transmission under an environment (transmission.glsl's transmissionThrough):
// what the dielectric's reflection leaves to the light through the wall, weighted as the split
// sum above weighs the diffuse (1 - the dielectric's FssEss and, with PATINA_MS_FDEZ_AGUERA,
// Fms Ems, for glTF's models; 1 - (F0 A + B) for the others; a film's mixed in by its strength).
PATINA_INLINE vec3 transmittedEnvironmentWeight(SurfaceMaterial material, real NoV) {
    vec2 ab = environmentBrdfLookup(NoV, material.roughness);
#if PATINA_FD == PATINA_FD_LAMBERT_FRESNEL_MIX
    ScatteredEnergy dielectric = lobeEnergies(material, ab, NoV).dielectric;   // a film's in it
    return vec3(minValue(vec3(1.0f) - dielectric.single - dielectric.multiple));
#else
    real w = material.specularWeight;
    vec3 reflected = w * (material.dielectricF0 * ab.x + vec3(ab.y));
#if defined(PATINA_IRIDESCENT_FIELDS) && !defined(PATINA_NO_THIN_FILM)
    if (material.iridescence > 0.0f) {   // the film's F at N.V times the lobe's albedo, as splitSumShares
        reflected = mix(reflected, filmFresnelAt(material, NoV).dielectric * (ab.x + ab.y), material.iridescence);
    }
#endif
    return vec3(1.0f - maxValue(reflected));
#endif
}

PATINA_INLINE vec3 splitSum(SurfaceMaterial material, real NoV, vec3 prefiltered, vec3 irradiance) {
    LightShares shares = splitSumShares(material, NoV, prefiltered, irradiance);
#if defined(PATINA_NO_DIFFUSE)
    return shares.specular;
#else
    return shares.specular + shares.diffuse;
#endif
}

// Outgoing radiance towards V from an environment of `intensity` turned by (cosRotation,
// sinRotation) about +Y: the split sum, LD read from the prefiltered chain at roughnessToLod
// and E from the irradiance map, both in the environment's frame.
// The split sum's two lobes before the intensity (the inspector's channels).
PATINA_INLINE LightShares environmentShares(EnvironmentSource prefiltered, real maxLod, EnvironmentSource irradianceMap,
                                            real cosRotation, real sinRotation, SurfaceMaterial material, vec3 N,
                                            vec3 V, bool dominant) {
    real NoV = max(dot(N, V), MIN_N_DOT_V);
    vec3 R = toEnvironmentFrame(environmentReflection(material, N, V, dominant), cosRotation, sinRotation);
    vec3 ld = sampleEnvironmentSource(prefiltered, R, roughnessToLod(material.roughness, maxLod));
    vec3 irradiance = irradianceFromMap(irradianceMap, toEnvironmentFrame(N, cosRotation, sinRotation));
    return splitSumShares(material, NoV, ld, irradiance);
}

PATINA_INLINE vec3 shadeEnvironment(EnvironmentSource prefiltered, real maxLod, EnvironmentSource irradianceMap,
                                    real intensity, real cosRotation, real sinRotation, SurfaceMaterial material,
                                    vec3 N, vec3 V, bool dominant) {
    LightShares shares =
        environmentShares(prefiltered, maxLod, irradianceMap, cosRotation, sinRotation, material, N, V, dominant);
#if defined(PATINA_NO_DIFFUSE)
    return intensity * shares.specular;
#else
    return intensity * (shares.specular + shares.diffuse);
#endif
}

// KHR_materials_clearcoat under an environment (clearcoat.glsl's clearcoatSplitSum, before the
// intensity): LD read from the prefiltered chain along R_c at the coat's roughness, (A, B) from
// this model's table at (N_c.V, the coat's roughness). Include clearcoat.glsl first.
PATINA_INLINE vec3 clearcoatEnvironment(EnvironmentSource prefiltered, real maxLod, real cosRotation, real sinRotation,
                                        Clearcoat coat, vec3 V) {
    vec3 R = toEnvironmentFrame(clearcoatReflection(coat, V), cosRotation, sinRotation);
    vec3 ld = sampleEnvironmentSource(prefiltered, R, roughnessToLod(coat.roughness, maxLod));
    return clearcoatSplitSum(coat, ld, environmentBrdfLookup(coat.NoV, coat.roughness));
}

// KHR_materials_transmission under an environment (transmission.glsl, before the intensity),
// thin-walled: the environment along -V read from the prefiltered chain at the wall's roughness
// (blurred as the reflection is), weighted by transmittedEnvironmentWeight at N.V. Include
// transmission.glsl first.
PATINA_INLINE vec3 transmissionEnvironment(EnvironmentSource prefiltered, real maxLod, real cosRotation,
                                           real sinRotation, SurfaceMaterial material, Transmission t, vec3 V) {
    vec3 through = sampleEnvironmentSource(prefiltered, toEnvironmentFrame(-V, cosRotation, sinRotation),
                                           roughnessToLod(material.roughness, maxLod));
    return transmissionThrough(t, through, transmittedEnvironmentWeight(material, t.NoV));
}

// The stochastic alternative to the split sum: the specular integral itself at the real N and
// V (no N = V, no split of F and G from the light), estimated per pixel by `count` GGX
// half-vector samples (f NoL / pdf = F G_Vis, G_Vis as in eq. 8), each read from the source's
// box-filtered mip chain at the filtered-importance-sampling lod of prefilterEnvironment
// (Krivanek and Colbert 2008, eq. 13; pdf_L = D NoH / (4 VoH)). `jitter` turns the Hammersley
// set per pixel (Cranley-Patterson rotation), so its error shows as noise, not as a pattern.
// N and V in the environment's frame; the model's own Fresnel and energy compensation.
PATINA_INLINE vec3 stochasticSpecular(EnvironmentSource source, real sourceFaceSize, SurfaceMaterial material,
                                      vec3 N, vec3 V, uint count, vec2 jitter) {
    real NoV = max(dot(N, V), MIN_N_DOT_V);
    real texelSolidAngle = 4.0f * PATINA_PI / (6.0f * sourceFaceSize * sourceFaceSize);
    vec3 sum = vec3(0.0f);
    for (uint i = 0u; i < count; ++i) {
        vec2 xi = fract(hammersley(i, count) + jitter);
        vec3 H = importanceSampleGGX(xi, material.alpha, N);
        real VoH = dot(V, H);
        vec3 L = 2.0f * VoH * H - V;
        real NoL = dot(N, L);
        real NoH = dot(N, H);
        if (NoL > 0.0f && VoH > 0.0f && NoH > 0.0f) {
            real pdf = D_GGX(NoH, cross(N, H), material.alpha) * NoH / (4.0f * VoH);
            real sampleSolidAngle = 1.0f / (real(count) * pdf);
            real lod = max(0.5f * log2(sampleSolidAngle / texelSolidAngle) + 1.0f, 0.0f);
            real gVis = environmentVisibility(NoV, min(NoL, 1.0f), material) * 4.0f * NoL * VoH / NoH;
            sum += sampleEnvironmentSource(source, L, lod) * surfaceFresnel(material, NoV, VoH) * gVis;
        }
    }
    return sum / real(count) * energyCompensation(material.f0, NoV, material.roughness);
}

// The stochastic mode's outgoing radiance: stochasticSpecular plus the same Lambert diffuse
// from the irradiance map as the split sum.
PATINA_INLINE vec3 shadeEnvironmentStochastic(EnvironmentSource source, real sourceFaceSize,
                                              EnvironmentSource irradianceMap, real intensity, real cosRotation,
                                              real sinRotation, SurfaceMaterial material, vec3 N, vec3 V, uint count,
                                              vec2 jitter) {
    vec3 n = toEnvironmentFrame(N, cosRotation, sinRotation);
    vec3 v = toEnvironmentFrame(V, cosRotation, sinRotation);
    vec3 specular = stochasticSpecular(source, sourceFaceSize, material, n, v, count, jitter);
#if PATINA_FD == PATINA_FD_LAMBERT_FRESNEL_MIX
    // The samples give the single-scattered specular; the multiple-scattered and the weighted
    // diffuse are the split sum's (splitSumShares with no prefiltered light).
    LightShares rest =
        splitSumShares(material, max(dot(n, v), MIN_N_DOT_V), vec3(0.0f), irradianceFromMap(irradianceMap, n));
    return intensity * (specular + rest.specular + rest.diffuse);
#elif defined(PATINA_NO_DIFFUSE)
    return intensity * specular;
#else
    return intensity * (specular + Fd_Lambert(material.diffuseColor) * irradianceFromMap(irradianceMap, n));
#endif
}

