// KHR_materials_iridescence (Khronos, ratified 2022): a thin film over the base whose
// interference colours its Fresnel. The film's Fresnel is Belcour & Barla 2017, "A Practical
// Extension to Microfacet Theory for the Modeling of Varying Iridescence" (ACM TOG 36(4)): an
// Airy sum of the film's two interfaces (each Schlick's, unpolarised) over its first two orders,
// integrated against the CIE XYZ sensitivities by their Gaussian fit (sec. 4, "Analytic Spectral
// Integration"), then taken to linear Rec. 709, as the extension's "Implementation Notes" give it.
// Shared GLSL / C++ (brdf.glsl says how); include after brdf.glsl. Not in the fp16 instance
// (it needs cos and exp of vectors); the GPU compiles it in only for an iridescent material
// (shade.frag's PATINA_IRIDESCENCE).

// The film's outside: air (the extension leaves a clear coat above the film out).
const real IRIDESCENCE_OUTSIDE_IOR = 1.0f;

// ((n_t - n_i) / (n_t + n_i))^2, per channel: normal-incidence reflectance between two media.
PATINA_INLINE vec3 reflectanceBetween(vec3 transmitted, real incident) {
    vec3 r = (transmitted - vec3(incident)) / (transmitted + vec3(incident));
    return r * r;
}

// The ior of a base whose F0 against air is `f0`, per channel (a metal's taken as a real ior, as
// the extension does); F0 capped at 0.9999 so that the ior stays finite.
PATINA_INLINE vec3 iorOfReflectance(vec3 f0) {
    vec3 s = sqrt(clamp(f0, vec3(0.0f), vec3(0.9999f)));
    return (vec3(1.0f) + s) / (vec3(1.0f) - s);
}

// The XYZ sensitivity's Fourier transform at optical path difference `opd` (nm) with phase shift
// `shift` per channel (Belcour & Barla 2017, sec. 4: each of X, Y, Z a Gaussian in wavelength,
// X with a second lobe), normalised and taken to linear Rec. 709 (the XYZ to sRGB primaries
// matrix, D65).
PATINA_INLINE vec3 thinFilmSensitivity(real opd, vec3 shift) {
    real phase = 2.0f * PATINA_PI * opd * 1.0e-9f;
    vec3 height = vec3(5.4856e-13f, 4.4201e-13f, 5.2481e-13f);
    vec3 centre = vec3(1.6810e+06f, 1.7953e+06f, 2.2084e+06f);
    vec3 spread = vec3(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
    vec3 xyz = height * sqrt(2.0f * PATINA_PI * spread) * cos(centre * phase + shift) *
               exp(-(phase * phase) * spread);
    real secondX = 9.7470e-14f * sqrt(2.0f * PATINA_PI * 4.5282e+09f) * cos(2.2399e+06f * phase + shift.x) *
                   exp(-4.5282e+09f * phase * phase);
    xyz = vec3(xyz.x + secondX, xyz.y, xyz.z) / real(1.0685e-7f);
    return vec3(dot(vec3(3.2404542f, -1.5371385f, -0.4985314f), xyz),
                dot(vec3(-0.9692660f, 1.8760108f, 0.0415560f), xyz),
                dot(vec3(0.0556434f, -0.2040259f, 1.0572252f), xyz));
}

// The film's Fresnel, RGB, seen at cos(theta_1) = N.V from outside ior `outsideIor`: a film of
// ior `filmIor` and `thickness` nm over a base of normal-incidence reflectance `baseF0`.
PATINA_INLINE vec3 thinFilmFresnel(real outsideIor, real filmIor, real cosTheta1, real thickness, vec3 baseF0) {
    // The film's ior fades to the outside's as the film vanishes (over 0.03 nm: Belcour's code
    // in micrometres, as the Khronos sample viewer keeps it).
    real fade = clamp(thickness / 0.03f, 0.0f, 1.0f);
    real eta2 = mix(outsideIor, filmIor, fade * fade * (3.0f - 2.0f * fade));
    // Snell into the film; total internal reflection (a film below the outside's ior) reflects all.
    real sinTheta2Squared = (outsideIor / eta2) * (outsideIor / eta2) * (1.0f - cosTheta1 * cosTheta1);
    real cosTheta2Squared = 1.0f - sinTheta2Squared;
    if (cosTheta2Squared < 0.0f) {
        return vec3(1.0f);
    }
    real cosTheta2 = sqrt(cosTheta2Squared);
    // First interface, outside to film: Schlick's reflectance, and what it transmits both ways.
    real r0 = (eta2 - outsideIor) / (eta2 + outsideIor);
    real m1 = clamp(1.0f - cosTheta1, 0.0f, 1.0f);
    real R12 = r0 * r0 + (1.0f - r0 * r0) * (m1 * m1 * m1 * m1 * m1);
    real T121 = 1.0f - R12;
    real phi12 = eta2 < outsideIor ? PATINA_PI : 0.0f;
    real phi21 = PATINA_PI - phi12;
    // Second interface, film to base, per channel.
    vec3 baseIor = iorOfReflectance(baseF0);
    vec3 R23 = F_Schlick(reflectanceBetween(baseIor, eta2), cosTheta2);
    vec3 phi23 = vec3(baseIor.x < eta2 ? PATINA_PI : 0.0f, baseIor.y < eta2 ? PATINA_PI : 0.0f,
                      baseIor.z < eta2 ? PATINA_PI : 0.0f);
    real opd = 2.0f * eta2 * thickness * cosTheta2;
    vec3 phi = vec3(phi21) + phi23;
    // The Airy sum: the order 0 term, then orders 1 and 2 of the interference.
    vec3 R123 = clamp(R12 * R23, vec3(1.0e-5f), vec3(0.9999f));
    vec3 r123 = sqrt(R123);
    vec3 Rs = (T121 * T121) * R23 / (vec3(1.0f) - R123);
    vec3 intensity = vec3(R12) + Rs;
    vec3 order = Rs - vec3(T121);
    for (int m = 1; m <= 2; ++m) {
        order = order * r123;
        intensity = intensity + order * (real(2.0f) * thinFilmSensitivity(real(m) * opd, real(m) * phi));
    }
    return max(intensity, vec3(0.0f));
}

// The film's strength, ior and thickness on the surface (withIridescence; strength 0 without).
#ifdef PATINA_IRIDESCENT_FIELDS
// `factor` the extension's iridescenceFactor (times its map), `filmIor` iridescenceIor,
// `thickness` in nm (iridescenceThicknessMaximum, or its map's mix of the two); a film of no
// thickness is none (the Khronos sample viewer's rule: the formula does not fade to the base's
// Fresnel there).
PATINA_INLINE SurfaceMaterial withIridescence(SurfaceMaterial material, real factor, real filmIor, real thickness) {
    material.iridescence = thickness > 0.0f ? factor : 0.0f;
    material.iridescenceIor = filmIor;
    material.iridescenceThickness = thickness;
    return material;
}

// The film's Fresnel over the dielectric (its F0 as KHR_materials_specular weights it) and over
// the metal (F0 = c_base), evaluated once at N.V for every light and the environment, as the
// extension's "Iridescence BRDF" evaluates it.
struct IridescentFresnel {
    vec3 dielectric;
    vec3 metal;
};

PATINA_INLINE IridescentFresnel iridescentFresnel(SurfaceMaterial material, real NoV) {
    real cosTheta1 = clamp(NoV, 0.0f, 1.0f);
    return IridescentFresnel(
        thinFilmFresnel(IRIDESCENCE_OUTSIDE_IOR, material.iridescenceIor, cosTheta1, material.iridescenceThickness,
                        material.dielectricF0 * material.specularWeight),
        thinFilmFresnel(IRIDESCENCE_OUTSIDE_IOR, material.iridescenceIor, cosTheta1, material.iridescenceThickness,
                        material.baseColor));
}

// The film's Fresnel at N.V kept on the material: shade.frag calls this once a pixel where N
// and V are final, so that the lights' loop reads it instead of evaluating it a light at a time
// (the extension evaluates it once, at N.V). `NoV` as the BRDF floors it.
PATINA_INLINE SurfaceMaterial withFilmAt(SurfaceMaterial material, real NoV) {
    if (material.iridescence > 0.0f) {
        IridescentFresnel film = iridescentFresnel(material, NoV);
        material.filmDielectric = film.dielectric;
        material.filmMetal = film.metal;
    }
    return material;
}

// The film's Fresnel where the BRDF asks for it at `NoV`: withFilmAt's on the GPU; evaluated
// here in C++, where the twin, the truth and the lobe views ask at any N.V (the same function
// at the same N.V: the same numbers).
PATINA_INLINE IridescentFresnel filmFresnelAt(SurfaceMaterial material, real NoV) {
#ifdef __cplusplus
    return iridescentFresnel(material, NoV);
#else
    return IridescentFresnel(material.filmDielectric, material.filmMetal);
#endif
}
#endif
