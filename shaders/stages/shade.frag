// Shades the mesh (or, with PATINA_PROBE, one probe row per pixel) in linear light.
// PATINA_SINGLE_PASS: every light of the block in one pass; otherwise only uLightIndex, and the
// renderer adds the passes with blending (the seed's multi-pass design). PATINA_KARIS_POINTS:
// every point light has KARIS_ATTENUATION, so single need not read the coefficients.
// PATINA_NO_POINT_LIGHTS, PATINA_NO_DIRECTIONAL_LIGHTS, PATINA_NO_HEMISPHERE_LIGHTS,
// PATINA_NO_SPHERE_LIGHTS, PATINA_NO_TUBE_LIGHTS: single leaves out the loop of a type the scene
// lacks (ShadingPrograms::singlePassFor); KARIS_POINTS holds for sphere and tube lights too.
// PATINA_SPECIALISED: PATINA_LIGHTS lists the scene's enabled lights in order as
// SHADE_POINT(light, windowed, karis), SHADE_DIRECTIONAL(light), SHADE_HEMISPHERE(light),
// SHADE_SPHERE(light, windowed, karis) and SHADE_TUBE(light, windowed, karis), so
// the shader has no light loop and no code for a type the scene lacks; `light` is FLAT(i), a
// flat input from mesh.vert, or BLOCK(i), read from the block (engine/gl/shader_specialisation.h
// builds the list and says why).
// PATINA_ENVIRONMENT: the scene's environment (environment.glsl) by the split sum, after the
// lights in single and specialised, in a pass of its own (uLightIndex < 0) in multi.
// PATINA_TEXTURED: a model's maps (surface_maps.glsl) multiply into the factors, bend the
// normal, occlude the environment and hemisphere lights, add emission (once: in multi, in the
// pass uEmissionPass marks) and cut out MASK's pixels.
// PATINA_CLEARCOAT: KHR_materials_clearcoat (clearcoat.glsl), only for an item with a coat: the
// base's light, environment and emission weighed by 1 - clearcoat fr_c, the coat's own lobe
// added light by light and from the environment (COATED). Without it not one instruction of the
// coat is compiled.
// PATINA_SHEEN: KHR_materials_sheen (sheen.glsl), only for an item with a sheen: each light's
// share of the base weighed by the extension's albedo scaling and the sheen's lobe added, the
// environment's by E(N.V) with the sheen lit by the irradiance (SHEENED). Without it not one
// instruction of the sheen is compiled.
// PATINA_SHADOWS: some light casts shadows (engine/gl/shadow_maps.h, docs/LIGHTING.md
// "Shadows"): its light is weighed by the share of its shadow map's PCF taps that see the
// surface (PCSS's for a sphere or tube light). Single and multi read a light's map from PackedLight::shadowMap; specialised names it
// in the list, SHADOWED(towards the light, map, SHADE_...). Without it not one instruction of it is compiled.
// PATINA_SHADOW_CATCHER (single, with PATINA_SHADOWS): the ground of Ground::Shadow, which
// writes no light but the share of its light that its shadows leave, which the renderer
// multiplies the background by.
// PATINA_TRANSMISSION: KHR_materials_transmission and KHR_materials_volume (transmission.glsl),
// thin-walled, only for an item with a transmission: that fraction of the diffuse gone, each
// light behind the surface seen through it and the environment along -V (TRANSMITTED), tinted
// by the base colour and attenuated over the thickness; beneath the coat. Without it not one
// instruction of the transmission is compiled.
// PATINA_ANISOTROPY: KHR_materials_anisotropy (brdf.glsl's withAnisotropy), only for an item
// with one: the specular lobe's D and V stretched along the tangent turned by the rotation, on
// the shading normal, for every light; the environment read along the bent normal (ibl.glsl).
// Without it not one instruction of it is compiled.
// PATINA_AMBIENT_OCCLUSION: the item's ambient occlusion baked at its vertices (mesh.vert's
// vAmbientOcclusion, engine/scene/ambient_occlusion.h) times the file's occlusion map takes the
// map's place on the environment's and the hemisphere lights' light (OCCLUDED), and the
// environment's specular lobe takes the specular occlusion instead (ambientEnvironmentRadiance).
// Without it not one instruction of it is compiled.
#ifdef PATINA_PROBE
flat in vec3 vPosition;
flat in vec3 vNormal;
flat in vec3 vView;
#else
in vec3 vPosition;
in vec3 vNormal;
uniform vec3 uCameraPosition;
#endif

uniform vec3 uBaseColor;
uniform float uRoughness;
uniform float uSpecular;
uniform float uMetallic;
#ifndef PATINA_PROBE
// glTF's double-sided lighting (§3.9.5): a back face is shaded with its normal reversed. Off
// for the built-in meshes, which have always been shaded with the normals they have.
uniform bool uReverseBackNormals;
#endif

#ifdef PATINA_FLAT_LIGHT_COUNT
// Lights 0 to PATINA_FLAT_LIGHT_COUNT - 1 as mesh.vert's FLAT_* wrote them: two rows each, the
// fields of the light's type (radiance or sky, and 1/range; position, direction or ground).
flat in vec4 vFlatLight[2 * PATINA_FLAT_LIGHT_COUNT];
PackedLight flatLight(int i) {
    PackedLight light;
    light.type = -1;   // not read: each SHADE_* macro names its type
    light.shadowMap = 0.0f;   // the specialised list names a flat light's map (SHADOWED)
    light.unused2 = 0.0f;
    light.unused3 = 0.0f;
    light.unused4 = 0.0f;
    light.radiance = vFlatLight[2 * i].xyz;
    light.sky = vFlatLight[2 * i].xyz;
    light.inverseRange = vFlatLight[2 * i].w;
    light.position = vFlatLight[2 * i + 1].xyz;
    light.directionToLight = vFlatLight[2 * i + 1].xyz;
    light.ground = vFlatLight[2 * i + 1].xyz;
    light.sourceRadius = vFlatLight[2 * i + 1].w;
    // Read only for a point, sphere or tube light with other coefficients than Karis's (not a
    // constant), and for a tube's end.
    light.attenuation = uLights[i].attenuation;
    light.tubeEnd = uLights[i].tubeEnd;
    return light;
}
#define FLAT(i) flatLight(i)
#endif
#define BLOCK(i) uLights[i]

#ifndef PATINA_SINGLE_PASS
uniform int uLightIndex;
#endif

#ifdef PATINA_CLEARCOAT
uniform float uClearcoat;            // clearcoatFactor
uniform float uClearcoatRoughness;   // clearcoatRoughnessFactor
#define COATED(term) coatRadiance += (term);
#else
#define COATED(term)
#endif

// KHR_materials_specular's tint of F0 and weight of its Fresnel (withSpecular), only for a
// material that has them or their maps (hasSpecularTint).
#ifdef PATINA_SPECULAR
uniform vec3 uSpecularTint;
uniform float uSpecularWeight;
#endif

// KHR_materials_iridescence's thin film (withIridescence), only for a material that has one
// (hasIridescence).
#ifdef PATINA_IRIDESCENCE
uniform float uIridescence;            // iridescenceFactor
uniform float uIridescenceIor;         // iridescenceIor
uniform vec2 uIridescenceThickness;    // iridescenceThicknessMinimum, iridescenceThicknessMaximum (nm)
#endif

#ifdef PATINA_ANISOTROPY
uniform float uAnisotropyStrength;   // anisotropyStrength
uniform vec2 uAnisotropyDirection;   // (cos, sin) of anisotropyRotation
#if !defined(PATINA_TEXTURED) && !defined(PATINA_PROBE)
in vec4 vTangent;   // mesh.vert's, world space; w = 0: the vertex has none
#endif
#endif

#ifdef PATINA_SHEEN
uniform vec3 uSheenColor;        // sheenColorFactor
uniform float uSheenRoughness;   // sheenRoughnessFactor
#define SHEENED(base, share) sheenOver((base), (share))
#else
#define SHEENED(base, share) (base)
#endif

#ifdef PATINA_SHADOWS
const int MAX_SHADOW_MAPS = 12;   // engine/gl/shadow_maps.h's kMaxShadowMaps
uniform sampler2DArrayShadow uShadowMaps;
uniform sampler2DArray uShadowDepthMaps;   // the same maps' raw depths, no comparison (PCSS's blocker search)
uniform mat4 uShadowTransforms[MAX_SHADOW_MAPS];   // world to a map's [0, 1] coordinates and depth
uniform vec4 uShadowTexels[MAX_SHADOW_MAPS];   // x a texel's world size at w 1, y 1 / size, z tap spacing
// A sphere's or tube's size in the map (ShadowView::source): xy its half-extent along its long
// axis, z across, in texels at view depth 1; zero for a point or directional light.
uniform vec4 uShadowSources[MAX_SHADOW_MAPS];
uniform vec2 uShadowRanges[MAX_SHADOW_MAPS];   // the view's near and far depths
float lightShadow = 1.0f;                       // the visibility of the light being added
vec3 shadowNormal = vec3(0.0f, 1.0f, 0.0f);     // the geometric normal (no normal map), as shaded

// The map's depth along the receiver's tangent plane per unit of the map's coordinates
// (receiver plane depth bias, Isidoro 2006, "Shadow mapping: GPU-based tips and techniques"):
// a wide tap compares against the plane's depth where it lands, so a flat or convex receiver's
// own surface does not shadow it however far the taps spread. None where the plane grazes the
// light (its projection degenerate): the normal offset alone there.
vec2 receiverPlaneSlope(int k, vec3 position, vec3 coordinates, float w) {
    vec3 t1 = normalize(cross(shadowNormal, abs(shadowNormal.x) > 0.9f ? vec3(0.0f, 1.0f, 0.0f) : vec3(1.0f, 0.0f, 0.0f)));
    vec3 t2 = cross(shadowNormal, t1);
    vec4 a = uShadowTransforms[k] * vec4(position + 1e-3f * w * t1, 1.0f);
    vec4 b = uShadowTransforms[k] * vec4(position + 1e-3f * w * t2, 1.0f);
    vec3 da = a.xyz / a.w - coordinates, db = b.xyz / b.w - coordinates;
    mat2 J = mat2(da.xy, db.xy);   // the plane's two steps in the map
    if (abs(determinant(J)) < 0.05f * length(da.xy) * length(db.xy)) {
        return vec2(0.0f);
    }
    return transpose(inverse(J)) * vec2(da.z, db.z);
}

// Tap i of n of a Vogel disk (the golden angle's spiral): n points spread evenly over the unit
// disk, no two at the same radius, so a shadow's edge crossing it is a ramp of n small steps.
vec2 diskTap(int i, int n) {
    float r = sqrt((float(i) + 0.5f) / float(n));
    float theta = 2.39996323f * float(i);
    return r * vec2(cos(theta), sin(theta));
}

// Map k's light seen at `scale` (tan units per world unit of the light's size) as an ellipse in
// the map's coordinates: its columns the two half-axes, each at least a texel.
mat2 sourceKernel(int k, float scale) {
    vec4 source = uShadowSources[k];
    vec2 axis = normalize(source.xy);
    float texel = uShadowTexels[k].y;
    return mat2(axis * (max(length(source.xy) * scale, 1.0f) * texel),
                vec2(-axis.y, axis.x) * (max(source.z * scale, 1.0f) * texel));
}

// The view depth of map k's stored depth z (perspective: 1/d is linear in z).
float shadowViewDepth(int k, float z) {
    vec2 range = uShadowRanges[k];
    return range.x * range.y / (range.y - z * (range.y - range.x));
}

// Percentage-closer soft shadows (Fernando 2005, "Percentage-closer soft shadows", SIGGRAPH
// sketch), the receiver at `coordinates` and view depth dR: (1) the blocker search, the mean
// depth of what lies nearer the light within the map's region from which a caster between the
// near plane and the receiver can hide part of the light; (2) the penumbra by similar
// triangles, w = (dR - dB) * lightSize / dB on the receiver, (dR - dB) / (dR dB) per unit of
// light size seen from the light; (3) PCF over that width. Each tap compares against the
// receiver's plane where it lands (`slope`).
float softShadowVisibility(int k, vec3 coordinates, float dR, vec2 slope) {
    const int BLOCKER_TAPS = 16, FILTER_TAPS = 32;
    float nearPlane = uShadowRanges[k].x;
    mat2 search = sourceKernel(k, max(dR - nearPlane, 0.0f) / (dR * nearPlane));
    float blockers = 0.0f, blockerDepth = 0.0f;
    for (int i = 0; i < BLOCKER_TAPS; ++i) {
        vec2 o = search * diskTap(i, BLOCKER_TAPS);
        float z = texture(uShadowDepthMaps, vec3(coordinates.xy + o, float(k))).r;
        if (z < min(coordinates.z + dot(slope, o), 1.0f)) {   // the comparison clamps to the far depth, lit
            blockers += 1.0f;
            blockerDepth += z;
        }
    }
    if (blockers == 0.0f) {
        return 1.0f;
    }
    float dB = shadowViewDepth(k, blockerDepth / blockers);
    mat2 penumbra = sourceKernel(k, max(dR - dB, 0.0f) / (dR * dB));
    float seen = 0.0f;
    for (int i = 0; i < FILTER_TAPS; ++i) {
        vec2 o = penumbra * diskTap(i, FILTER_TAPS);
        seen += texture(uShadowMaps, vec4(coordinates.xy + o, float(k), coordinates.z + dot(slope, o)));
    }
    return seen / float(FILTER_TAPS);
}

// The share of map k's taps that see the surface, L towards the light: PCSS for a sphere or
// tube light, otherwise 3x3 PCF taps a texel apart (each a bilinear 2x2 comparison,
// GL_LINEAR). The lookup moves out along the geometric normal by about the taps' spacing in
// world units, more where the light grazes (normal offset, Holbein 2011): a tap s texels away
// on a surface tilted from the light meets the surface's own depth s texels further on. The
// map's own depth carries the slope-scaled offset (glPolygonOffset when drawn, renderer.cpp).
float shadowVisibility(int k, vec3 L) {
    vec4 texel = uShadowTexels[k];
    float cosine = clamp(dot(shadowNormal, L), 0.0f, 1.0f);
    float w = (uShadowTransforms[k] * vec4(vPosition, 1.0f)).w;
    float offset = texel.x * texel.z * w * (1.0f + 2.0f * sqrt(1.0f - cosine * cosine));
    vec3 lifted = vPosition + offset * shadowNormal;
    vec4 p = uShadowTransforms[k] * vec4(lifted, 1.0f);
    vec3 coordinates = p.xyz / p.w;
    if (uShadowSources[k].xy != vec2(0.0f)) {
        return softShadowVisibility(k, coordinates, p.w, receiverPlaneSlope(k, lifted, coordinates, p.w));
    }
    vec2 step = vec2(texel.y * texel.z);
    float seen = 0.0f;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            seen += texture(uShadowMaps, vec4(coordinates.xy + vec2(x, y) * step, float(k), coordinates.z));
        }
    }
    return seen / 9.0f;
}

// Towards the light from the surface (a tube's from its segment's middle, as its map looks).
vec3 towardsShadowedLight(PackedLight light) {
    if (light.type == LIGHT_DIRECTIONAL) {
        return light.directionToLight;
    }
    vec3 source = light.type == LIGHT_TUBE ? 0.5f * (light.position + light.tubeEnd) : light.position;
    return safeNormalize(source - vPosition);
}

// Which of a cube map's six faces (+X, -X, +Y, -Y, +Z, -Z: engine/gl/shadow_maps.h) holds the
// direction d from the light: its largest axis, as each face's 90-degree view holds exactly the
// directions whose largest axis is its own.
int cubeFace(vec3 d) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) {
        return d.x >= 0.0f ? 0 : 1;
    }
    if (a.y >= a.z) {
        return d.y >= 0.0f ? 2 : 3;
    }
    return d.z >= 0.0f ? 4 : 5;
}

// A light's map: its layer, or for a cube map (a negative shadowMap) the layer of the face the
// light sees this fragment in.
float shadowOf(PackedLight light) {
    int k = int(abs(light.shadowMap)) - 1;
    if (k < 0) {
        return 1.0f;
    }
    vec3 L = towardsShadowedLight(light);
    return shadowVisibility(light.shadowMap < 0.0f ? k + cubeFace(-L) : k, L);
}
#define SHADOW_OF(light) lightShadow = shadowOf(light);
#define SHADOWED(L, k, shade) lightShadow = shadowVisibility(k, L); shade lightShadow = 1.0f;
#ifdef PATINA_SHADOW_CATCHER
vec3 catcherShadowed = vec3(0.0f), catcherUnshadowed = vec3(0.0f);   // the lights' sums with and without
vec3 catcherLit(vec3 term) {
    catcherUnshadowed += term;
    catcherShadowed += lightShadow * term;
    return lightShadow * term;
}
#define LIT(term) catcherLit(term)
#else
#define LIT(term) (lightShadow * (term))
#endif
#else
#define SHADOW_OF(light)
#define LIT(term) (term)
#endif
#ifdef PATINA_TRANSMISSION
uniform float uTransmission;          // transmissionFactor
uniform float uThickness;             // thicknessFactor, in the mesh's units
uniform vec3 uAttenuationColor;       // attenuationColor
uniform float uAttenuationDistance;   // attenuationDistance; 0: infinite
#ifndef PATINA_PROBE
uniform float uThicknessScale;        // the draw's scale (thicknessScaleOf)
#endif
#define TRANSMITTED(term) transmitted += (term);
#ifndef PATINA_PROBE
// The frame's opaque items that do not transmit, drawn first (engine/gl/scene_behind.h):
// premultiplied by their coverage, with a mip chain. uSceneBehindPlace: x the strip's first
// image row, y log2 of the image's width, z 0 where the renderer drew none (a channel), 1 where
// this pass adds what is seen of it, 2 where it only hides the light beyond (the multi path's
// passes after the first: the scene behind is added once).
uniform sampler2D uSceneBehind;
uniform vec3 uSceneBehindPlace;
// Thin-walled, the light leaves along -V: the scene behind is the one at this very pixel,
// blurred by the wall's roughness as the Khronos glTF-Sample-Viewer blurs its transmission
// framebuffer, at level log2(width) x roughness (the extension's thin-wall scale of the
// roughness, clamp(2 ior - 2, 0, 1), is 1 at Patina's ior of 1.5).
vec4 sceneBehind(float roughness) {
    if (uSceneBehindPlace.z == 0.0f) {
        return vec4(0.0f);
    }
    vec2 at = (gl_FragCoord.xy + vec2(0.0f, uSceneBehindPlace.x)) / vec2(textureSize(uSceneBehind, 0));
    return textureLod(uSceneBehind, at, uSceneBehindPlace.y * roughness);
}
// Light from beyond the scene (the environment, a hemisphere light's sky) passes only where
// none of the scene is behind the pixel.
#define BEYOND(term) (beyond * (term))
#else
#define BEYOND(term) (term)
#endif
#else
#define TRANSMITTED(term)
#endif

// Light that skips the surface's crevices: the environment's and the hemisphere lights'
// (glTF 2.0 section 3.9.3: occlusion applies to indirect lighting).
#ifdef PATINA_TEXTURED
#define OCCLUDED(radiance) (occlusion * (radiance))
#if !defined(PATINA_SINGLE_PASS) && !defined(PATINA_SPECIALISED)
uniform bool uEmissionPass;
#endif
#else
#define OCCLUDED(radiance) (radiance)
#endif

#ifdef PATINA_AMBIENT_OCCLUSION
// The ambient occlusion (PATINA_AMBIENT_OCCLUSION, docs/LIGHTING.md "Ambient occlusion").
in float vAmbientOcclusion;
float ambientOcclusion = 1.0f;         // the vertices' times the map's; main sets it
float specularOcclusionShare = 1.0f;   // ibl.glsl's specularOcclusion over ambientOcclusion; main sets it
#undef OCCLUDED
#ifdef PATINA_SHADOW_CATCHER
// The catcher takes the occlusion as it takes shadows: the light with and without it.
#ifndef PATINA_SHADOWS
vec3 catcherShadowed = vec3(0.0f), catcherUnshadowed = vec3(0.0f);
#endif
vec3 catcherOccluded(vec3 term) {
    catcherUnshadowed += term;
    catcherShadowed += ambientOcclusion * term;
    return ambientOcclusion * term;
}
#define OCCLUDED(radiance) catcherOccluded(radiance)
#else
#define OCCLUDED(radiance) (ambientOcclusion * (radiance))
#endif
#endif

#ifdef PATINA_ENVIRONMENT
// PATINA_ENVIRONMENT_DOMINANT: the split sum along the dominant direction;
// PATINA_ENVIRONMENT_STOCHASTIC N: N filtered importance samples a pixel instead
// (engine/gl/environment_method.h).
vec3 environmentRadiance(SurfaceMaterial material, vec3 N, vec3 V) {
#if defined(PATINA_ENVIRONMENT_STOCHASTIC)
    vec2 jitter = pixelJitter(uint(gl_FragCoord.x), uint(gl_FragCoord.y));
    return shadeEnvironmentStochastic(uEnvironmentSource, uEnvironmentSourceSize, uEnvironmentIrradiance,
                                      uEnvironmentIntensity, uEnvironmentRotation.x, uEnvironmentRotation.y, material,
                                      N, V, uint(PATINA_ENVIRONMENT_STOCHASTIC), jitter);
#else
#if defined(PATINA_ENVIRONMENT_DOMINANT)
    const bool dominant = true;
#else
    const bool dominant = false;
#endif
    return shadeEnvironment(uEnvironmentMap, uEnvironmentMaxLod, uEnvironmentIrradiance, uEnvironmentIntensity,
                            uEnvironmentRotation.x, uEnvironmentRotation.y, material, N, V, dominant);
#endif
}
#endif

#if defined(PATINA_ENVIRONMENT) && defined(PATINA_AMBIENT_OCCLUSION)
// The environment's light with its specular lobe weighed by specularOcclusionShare: after
// OCCLUDED, the diffuse has the ambient occlusion and the specular the specular occlusion. The
// diffuse is the split sum's in every method (shadeEnvironmentStochastic's too).
vec3 ambientEnvironmentRadiance(SurfaceMaterial material, vec3 N, vec3 V) {
    vec3 radiance = environmentRadiance(material, N, V);
#ifdef PATINA_NO_DIFFUSE
    vec3 diffuse = vec3(0.0f);
#else
    vec3 irradiance =
        irradianceFromMap(uEnvironmentIrradiance, toEnvironmentFrame(N, uEnvironmentRotation.x, uEnvironmentRotation.y));
    vec3 diffuse = uEnvironmentIntensity *
                   splitSumShares(material, max(dot(N, V), MIN_N_DOT_V), vec3(0.0f), irradiance).diffuse;
#endif
    return diffuse + specularOcclusionShare * (radiance - diffuse);
}
#define environmentRadiance ambientEnvironmentRadiance
#endif

#if defined(PATINA_ENVIRONMENT) && defined(PATINA_CLEARCOAT)
// The coat's split sum (ibl_model.glsl's clearcoatEnvironment), whatever the base's method.
vec3 clearcoatEnvironmentRadiance(Clearcoat coat, vec3 V) {
    return uEnvironmentIntensity * clearcoatEnvironment(uEnvironmentMap, uEnvironmentMaxLod, uEnvironmentRotation.x,
                                                        uEnvironmentRotation.y, coat, V);
}
#endif

#if defined(PATINA_ENVIRONMENT) && defined(PATINA_SHEEN)
// The sheen under the environment (sheen.glsl's sheenIrradianceShare): lit by the irradiance at
// N, whatever the base's method.
SheenShare sheenEnvironmentShare(Sheen sheen, vec3 N) {
    vec3 irradiance =
        irradianceFromMap(uEnvironmentIrradiance, toEnvironmentFrame(N, uEnvironmentRotation.x, uEnvironmentRotation.y));
    return sheenIrradianceShare(sheen, uEnvironmentIntensity * irradiance);
}
#endif

#if defined(PATINA_ENVIRONMENT) && defined(PATINA_TRANSMISSION)
// The environment through the wall (ibl_model.glsl's transmissionEnvironment), whatever the
// base's method.
vec3 transmissionEnvironmentRadiance(Transmission transmission, SurfaceMaterial material, vec3 V) {
    return uEnvironmentIntensity * transmissionEnvironment(uEnvironmentMap, uEnvironmentMaxLod, uEnvironmentRotation.x,
                                                           uEnvironmentRotation.y, material, transmission, V);
}
#endif

#ifdef PATINA_CHANNEL
// The inspector (channels.glsl, channel_model.glsl): the channel PATINA_CHANNEL written instead
// of the radiance, from every light and the environment by the split sum. Indices into the block:
uniform int uChannelLight;   // CHANNEL_LIGHT's light; -1 none, -2 the environment
uniform int uKeyLight;       // the light D, G and F are read towards; -1 none
uniform bool uChannelSrgb;   // the display value sRGB-encoded (shownChannel)
uniform vec3 uPbrRanges;     // CHANNEL_PBR_VALIDATION's (pbrVerdict)
#ifndef PATINA_TEXTURED
uniform float uChannelAlpha;   // the item's alpha (BLEND's factor), which only maps otherwise read
#endif

// `layers`: the part's coat, sheen and transmission (CHANNEL_CLEARCOAT, CHANNEL_SHEEN,
// CHANNEL_TRANSMISSION), as main derives them.
vec3 inspectedChannel(vec3 baseColor, float alpha, float roughness, vec3 specularTint, float specularWeight,
                      float metallic, float occlusion, vec3 emission, vec2 uv0, vec2 uv1, vec4 tangent,
                      vec3 geometryNormal, vec3 N, vec3 V, ChannelLayers layers) {
    ChannelInputs c = channelSurface(baseColor, alpha, roughness, uSpecular, specularTint, specularWeight, metallic,
                                     occlusion, emission, uv0, uv1, tangent, geometryNormal, N, V);
    SurfaceMaterial material = channelMaterial(c, layers);
    for (int i = 0; i < uLightCount.x; ++i) {
        c = channelWithLight(c, material, layers, uLights[i], i == uChannelLight, i == uKeyLight, vPosition, V);
    }
#ifdef PATINA_ENVIRONMENT
    LightShares shares = environmentShares(uEnvironmentMap, uEnvironmentMaxLod, uEnvironmentIrradiance,
                                           uEnvironmentRotation.x, uEnvironmentRotation.y, material, N, V, false);
    c = channelWithEnvironment(c, shares, uEnvironmentIntensity, uChannelLight == -2);
    c = channelWithEnvironmentLayers(c, material, layers, uEnvironmentMap, uEnvironmentMaxLod, uEnvironmentIrradiance,
                                     uEnvironmentIntensity, uEnvironmentRotation.x, uEnvironmentRotation.y, V);
#endif
    return channelValue(PATINA_CHANNEL, channelFinished(c, layers), layers, uPbrRanges);
}
#endif

// Alpha: which strip wrote a sample (RenderTargets::SampleStamp). Only MSAA samples need it;
// elsewhere it is not read, and a uniform costs llvmpipe a gather.
#if !defined(PATINA_PROBE) && !defined(PATINA_DISPLAY_OUTPUT)
#define PATINA_STAMPED
uniform float uSampleStamp;
#endif

layout(location = 0) out vec4 fragColor;   // linear radiance
#ifdef PATINA_DISPLAY_OUTPUT
// Without MSAA there is nothing to resolve, so the pass also writes the display value itself
// (display.glsl) and the renderer needs no display pass.
uniform float uExposure;
uniform int uTonemap;
layout(location = 1) out vec4 displayColor;
#endif

void main() {
#ifdef PATINA_TEXTURED
    discardMasked();
    TexturedMaterial mapped = texturedMaterial(vec4(uBaseColor, uBaseAlpha) * VERTEX_COLOR,
                                               MAP_TEXEL(0, uBaseColorMap, vec4(1.0f)),
                                               uRoughness, uMetallic,
                                               MAP_TEXEL(1, uMetallicRoughnessMap, vec4(1.0f)));
    SurfaceMaterial material = deriveSurfaceMaterial(mapped.baseColor, mapped.roughness, uSpecular, mapped.metallic);
    float occlusion = surfaceOcclusion();
#else
    SurfaceMaterial material = deriveSurfaceMaterial(uBaseColor, uRoughness, uSpecular, uMetallic);
#endif
#if defined(PATINA_SPECULAR) && defined(PATINA_TEXTURED)
    vec3 specularTint = mappedSpecularTint(uSpecularTint);
    float specularWeight = mappedSpecularWeight(uSpecularWeight);
#elif defined(PATINA_SPECULAR)
    vec3 specularTint = uSpecularTint;
    float specularWeight = uSpecularWeight;
#else
    vec3 specularTint = vec3(1.0f);   // what deriveSurfaceMaterial's material has
    float specularWeight = 1.0f;
#endif
#ifdef PATINA_SPECULAR
    material = withSpecular(material, specularTint, specularWeight);
#endif
#if defined(PATINA_IRIDESCENCE) && defined(PATINA_TEXTURED)
    material = withIridescence(material, mappedIridescence(uIridescence), uIridescenceIor,
                               mappedIridescenceThickness(uIridescenceThickness));
#elif defined(PATINA_IRIDESCENCE)
    material = withIridescence(material, uIridescence, uIridescenceIor, uIridescenceThickness.y);
#endif
    vec3 N = safeNormalize(vNormal);
#ifdef PATINA_PROBE
    vec3 V = safeNormalize(vView);
#else
    if (uReverseBackNormals && !gl_FrontFacing) {
        N = -N;
    }
    vec3 V = safeNormalize(uCameraPosition - vPosition);
#endif
#ifdef PATINA_SHADOWS
    shadowNormal = N;
#endif
#ifdef PATINA_CHANNEL
    vec3 geometryNormal = N;
#endif
#ifdef PATINA_CLEARCOAT
    // The coat lies on the geometric normal, or on its own normal map: not on the base's.
#ifdef PATINA_TEXTURED
    Clearcoat coat = deriveClearcoat(mappedClearcoat(uClearcoat), mappedClearcoatRoughness(uClearcoatRoughness),
                                     mappedClearcoatNormal(N), V);
#else
    Clearcoat coat = deriveClearcoat(uClearcoat, uClearcoatRoughness, N, V);
#endif
    vec3 coatRadiance = vec3(0.0f);
#endif
#ifdef PATINA_TEXTURED
    N = mappedNormal(N);
#endif
#ifdef PATINA_ANISOTROPY
    // On the shading normal (the normal map's included), from the interpolated tangent; a probe
    // has none and takes the fallback direction.
#ifdef PATINA_PROBE
    vec4 anisotropyTangent = vec4(0.0f);
#else
    vec4 anisotropyTangent = vTangent;
#endif
#ifdef PATINA_TEXTURED
    vec3 anisotropy = mappedAnisotropy(uAnisotropyDirection, uAnisotropyStrength);   // its map's direction and B
#else
    vec3 anisotropy = vec3(uAnisotropyDirection, uAnisotropyStrength);
#endif
    material = withAnisotropy(material, N, anisotropyTangent.xyz, anisotropyTangent.w, anisotropy.x, anisotropy.y,
                              anisotropy.z);
#endif
#ifdef PATINA_IRIDESCENCE
    material = withFilmAt(material, max(dot(N, V), MIN_N_DOT_V));   // once a pixel, N and V final
#endif
#ifdef PATINA_AMBIENT_OCCLUSION
#ifdef PATINA_TEXTURED
    ambientOcclusion = occlusion * vAmbientOcclusion;
#else
    ambientOcclusion = vAmbientOcclusion;
#endif
#ifndef PATINA_SHADOW_CATCHER
    float specularShare = specularOcclusion(max(dot(N, V), MIN_N_DOT_V), ambientOcclusion, material.alpha);
    specularOcclusionShare = ambientOcclusion > 0.0f ? specularShare / ambientOcclusion : 0.0f;
#endif
#endif
#ifdef PATINA_SHEEN
    // The sheen lies on the base's normal, its map's included.
#ifdef PATINA_TEXTURED
    Sheen sheen = deriveSheen(mappedSheenColor(uSheenColor), mappedSheenRoughness(uSheenRoughness), N, V);
#else
    Sheen sheen = deriveSheen(uSheenColor, uSheenRoughness, N, V);
#endif
#endif
#ifdef PATINA_TRANSMISSION
    // What passes is the diffuse's share (before transmissionDiffuse takes it away).
#ifdef PATINA_PROBE
    const float thicknessScale = 1.0f;
#else
    float thicknessScale = uThicknessScale;
#endif
#ifdef PATINA_TEXTURED
    float transmissionFactor = mappedTransmission(uTransmission);
    float thickness = mappedThickness(uThickness);
#else
    float transmissionFactor = uTransmission;
    float thickness = uThickness;
#endif
    Transmission transmission = deriveTransmission(
        material, transmissionFactor, volumeAttenuation(uAttenuationColor, uAttenuationDistance, thickness * thicknessScale),
        N, V);
    material = transmissionDiffuse(material, transmissionFactor);
#endif
#ifdef PATINA_CHANNEL
    ChannelLayers layers = noChannelLayers();
#ifdef PATINA_CLEARCOAT
    layers.coated = true;
    layers.coat = coat;
#endif
#ifdef PATINA_SHEEN
    layers.sheened = true;
    layers.sheen = sheen;
#endif
#ifdef PATINA_TRANSMISSION
    layers.transmits = true;
    layers.transmissionFactor = transmissionFactor;
    layers.transmission = transmission;
#endif
#ifdef PATINA_ANISOTROPY
    layers.anisotropic = true;
    layers.anisotropy = anisotropy;
    layers.anisotropyTangent = anisotropyTangent;
#endif
#ifdef PATINA_IRIDESCENCE
    layers.iridescence = material.iridescence;
    layers.iridescenceIor = material.iridescenceIor;
    layers.iridescenceThickness = material.iridescenceThickness;
#endif
#ifdef PATINA_TEXTURED
    vec3 channel = inspectedChannel(mapped.baseColor, mapped.alpha, mapped.roughness, specularTint, specularWeight,
                                    mapped.metallic, occlusion, surfaceEmission(), vUv0, vUv1, vTangent, geometryNormal,
                                    N, V, layers);
#else
    vec3 channel = inspectedChannel(uBaseColor, uChannelAlpha, uRoughness, specularTint, specularWeight, uMetallic, 1.0f,
                                    vec3(0.0f), vec2(0.0f), vec2(0.0f), vec4(0.0f), geometryNormal, N, V, layers);
#endif
    // Data, not light: no exposure or tone map in the display value either.
#ifdef PATINA_STAMPED
    fragColor = vec4(channel, uSampleStamp);
#else
    fragColor = vec4(channel, 1.0f);
#endif
#ifdef PATINA_DISPLAY_OUTPUT
    displayColor = vec4(shownChannel(PATINA_CHANNEL, channel, uChannelSrgb), 1.0f);
#endif
    return;
#endif
#ifdef PATINA_TRANSMISSION
    vec3 transmitted = vec3(0.0f);
#ifndef PATINA_PROBE
    vec4 behind = sceneBehind(material.roughness);
    float beyond = 1.0f - behind.a;
    // The scene behind, weighted as the light beyond it is: as the split sum weighs the diffuse
    // under an environment, by 1 - F(N.V) without one.
    if (uSceneBehindPlace.z == 1.0f) {
#ifdef PATINA_ENVIRONMENT
        transmitted += transmissionThrough(transmission, behind.rgb,
                                           transmittedEnvironmentWeight(material, transmission.NoV));
#else
        transmitted += transmissionThrough(transmission, behind.rgb,
                                           transmissionKept(transmission, transmission.NoV));
#endif
    }
#endif
#endif
    vec3 radiance = vec3(0.0f);
#if defined(PATINA_SPECIALISED)
#define SHADE_POINT(light, windowed, karis) radiance += LIT(SHEENED(shadePointLight(light, windowed, karis, material, vPosition, N, V), \
    sheenPointLight(light, windowed, karis, sheen, vPosition, N, V))); \
    TRANSMITTED(LIT(transmissionPointLight(light, windowed, karis, transmission, vPosition, N, V))) \
    COATED(LIT(clearcoatPointLight(light, windowed, karis, coat, vPosition, V)))
#define SHADE_DIRECTIONAL(light) radiance += LIT(SHEENED(shadeDirectionalLight(light, material, N, V), \
    sheenDirectionalLight(light, sheen, N, V))); \
    TRANSMITTED(LIT(transmissionDirectionalLight(light, transmission, N, V))) \
    COATED(LIT(clearcoatDirectionalLight(light, coat, V)))
#define SHADE_HEMISPHERE(light) radiance += OCCLUDED(SHEENED(shadeHemisphereLight(light, material, N, V), \
    sheenHemisphereLight(light, sheen, N))); \
    TRANSMITTED(OCCLUDED(BEYOND(transmissionHemisphereLight(light, transmission, V))))
#define SHADE_SPHERE(light, windowed, karis) radiance += LIT(SHEENED(shadeSphereLight(light, windowed, karis, material, vPosition, N, V), \
    sheenSphereLight(light, windowed, karis, sheen, vPosition, N, V))); \
    TRANSMITTED(LIT(transmissionSphereLight(light, windowed, karis, transmission, vPosition, N, V))) \
    COATED(LIT(clearcoatSphereLight(light, windowed, karis, coat, vPosition, V)))
#define SHADE_TUBE(light, windowed, karis) radiance += LIT(SHEENED(shadeTubeLight(light, windowed, karis, material, vPosition, N, V), \
    sheenTubeLight(light, windowed, karis, sheen, vPosition, N, V))); \
    TRANSMITTED(LIT(transmissionTubeLight(light, windowed, karis, transmission, vPosition, N, V))) \
    COATED(LIT(clearcoatTubeLight(light, windowed, karis, coat, vPosition, V)))
    PATINA_LIGHTS
#elif defined(PATINA_SINGLE_PASS)
    // Lights come grouped by type (engine/scene/light_packing.h): a loop per type, no type branch.
    // Each loop tests at its end. llvmpipe has no jump for a test all lanes agree on: a body
    // runs until no lane is left in the loop, so a test at the top costs one more pass of the
    // body with every lane off. The `if` costs such a pass when a type has no lights, so the
    // renderer compiles out the loop of a type the scene lacks.
#ifdef PATINA_KARIS_POINTS
    const bool karisPoints = true;   // every point light has KARIS_ATTENUATION
#else
    const bool karisPoints = false;
#endif
    int first = 0;
    int end = uLightCount.y;
#ifndef PATINA_NO_POINT_LIGHTS
    if (first < end) {
        int i = first;
        do {
            SHADOW_OF(uLights[i])
            radiance += LIT(SHEENED(shadePointLight(uLights[i], true, karisPoints, material, vPosition, N, V),
                                    sheenPointLight(uLights[i], true, karisPoints, sheen, vPosition, N, V)));
            TRANSMITTED(LIT(transmissionPointLight(uLights[i], true, karisPoints, transmission, vPosition, N, V)))
            COATED(LIT(clearcoatPointLight(uLights[i], true, karisPoints, coat, vPosition, V)))
        } while (++i < end);
    }
#endif
    first = end;
    end += uLightCount.z;
#ifndef PATINA_NO_DIRECTIONAL_LIGHTS
    if (first < end) {
        int i = first;
        do {
            SHADOW_OF(uLights[i])
            radiance += LIT(SHEENED(shadeDirectionalLight(uLights[i], material, N, V),
                                    sheenDirectionalLight(uLights[i], sheen, N, V)));
            TRANSMITTED(LIT(transmissionDirectionalLight(uLights[i], transmission, N, V)))
            COATED(LIT(clearcoatDirectionalLight(uLights[i], coat, V)))
        } while (++i < end);
    }
#endif
    first = end;
    end += uLightCount.w;
#ifndef PATINA_NO_HEMISPHERE_LIGHTS
    if (first < end) {
        int i = first;
        do {
            radiance += OCCLUDED(SHEENED(shadeHemisphereLight(uLights[i], material, N, V),
                                         sheenHemisphereLight(uLights[i], sheen, N)));
            TRANSMITTED(OCCLUDED(BEYOND(transmissionHemisphereLight(uLights[i], transmission, V))))
        } while (++i < end);
    }
#endif
    first = end;
    end += uAreaLightCount.x;
#ifndef PATINA_NO_SPHERE_LIGHTS
    if (first < end) {
        int i = first;
        do {
            SHADOW_OF(uLights[i])
            radiance += LIT(SHEENED(shadeSphereLight(uLights[i], true, karisPoints, material, vPosition, N, V),
                                    sheenSphereLight(uLights[i], true, karisPoints, sheen, vPosition, N, V)));
            TRANSMITTED(LIT(transmissionSphereLight(uLights[i], true, karisPoints, transmission, vPosition, N, V)))
            COATED(LIT(clearcoatSphereLight(uLights[i], true, karisPoints, coat, vPosition, V)))
        } while (++i < end);
    }
#endif
    first = end;
    end += uAreaLightCount.y;
#ifndef PATINA_NO_TUBE_LIGHTS
    if (first < end) {
        int i = first;
        do {
            SHADOW_OF(uLights[i])
            radiance += LIT(SHEENED(shadeTubeLight(uLights[i], true, karisPoints, material, vPosition, N, V),
                                    sheenTubeLight(uLights[i], true, karisPoints, sheen, vPosition, N, V)));
            TRANSMITTED(LIT(transmissionTubeLight(uLights[i], true, karisPoints, transmission, vPosition, N, V)))
            COATED(LIT(clearcoatTubeLight(uLights[i], true, karisPoints, coat, vPosition, V)))
        } while (++i < end);
    }
#endif
#endif
#if defined(PATINA_SPECIALISED) || defined(PATINA_SINGLE_PASS)
#ifdef PATINA_ENVIRONMENT
    radiance += OCCLUDED(SHEENED(environmentRadiance(material, N, V), sheenEnvironmentShare(sheen, N)));
    TRANSMITTED(OCCLUDED(BEYOND(transmissionEnvironmentRadiance(transmission, material, V))))
    COATED(OCCLUDED(clearcoatEnvironmentRadiance(coat, V)))
#endif
#ifdef PATINA_TEXTURED
    radiance += surfaceEmission();
#endif
#else
#if defined(PATINA_ENVIRONMENT)
    if (uLightIndex < 0) {
        radiance = OCCLUDED(SHEENED(environmentRadiance(material, N, V), sheenEnvironmentShare(sheen, N)));
        TRANSMITTED(OCCLUDED(BEYOND(transmissionEnvironmentRadiance(transmission, material, V))))
        COATED(OCCLUDED(clearcoatEnvironmentRadiance(coat, V)))
    } else
#endif
    {
        PackedLight light = uLights[max(uLightIndex, 0)];
        SHADOW_OF(light)
        radiance = LIT(SHEENED(shadeLight(light, material, vPosition, N, V), sheenLight(light, sheen, vPosition, N, V)));
        COATED(LIT(clearcoatLight(light, coat, vPosition, V)))
#ifdef PATINA_TRANSMISSION
        vec3 throughWall = LIT(transmissionLight(light, transmission, vPosition, N, V));
        transmitted += light.type == LIGHT_HEMISPHERE ? OCCLUDED(BEYOND(throughWall)) : throughWall;
#endif
        if (light.type == LIGHT_HEMISPHERE) {
            radiance = OCCLUDED(radiance);
        }
    }
#ifdef PATINA_TEXTURED
    if (uEmissionPass) {
        radiance += surfaceEmission();
    }
#endif
#endif
#ifdef PATINA_TRANSMISSION
    // Through the base's wall, beneath the coat as the base's own light, and beneath the sheen:
    // weighed by its albedo scaling towards V (sheenViewWeight).
#ifdef PATINA_SHEEN
    transmitted *= sheenViewWeight(sheen);
#endif
    radiance += transmitted;
#endif
#ifdef PATINA_CLEARCOAT
    // The base, its emission too, seen through the coat, and the coat's own light.
    radiance = clearcoatOver(radiance, coatRadiance, coat);
#endif
#ifdef PATINA_SHADOW_CATCHER
    // The share of the ground's light (its luminance, so the background keeps its hue) that
    // its shadows leave: what reaches it over what would without them, the environment in both.
    const vec3 rec709 = vec3(0.2126f, 0.7152f, 0.0722f);
    float unshadowed = dot(radiance - catcherShadowed + catcherUnshadowed, rec709);
    radiance = vec3(unshadowed > 0.0f ? clamp(dot(radiance, rec709) / unshadowed, 0.0f, 1.0f) : 1.0f);
#endif
#ifdef PATINA_STAMPED
    fragColor = vec4(radiance, uSampleStamp);
#else
    fragColor = vec4(radiance, 1.0f);
#endif
#ifdef PATINA_DISPLAY_OUTPUT
    displayColor = vec4(displayTransform(radiance, uExposure, uTonemap), 1.0f);
#endif
}
