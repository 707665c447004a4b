// Patina's light types (shared GLSL / C++ like brdf.glsl; include after it). shadeLight, which
// needs the BRDF model, is in brdf_model.glsl.
// The same PackedLight struct is a std140 uniform block on the GPU and a plain array on the CPU
// (engine/scene/light_packing.cpp fills it).

const int LIGHT_POINT = 0;
const int LIGHT_DIRECTIONAL = 1;
const int LIGHT_HEMISPHERE = 2;
const int LIGHT_SPHERE = 3;
const int LIGHT_TUBE = 4;

// Largest light count the single-pass uniform block holds (64 * 112 bytes = 7 KiB of the
// 16 KiB every GL 3.3 implementation guarantees).
const int MAX_LIGHTS = 64;

// A window of 1/x^2-style attenuation that never divides by less than this; it only acts when
// a_c + a_l t + a_q t^2 < 1e-4 (all three zero, or a light at the surface with a_c = 0).
const real MIN_ATTENUATION_DENOMINATOR = 1e-4f;
// Below this squared distance a point light sits on the shaded point and L has no direction.
const real MIN_LIGHT_DISTANCE_SQUARED = 1e-12f;
const real MIN_LIGHT_DISTANCE = 1e-6f;   // its square root

// No swizzles here (C++ has none): each vec3 is followed by the scalar that fills its std140
// slot, so a light is seven 16-byte rows in both languages.
struct PackedLight {
    vec3 radiance;           // colour * intensity
    int type;                // LIGHT_*
    vec3 position;           // point, sphere: the centre; tube: its start
    real inverseRange;      // point, sphere, tube: 1 / range, 0 for no window (range 0)
    vec3 directionToLight;   // directional: -normalize(direction)
    real sourceRadius;      // sphere, tube: s
    vec3 attenuation;        // point, sphere, tube: a_c, a_l, a_q
    real shadowMap;          // the renderer's: 1 + the light's shadow map layer (shade.frag), 0 for none; negative for a cube map's six
    vec3 sky;                // hemisphere: sky colour * colour * intensity
    real unused2;
    vec3 ground;             // hemisphere: ground colour * colour * intensity
    real unused3;
    vec3 tubeEnd;            // tube: its end
    real unused4;
};

// a_c, a_l, a_q of Karis 2013's falloff denominator d^2 + 1 (eq. 9), every Light's default.
// Shaders take these as a constant where a light has exactly them (specialised per light,
// single when every point light has them: PATINA_KARIS_POINTS): llvmpipe turns each uniform
// scalar a fragment shader reads into a per-lane gather, and these are three
// (docs/PERFORMANCE.md).
const vec3 KARIS_ATTENUATION = vec3(1.0f, 0.0f, 1.0f);

// Windowed distance attenuation (docs/SHADING.md S1, after Karis 2013 eq. 9, with the general
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

// Area lights (Karis 2013, "Real Shading in Unreal Engine 4", section "Area lights"): a sphere of
// source radius s, and a tube, the capsule of radius s around a segment. Both keep the point
// light's intensity and falloff; brdf_model.glsl's shadeSphereLight and shadeTubeLight build
// them from the terms below. Vectors are relative to the shaded point and not normalised.

// The widening of Karis 2013 eq. 10, alpha' = saturate(alpha + size / (w d)), is printed
// ambiguously: w = 2 in UE4's code and two independent transcriptions, w = 3 in other ports.
// Both are kept; docs/LIGHTING.md ("Area lights") measures them against the ground truth.
const real WIDENING_UE4 = 2.0f;     // size / (2 d)
const real WIDENING_THIRD = 3.0f;   // size / (3 d)

// Which variant a shader runs: the widening divisor w, and for a sphere's diffuse either Karis's
// point at the centre (false) or Frostbite's horizon-clipped illuminance (true).
struct AreaLightMethod {
    real widening;
    bool exactSphereDiffuse;
};

// The renderer's choice (PATINA_AREA_WIDENING and PATINA_EXACT_SPHERE_DIFFUSE select another at
// compile time), measured in docs/LIGHTING.md ("Area lights"): UE4's w = 2. Over spheres at 30
// degrees its mean error is 0.17 against 0.43 for w = 3, which brightens smooth highlights
// 1.75-2.6x (w = 3 wins only from r = 0.5 up, by 0.03-0.06). Diffuse: the centre's, exact above
// the horizon and cheapest; Frostbite's costs the same above it and cuts the error across it from
// up to 0.28 to 0.003 of I / d^2.
#ifndef PATINA_AREA_WIDENING
#define PATINA_AREA_WIDENING WIDENING_UE4
#endif
#ifndef PATINA_EXACT_SPHERE_DIFFUSE
#define PATINA_EXACT_SPHERE_DIFFUSE false
#endif
PATINA_INLINE AreaLightMethod defaultAreaLightMethod() {
    return AreaLightMethod(PATINA_AREA_WIDENING, PATINA_EXACT_SPHERE_DIFFUSE);
}

// Karis 2013, eq. 11: the point of the sphere (centre L, radius s) closest to the ray along the
// unit R: c = (L.R) R - L, closest = L + c saturate(s / |c|).
PATINA_INLINE vec3 sphereRepresentativePoint(vec3 L, vec3 R, real sourceRadius) {
    vec3 centreToRay = dot(L, R) * R - L;
    real distanceToRaySquared = dot(centreToRay, centreToRay);
    // R through the centre: c = 0 and s / |c| = s / 0. Any fraction of c = 0 gives the centre.
    real fraction = distanceToRaySquared > 0.0f
                        ? clamp(sourceRadius * inversesqrt(distanceToRaySquared), 0.0f, 1.0f)
                        : 0.0f;
    return L + centreToRay * fraction;
}

// Karis 2013, eqs. 15-17: the point of the segment L0 + t Ld, t in [0, 1], closest to the ray
// along the unit R: t = saturate(((R.L0)(R.Ld) - L0.Ld) / (|Ld|^2 - (R.Ld)^2)).
PATINA_INLINE vec3 tubeClosestPoint(vec3 L0, vec3 Ld, vec3 R) {
    real RoLd = dot(R, Ld);
    real denominator = dot(Ld, Ld) - RoLd * RoLd;
    // 0 for a segment of no length or one along R (every point as close): the start will do.
    real t = denominator > 0.0f ? clamp((dot(R, L0) * RoLd - dot(L0, Ld)) / denominator, 0.0f, 1.0f) : 0.0f;
    return L0 + Ld * t;
}

// Karis 2013, eq. 10: the roughness a lobe widened by a source of `size` (a sphere's radius, a
// tube's length) seen at `distance`: alpha' = saturate(alpha + size / (w distance)).
PATINA_INLINE real widenedAlpha(real alpha, real size, real distance, real widening) {
    // The shaded point at the light's centre: size / 0. The floor keeps it finite (alpha' = 1
    // for any size > 0, alpha' = alpha for size 0).
    return clamp(alpha + size / (widening * max(distance, MIN_LIGHT_DISTANCE)), 0.0f, 1.0f);
}

// Karis 2013, eq. 14: a sphere light's energy normalisation (alpha / alpha')^2.
// alpha >= the floor's 0.002 and alpha' >= alpha, so it lies in (0, 1].
PATINA_INLINE real sphereNormalization(real alpha, real widened) {
    real ratio = alpha / widened;
    return ratio * ratio;
}

// Karis 2013, eq. 16: a line's energy normalisation alpha / alpha'.
PATINA_INLINE real lineNormalization(real alpha, real widened) {
    return alpha / widened;
}

// Karis 2013, "Tube lights": the irradiance of a segment from its two ends,
// E = I 2 saturate(N.L0 / (2 |L0|) + N.L1 / (2 |L1|)) / (|L0| |L1| + L0.L1), is a point light's
// I cos / t^2 with t^2 the half sum below and cos the mean of the ends' cosines. For L0 = L1,
// t^2 = |L0|^2. The shaded point on the segment makes it 0 (the falloff's floor then acts).
PATINA_INLINE real lineIrradianceDistanceSquared(vec3 L0, vec3 L1) {
    return 0.5f * (sqrt(dot(L0, L0) * dot(L1, L1)) + dot(L0, L1));
}

PATINA_INLINE real lineIrradianceCosine(vec3 N, vec3 L0, vec3 L1) {
    // An end on the shaded point has no direction; its cosine counts 0.
    real cosine0 = dot(N, L0) * inversesqrt(max(dot(L0, L0), MIN_LIGHT_DISTANCE_SQUARED));
    real cosine1 = dot(N, L1) * inversesqrt(max(dot(L1, L1), MIN_LIGHT_DISTANCE_SQUARED));
    return clamp(0.5f * (cosine0 + cosine1), 0.0f, 1.0f);
}

// Lagarde and de Rousiers 2014, "Moving Frostbite to PBR", section 4.7.2 (after Snyder 1996):
// the illuminance of a sphere of radiance Le and angular radius sigma whose centre lies at theta
// from the normal, clipped by the horizon, over pi Le sin^2 sigma, the illuminance of the point
// light of the same intensity I = pi s^2 Le at its centre without the cosine. So it is cos theta
// while the sphere is above the horizon (cos^2 theta > sin^2 sigma), 0 once below, and between
//   ((cos theta acos y - x sin theta sqrt(1 - y^2)) sin^2 sigma + atan(sin theta sqrt(1 - y^2) / x))
//   / (pi sin^2 sigma),   x = sqrt(1 / sin^2 sigma - 1), y = -x cos theta / sin theta.
// Inside the sphere (sin^2 sigma >= 1) the whole hemisphere sees it: pi Le, so 1 / sin^2 sigma.
PATINA_INLINE real sphereIlluminance_Frostbite(real cosTheta, real sinSigmaSquared) {
    if (sinSigmaSquared >= 1.0f) {
        return 1.0f / sinSigmaSquared;
    }
    // Also sigma = 0 (a point): the band below is empty, and nothing divides by sin^2 sigma.
    if (cosTheta * cosTheta >= sinSigmaSquared) {
        return max(cosTheta, 0.0f);
    }
    // Here cos^2 theta < sin^2 sigma < 1: sin theta > 0 and x > 0. |y| <= 1 but for rounding.
    real sinTheta = sqrt(1.0f - cosTheta * cosTheta);
    real x = sqrt(1.0f / sinSigmaSquared - 1.0f);
    real y = clamp(-x * cosTheta / sinTheta, -1.0f, 1.0f);
    real sinThetaSqrtY = sinTheta * sqrt(1.0f - y * y);
    real illuminance = (cosTheta * acos(y) - x * sinThetaSqrtY) * sinSigmaSquared + atan(sinThetaSqrtY / x);
    // The two terms nearly cancel for a thin sliver above the horizon; rounding must not make
    // light negative.
    return max(illuminance, 0.0f) / (PATINA_PI * sinSigmaSquared);
}

// The falloff of a point, sphere or tube light at distance t, with shadePointLight's switches.
// 1/range = 0 turns the window off: with `windowed` a constant, the compiler folds it away.
PATINA_INLINE real lightFalloff(PackedLight light, real t, bool windowed, bool karis) {
    return pointLightAttenuation(t, windowed ? light.inverseRange : 0.0f, karis ? KARIS_ATTENUATION : light.attenuation);
}

// What a point light sends to P: its radiance after the falloff, the unit direction to it, and
// whether it has one (a light on the shaded point has none: no light).
struct LightArrival {
    vec3 radiance;
    vec3 L;
    bool present;
};

// What a sphere light sends to P: the vector to its centre, its distance t and 1 / t (clamped so
// the centre on the shaded point still gives finite numbers; `present` false there: no light),
// and its radiance after the point light's falloff at t.
struct SphereArrival {
    vec3 toCentre;
    real t;
    real inverseDistance;
    vec3 radiance;
    bool present;
};

PATINA_INLINE SphereArrival sphereLightArrival(PackedLight light, bool windowed, bool karis, vec3 P) {
    vec3 toCentre = light.position - P;
    real distanceSquared = dot(toCentre, toCentre);
    real inverseDistance = inversesqrt(max(distanceSquared, MIN_LIGHT_DISTANCE_SQUARED));
    real t = distanceSquared * inverseDistance;
    return SphereArrival(toCentre, t, inverseDistance, light.radiance * lightFalloff(light, t, windowed, karis),
                         distanceSquared > MIN_LIGHT_DISTANCE_SQUARED);
}

// A point light is a sphere light of no size: its arrival is the sphere's, the direction its
// vector to the centre made unit.
PATINA_INLINE LightArrival pointLightArrival(PackedLight light, bool windowed, bool karis, vec3 P) {
    SphereArrival sphere = sphereLightArrival(light, windowed, karis, P);
    return LightArrival(sphere.radiance, sphere.toCentre * sphere.inverseDistance, sphere.present);
}

// What a tube light sends to P: its ends and the segment seen from P, its radiance after the
// falloff at the line irradiance's distance, and the vector to its centre and that distance.
struct TubeArrival {
    vec3 L0;
    vec3 L1;
    vec3 Ld;
    vec3 radiance;
    vec3 toCentre;
    real centreDistance;
};

PATINA_INLINE TubeArrival tubeLightArrival(PackedLight light, bool windowed, bool karis, vec3 P) {
    vec3 L0 = light.position - P;
    vec3 L1 = light.tubeEnd - P;
    vec3 Ld = L1 - L0;
    real lineDistanceSquared = max(lineIrradianceDistanceSquared(L0, L1), 0.0f);
    vec3 radiance = light.radiance * lightFalloff(light, sqrt(lineDistanceSquared), windowed, karis);
    vec3 toCentre = L0 + Ld * real(0.5f);
    return TubeArrival(L0, L1, Ld, radiance, toCentre, sqrt(dot(toCentre, toCentre)));
}

// Karis 2013's representative point for a specular lobe of `alpha` about the reflected ray R:
// the unit direction to it and the normalisation its radiance takes.
struct RepresentativePoint {
    vec3 L;
    real normalization;
};

PATINA_INLINE vec3 towardsPoint(vec3 point) {
    return point * inversesqrt(max(dot(point, point), MIN_LIGHT_DISTANCE_SQUARED));
}

// A sphere: the point of eq. 11, normalised by (alpha / alpha')^2 (eq. 14) at the centre's distance.
PATINA_INLINE RepresentativePoint sphereRepresentative(SphereArrival arrival, real sourceRadius, vec3 R, real alpha,
                                                       AreaLightMethod method) {
    vec3 closest = sphereRepresentativePoint(arrival.toCentre, R, sourceRadius);
    return RepresentativePoint(towardsPoint(closest),
                               sphereNormalization(alpha, widenedAlpha(alpha, sourceRadius, arrival.t, method.widening)));
}

// A tube: the segment's point closest to R (eqs. 15-17), then the sphere's point about it,
// normalised by the line's alpha / alpha' (eq. 16) with the segment's length and the sphere's
// (alpha / alpha')^2 (eq. 14), both at the distance of the tube's centre.
PATINA_INLINE RepresentativePoint tubeRepresentative(TubeArrival arrival, real sourceRadius, vec3 R, real alpha,
                                                     AreaLightMethod method) {
    vec3 closest = sphereRepresentativePoint(tubeClosestPoint(arrival.L0, arrival.Ld, R), R, sourceRadius);
    real segmentLength = sqrt(dot(arrival.Ld, arrival.Ld));
    real normalization =
        lineNormalization(alpha, widenedAlpha(alpha, segmentLength, arrival.centreDistance, method.widening)) *
        sphereNormalization(alpha, widenedAlpha(alpha, sourceRadius, arrival.centreDistance, method.widening));
    return RepresentativePoint(towardsPoint(closest), normalization);
}
