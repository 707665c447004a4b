// The inspector's channel inputs (channels.glsl) gathered for one BRDF model: the surface, then
// each light, then the environment and the sum. Shared GLSL / C++; include after brdf_model.glsl
// and ibl_model.glsl. shade.frag with PATINA_CHANNEL and the CPU twin (engine/reference/channels.h)
// call these in the same order, each with its own list of lights.

// The surface's fields: the material after its maps (deriveSurfaceMaterial's F0 and diffuse
// colour from it, KHR_materials_specular's tint and weight applied), the occlusion and emission
// the maps give, the UVs, the tangent frame and the normals. The lighting starts at 0. `tangent`
// as interpolated (w = 0: none).
PATINA_INLINE ChannelInputs channelSurface(vec3 baseColor, real alpha, real roughness, real specular,
                                           vec3 specularTint, real specularWeight, real metallic, real occlusion,
                                           vec3 emission, vec2 uv0, vec2 uv1, vec4 tangent, vec3 geometryNormal,
                                           vec3 N, vec3 V) {
    SurfaceMaterial m =
        withSpecular(deriveSurfaceMaterial(baseColor, roughness, specular, metallic), specularTint, specularWeight);
    vec3 t = safeNormalize(vec3(tangent.x, tangent.y, tangent.z));
    real handedness = tangent.w > 0.0f ? 1.0f : (tangent.w < 0.0f ? -1.0f : 0.0f);
    return ChannelInputs(baseColor, alpha, metallic, roughness, specular, specularTint, specularWeight, m.f0,
                         m.diffuseColor, occlusion, emission,
                         uv0, uv1, geometryNormal, N, vec4(t.x, t.y, t.z, handedness), max(dot(N, V), MIN_N_DOT_V),
                         0.0f, 0.0f, vec3(0.0f), vec3(0.0f), vec3(0.0f), vec3(0.0f), vec3(0.0f), vec3(0.0f),
                         vec3(0.0f), vec3(0.0f), vec3(0.0f), vec3(0.0f), vec3(0.0f));
}

// The material the base's lobes read: deriveSurfaceMaterial's with its specular, its stretch and
// its film, its diffuse reduced by a transmission (transmission.glsl's transmissionDiffuse), as
// shade.frag shades it. Derived once a pixel: every light and the environment read it.
PATINA_INLINE SurfaceMaterial channelMaterial(ChannelInputs c, ChannelLayers layers) {
    SurfaceMaterial m = withSpecular(deriveSurfaceMaterial(c.baseColor, c.roughness, c.specular, c.metallic),
                                     c.specularTint, c.specularWeight);
    if (layers.anisotropic) {
        vec4 t = layers.anisotropyTangent;
        m = withAnisotropy(m, c.shadingNormal, vec3(t.x, t.y, t.z), t.w, layers.anisotropy.x, layers.anisotropy.y,
                           layers.anisotropy.z);
    }
#ifdef PATINA_IRIDESCENT_FIELDS
    m = withFilmAt(withIridescence(m, layers.iridescence, layers.iridescenceIor, layers.iridescenceThickness), c.NoV);
#endif
    return layers.transmits ? transmissionDiffuse(m, layers.transmissionFactor) : m;
}

// One light's lobes on `m` (channelMaterial's) added at P (occlusion on a hemisphere light, as the
// renderer applies it), then the layers' (channelLayersOfLight). `asked`: the light of
// CHANNEL_LIGHT (its lobes on the base); `key`: the light D, G and F are read towards.
PATINA_INLINE ChannelInputs channelWithLight(ChannelInputs c, SurfaceMaterial m, ChannelLayers layers,
                                             PackedLight light, bool asked, bool key, vec3 P, vec3 V) {
    LightShares shares = lightShares(light, m, P, c.shadingNormal, V);
    if (light.type == LIGHT_HEMISPHERE) {
        shares.diffuse = c.occlusion * shares.diffuse;
    }
    c.diffuse = c.diffuse + shares.diffuse;
    c.specularLighting = c.specularLighting + shares.specular;
    if (asked) {
        c.light = shares.diffuse + shares.specular;
    }
    if (key) {
        InspectedTerms terms = inspectedTerms(light, m, P, c.shadingNormal, V);
        c.D = terms.D;
        c.G = terms.G;
        c.F = terms.F;
    }
    return channelLayersOfLight(c, layers, light, shares.diffuse + shares.specular, P, V);
}

// The environment's split-sum lobes (environmentShares, before the intensity) added, occluded.
PATINA_INLINE ChannelInputs channelWithEnvironment(ChannelInputs c, LightShares shares, real intensity, bool asked) {
    c.environmentDiffuse = c.occlusion * (intensity * shares.diffuse);
    c.environmentSpecular = c.occlusion * (intensity * shares.specular);
    c.diffuse = c.diffuse + c.environmentDiffuse;
    c.specularLighting = c.specularLighting + c.environmentSpecular;
    if (asked) {
        c.light = c.environmentDiffuse + c.environmentSpecular;
    }
    return c;
}

// The layers under the environment, after channelWithEnvironment, as the renderer draws them:
// the sheen lit by the irradiance at N and the base weighed by E(N.V) (sheenIrradianceShare), the
// coat's split sum about its own mirror direction (clearcoatEnvironment), the environment along
// -V through the wall (transmissionEnvironment; a channel draws no scene behind), all occluded.
// `m` channelMaterial's.
PATINA_INLINE ChannelInputs channelWithEnvironmentLayers(ChannelInputs c, SurfaceMaterial m, ChannelLayers layers,
                                                         EnvironmentSource prefiltered, real maxLod,
                                                         EnvironmentSource irradianceMap, real intensity,
                                                         real cosRotation, real sinRotation, vec3 V) {
    vec3 base = c.environmentDiffuse + c.environmentSpecular;
    if (layers.sheened) {
        vec3 irradiance =
            irradianceFromMap(irradianceMap, toEnvironmentFrame(c.shadingNormal, cosRotation, sinRotation));
        SheenShare share = sheenIrradianceShare(layers.sheen, intensity * irradiance);
        share.sheen = c.occlusion * share.sheen;
        c.sheen = c.sheen + share.sheen;
        base = sheenOver(base, share);
    }
    if (layers.coated) {
        vec3 coat = clearcoatEnvironment(prefiltered, maxLod, cosRotation, sinRotation, layers.coat, V);
        c.clearcoat = c.clearcoat + c.occlusion * (intensity * coat);
    }
    if (layers.transmits) {
        vec3 through =
            transmissionEnvironment(prefiltered, maxLod, cosRotation, sinRotation, m, layers.transmission, V);
        c.transmission = c.transmission + c.occlusion * (intensity * through);
    }
    c.layeredLighting = c.layeredLighting + base;
    return c;
}

// The pixel's radiance once every light is in: the lobes and the emission; with layers, the
// base and sheen (layeredLighting), the light through the wall (weighed by a sheen's albedo
// scaling towards V, sheenViewWeight) and the emission seen through the coat, plus the coat's own
// (clearcoatOver), as shade.frag sums them.
PATINA_INLINE ChannelInputs channelFinished(ChannelInputs c, ChannelLayers layers) {
    if (!layers.coated && !layers.sheened && !layers.transmits) {
        c.radiance = c.diffuse + c.specularLighting + c.emission;
        return c;
    }
    // The transmission as it adds to the radiance: beneath a sheen, weighed by its scaling.
    c.transmission = (layers.sheened ? sheenViewWeight(layers.sheen) : 1.0f) * c.transmission;
    vec3 base = c.layeredLighting + c.transmission + c.emission;
    c.radiance = layers.coated ? clearcoatOver(base, c.clearcoat, layers.coat) : base;
    return c;
}
