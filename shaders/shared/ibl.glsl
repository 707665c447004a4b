// Image-based lighting, the parts every BRDF model shares (Karis 2013, "Real Shading in Unreal
// Engine 4", section "Image-based lighting"): the Hammersley set and GGX sampler that the
// tables, the prefilter and the ground truth all use, the prefilter itself, the roughness-to-mip
// mapping, the equirect convention and the irradiance map's read. Shared GLSL / C++ like
// brdf.glsl; include after it. The includer defines, before this file:
//   EnvironmentSource                          a cube map: the prefilter's source, the prefiltered
//                                              chain, the irradiance map (samplerCube on the GPU)
//   sampleEnvironmentSource(source, dir, lod)  its trilinear, seamless read at a mip level

// The 32 bits of `bits` in reverse order.
PATINA_INLINE uint reverseBits(uint bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return bits;
}

// Van der Corput radical inverse in base 2 (Hammersley's second coordinate): the bits
// reversed, as a fraction of 2^32.
PATINA_INLINE real radicalInverse(uint bits) {
    return real(reverseBits(bits)) * 2.3283064365386963e-10f;
}

// Point i of an n-point Hammersley set in [0, 1)^2 (Karis 2013, listing Hammersley), the
// first coordinate at the middle of its stratum.
PATINA_INLINE vec2 hammersley(uint i, uint n) {
    return vec2((real(i) + 0.5f) / real(n), radicalInverse(i));
}

// A half vector around N distributed as D(H) NoH for GGX (Karis 2013, listing
// ImportanceSampleGGX; Walter et al. 2007, eqs. 35-36): cos^2 theta = (1 - u) / (1 + (a^2 - 1) u).
PATINA_INLINE vec3 importanceSampleGGX(vec2 xi, real alpha, vec3 N) {
    real a2 = alpha * alpha;
    real phi = 2.0f * PATINA_PI * xi.x;
    real cosTheta = sqrt((1.0f - xi.y) / (1.0f + (a2 - 1.0f) * xi.y));
    real sinTheta = sqrt(max(1.0f - cosTheta * cosTheta, 0.0f));
    // Any tangent frame will do; this one is Karis's.
    vec3 up = abs(N.z) < 0.999f ? vec3(0.0f, 0.0f, 1.0f) : vec3(1.0f, 0.0f, 0.0f);
    vec3 tangentX = normalize(cross(up, N));
    vec3 tangentY = cross(N, tangentX);
    return tangentX * (sinTheta * cos(phi)) + tangentY * (sinTheta * sin(phi)) + N * cosTheta;
}

// Two numbers in [0, 1) from a pixel's coordinates, for the stochastic mode's per-pixel turn of
// the Hammersley set: a 32-bit integer hash (Jarzynski and Olano 2020, "Hash Functions for GPU
// Rendering", pcg) of each coordinate mixed with the other's. The CPU makes the same numbers.
PATINA_INLINE uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

PATINA_INLINE vec2 pixelJitter(uint x, uint y) {
    uint a = pcgHash(x + pcgHash(y));
    uint b = pcgHash(a);
    return vec2(real(a >> 8u), real(b >> 8u)) * (1.0f / 16777216.0f);
}

// The direction through face coordinates (sc, tc) in [-1, 1] of cube face `face` (0 to 5: +X,
// -X, +Y, -Y, +Z, -Z), not normalised: OpenGL 4.5 core, table 8.19, inverted. The CPU's cube maps
// and the GPU's prefilter pass place texels by it.
PATINA_INLINE vec3 cubeFaceDirection(int face, real sc, real tc) {
    if (face == 0) return vec3(1.0f, -tc, -sc);
    if (face == 1) return vec3(-1.0f, -tc, sc);
    if (face == 2) return vec3(sc, 1.0f, tc);
    if (face == 3) return vec3(sc, -1.0f, -tc);
    if (face == 4) return vec3(sc, -tc, 1.0f);
    return vec3(-sc, -tc, -1.0f);
}

// Equirect convention (docs/FORMATS.md): +Y up, row 0 the zenith, the image's centre along -Z.
// u = 0.5 + atan2(d.x, -d.z) / (2 pi), v = acos(d.y) / pi.
PATINA_INLINE vec2 directionToEquirect(vec3 d) {
    real u = 0.5f + atan(d.x, -d.z) / (2.0f * PATINA_PI);
    real v = acos(clamp(d.y, -1.0f, 1.0f)) / PATINA_PI;
    return vec2(u, v);
}

PATINA_INLINE vec3 equirectToDirection(vec2 uv) {
    real phi = (uv.x - 0.5f) * 2.0f * PATINA_PI;
    real theta = uv.y * PATINA_PI;
    return vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi));
}

// A world direction in the environment's own frame: `rotationDegrees` turns the environment
// about +Y, so a world direction looks up the image turned back by it. Background and lighting
// both go through this one function.
PATINA_INLINE vec3 toEnvironmentFrame(vec3 d, real cosRotation, real sinRotation) {
    return vec3(cosRotation * d.x - sinRotation * d.z, d.y, sinRotation * d.x + cosRotation * d.z);
}

// The prefiltered chain's mip for perceptual roughness r, and its inverse: Filament's
// lod = maxLod t (2 - t) (the rough end, where the lobe changes slowly, gets fewer mips than the
// glossy end), with t the roughness above the BRDF's floor, t = (r - r_min) / (1 - r_min).
// Mip 0 is the unfiltered source and the floor's lobe (alpha = 0.045^2, a tenth of a degree) is
// narrower than its texels, so every r at or below the floor reads mip 0 alone: with t = r the
// floor would read lod 0.44 and blend a mirror with mip 1 (docs/LIGHTING.md L5, "r = 0 blending mip
// 0 and 1"). r = 1 reads the last mip.
PATINA_INLINE real roughnessToLod(real roughness, real maxLod) {
    real t = clamp((roughness - MIN_PERCEPTUAL_ROUGHNESS) / (1.0f - MIN_PERCEPTUAL_ROUGHNESS), 0.0f, 1.0f);
    return maxLod * t * (2.0f - t);
}

PATINA_INLINE real lodToRoughness(real lod, real maxLod) {
    real t = 1.0f - sqrt(1.0f - clamp(lod / maxLod, 0.0f, 1.0f));
    return MIN_PERCEPTUAL_ROUGHNESS + (1.0f - MIN_PERCEPTUAL_ROUGHNESS) * t;
}

// Where the split sum reads the prefiltered chain: R = reflect(-V, N), or with `dominant` the
// "dominant direction" mix(R, N, alpha^2) that Frostbite and Filament use to make up for N = V
// in the prefilter (Lagarde and de Rousiers 2014, section 4.9.3).
// KHR_materials_anisotropy's lobe is read along a bent normal (Revie 2011, "Implementing Fur
// Using Deferred Shading", GPU Pro 2; McAuley 2015, "Rendering the World of Far Cry 4", as
// Filament and the Khronos sample viewer take it): the normal leans towards V's part across the
// stretch, the plane of b, the more the stronger and smoother the lobe (a bend of
// (1 - strength (1 - r))^4 keeps N): the prefiltered chain's isotropic lobe then sits along the
// streak's brightest reflection. An approximation: docs/SHADING.md S8 measures it.
PATINA_INLINE vec3 anisotropicBentNormal(SurfaceMaterial material, vec3 N, vec3 V) {
#ifdef PATINA_ANISOTROPIC_FIELDS
    if (material.alphaT > 0.0f) {
        vec3 b = material.anisotropicB;
        vec3 across = cross(cross(b, V), b);   // V less its part along b
        real keep = 1.0f - material.anisotropy * (1.0f - material.roughness);
        keep = keep * keep * keep * keep;
        vec3 bent = mix(across, N, keep);
        return dot(bent, bent) > 1e-12f ? normalize(bent) : N;
    }
#endif
    return N;
}

PATINA_INLINE vec3 environmentReflection(SurfaceMaterial material, vec3 N, vec3 V, bool dominant) {
#ifdef PATINA_ANISOTROPIC_FIELDS
    N = anisotropicBentNormal(material, N, V);
#endif
    vec3 R = reflect(-V, N);
    if (dominant) {
        real a2 = material.alpha * material.alpha;
        return normalize(mix(R, N, a2));
    }
    return R;
}

// The prefiltered radiance LD(R, r) with N = V = R (Karis 2013, listing PrefilterEnvMap): the
// environment summed over GGX-sampled L, weighted by NoL. Each sample reads the source at the
// mip whose texel covers the sample's solid angle (filtered importance sampling, Krivanek and
// Colbert 2008, GPU Gems 3 ch. 20, eq. 13): lod = 0.5 log2(Omega_s / Omega_p) + 1 with
// Omega_s = 1 / (n pdf), pdf = D / 4 when N = V, Omega_p = 4 pi / (6 w^2) for faces of w texels.
// It is what keeps a small bright sun from turning into a few fireflies.
PATINA_INLINE vec3 prefilterEnvironment(EnvironmentSource source, vec3 R, real roughness, uint samples,
                                        real sourceFaceSize) {
    real alpha = max(roughness, MIN_PERCEPTUAL_ROUGHNESS);
    alpha = alpha * alpha;
    vec3 N = R;
    vec3 V = R;
    real texelSolidAngle = 4.0f * PATINA_PI / (6.0f * sourceFaceSize * sourceFaceSize);
    vec3 sum = vec3(0.0f);
    real weight = 0.0f;
    for (uint i = 0u; i < samples; ++i) {
        vec3 H = importanceSampleGGX(hammersley(i, samples), alpha, N);
        real VoH = dot(V, H);
        vec3 L = 2.0f * VoH * H - V;
        real NoL = dot(N, L);
        if (NoL > 0.0f) {
            real NoH = clamp(dot(N, H), 0.0f, 1.0f);
            real pdf = D_GGX(NoH, cross(N, H), alpha) * 0.25f;
            real sampleSolidAngle = 1.0f / (real(samples) * pdf);
            real lod = max(0.5f * log2(sampleSolidAngle / texelSolidAngle) + 1.0f, 0.0f);
            sum += sampleEnvironmentSource(source, L, lod) * NoL;
            weight += NoL;
        }
    }
    return weight > 0.0f ? sum / weight : vec3(0.0f);
}

// The irradiance E(n) = integral of Env(l) max(n.l, 0) dl, the Lambert radiance's
// c_diff / pi E(n), read from the irradiance map: a cube map whose texels hold E exactly at
// their centres (engine/environment/irradiance.h), bilinear and seamless, at its one level.
PATINA_INLINE vec3 irradianceFromMap(EnvironmentSource irradiance, vec3 n) {
    return sampleEnvironmentSource(irradiance, n, 0.0f);
}

// The specular occlusion of a surface whose ambient occlusion is `ao` (the share of the sky it
// sees, cosine-weighted), seen at NoV, of roughness alpha = r^2 (as Filament passes it):
// Lagarde and de Rousiers 2014, "Moving Frostbite to PBR", section 4.10.2, listing 26,
// saturate((NoV + ao)^(2^(-16 alpha - 1)) - 1 + ao). It is about ao for a rough surface seen
// face on, 1 where nothing occludes, and falls towards 0 at the grazing angles of a smooth one,
// whose reflection comes from near its horizon, where a cavity's walls stand.
PATINA_INLINE real specularOcclusion(real NoV, real ao, real alpha) {
    real exponent = exp2(-16.0f * alpha - 1.0f);
    return clamp(exp2(exponent * log2(NoV + ao)) - 1.0f + ao, 0.0f, 1.0f);
}
