// One BRDF model's permutation of shaders/shared/brdf_model.glsl, compiled as C++. No include guard:
// engine/shading/brdf_models.cpp includes this once per model and precision, inside the namespace of the
// shared types (patina::shader or patina::shader_f64), with PATINA_INSTANCE set to an
// identifier of PATINA_BRDF_MODELS. It opens namespace model_<identifier>.
#define PATINA_D PATINA_APPLY(PATINA_TERM_D, (PATINA_TERMS_OF(PATINA_INSTANCE)))
#define PATINA_V PATINA_APPLY(PATINA_TERM_V, (PATINA_TERMS_OF(PATINA_INSTANCE)))
#define PATINA_F PATINA_APPLY(PATINA_TERM_F, (PATINA_TERMS_OF(PATINA_INSTANCE)))
#define PATINA_FD PATINA_APPLY(PATINA_TERM_FD, (PATINA_TERMS_OF(PATINA_INSTANCE)))
#define PATINA_MS PATINA_APPLY(PATINA_TERM_MS, (PATINA_TERMS_OF(PATINA_INSTANCE)))

namespace PATINA_MODEL_NAMESPACE(PATINA_INSTANCE) {

inline real energyTexel(int x, int y) {
    return energyTable(BrdfModelId::PATINA_INSTANCE)[size_t(y) * size_t(kEnergyTableSize) + size_t(x)];
}

#include "energy_table.glsl"
#include "brdf_model.glsl"
#ifdef PATINA_WITH_IBL
inline vec2 environmentBrdfTexel(int x, int y) {
    return environmentBrdfTable(BrdfModelId::PATINA_INSTANCE)[size_t(y) * size_t(kEnvironmentBrdfSize) + size_t(x)];
}
#include "ibl_model.glsl"
#include "channel_model.glsl"

// shade.frag's inspectedChannel on the CPU (engine/shading/channel_inputs.h).
inline ChannelInputs gatherChannelInputs(const ChannelPoint& p, const std::vector<PackedLight>& lights, int asked,
                                         int key, const ChannelEnvironment* environment) {
    ChannelInputs c = channelSurface(p.baseColor, p.alpha, p.roughness, p.specular, p.specularTint, p.specularWeight,
                                     p.metallic, p.occlusion, p.emission, p.uv0, p.uv1, p.tangent, p.geometryNormal,
                                     p.N, p.V);
    const ChannelLayers layers = channelPointLayers(p);
    const SurfaceMaterial material = channelMaterial(c, layers);
    for (int i = 0; i < int(lights.size()); ++i) {
        c = channelWithLight(c, material, layers, lights[size_t(i)], i == asked, i == key, p.P, p.V);
    }
    if (environment) {
        const vec2 rotation = environmentRotation(environment->rotationDegrees);
        LightShares shares = environmentShares(environment->prefiltered, environment->maxLod, environment->irradiance,
                                               rotation.x, rotation.y, material, p.N, p.V, false);
        c = channelWithEnvironment(c, shares, environment->intensity, asked == -2);
        c = channelWithEnvironmentLayers(c, material, layers, environment->prefiltered, environment->maxLod,
                                         environment->irradiance, environment->intensity, rotation.x, rotation.y, p.V);
    }
    return channelFinished(c, layers);
}
#endif

// A sphere or tube light by a chosen variant (C++ only: the area-light measurements compare them).
inline vec3 shadeAreaLightWith(PackedLight light, AreaLightMethod method, SurfaceMaterial material, vec3 P, vec3 N,
                               vec3 V) {
    return light.type == LIGHT_TUBE ? shadeTubeLightWith(light, true, false, method, material, P, N, V)
                                    : shadeSphereLightWith(light, true, false, method, material, P, N, V);
}

// The half vector and the cosines the specular terms read, clamped as evaluateBrdf clamps them
// (C++ only: evaluateBrdf guards L = -V itself).
struct LobeAngles {
    vec3 H;
    real NoV, NoL, NoH;
};
inline LobeAngles lobeAngles(vec3 N, vec3 V, vec3 L) {
    vec3 H = safeNormalize(L + V);
    return {H, max(dot(N, V), MIN_N_DOT_V), clamp(dot(N, L), 0.0f, 1.0f), clamp(dot(N, H), 0.0f, 1.0f)};
}

// D * V with F = 1 and no compensation: the lobe the white furnace integrates (C++ only).
inline real specularLobe(SurfaceMaterial material, vec3 N, vec3 V, vec3 L) {
    const LobeAngles a = lobeAngles(N, V, L);
    return distribution(a.NoH, cross(N, a.H), material.alpha) * visibility(a.NoV, a.NoL, material);
}

// The model's D, V and F for one configuration, for plots (C++ only); an anisotropic lobe's own
// D and V (stretchedTerms).
inline SpecularTerms specularTerms(SurfaceMaterial material, vec3 N, vec3 V, vec3 L) {
    const LobeAngles a = lobeAngles(N, V, L);
    const LobeShape shape = stretchedTerms(material, distribution(a.NoH, cross(N, a.H), material.alpha),
                                           visibility(a.NoV, a.NoL, material), a.NoV, a.NoL, a.NoH, a.H, V, L);
    return SpecularTerms(shape.D, shape.Vis, surfaceFresnel(material, a.NoV, clamp(dot(V, a.H), 0.0f, 1.0f)));
}

}  // namespace

#undef PATINA_D
#undef PATINA_V
#undef PATINA_F
#undef PATINA_FD
#undef PATINA_MS
#undef PATINA_INSTANCE
