// A model's texture maps, with PATINA_TEXTURED (GLSL only): which UV set and transform each map
// reads, and what it does to the surface (glTF 2.0 sections 3.9.2-3.9.3, KHR_texture_transform),
// through texture.glsl's shared functions. The texture units filter; the sRGB maps decode before
// they filter (GL_SRGB8_ALPHA8, engine/gl/model_textures.h), at the level of detail
// texture.glsl computes, which the CPU twin computes too. Read by shade.frag, and by
// black.frag for MASK's cut-outs in the multi-pass depth pre-pass.
#ifdef PATINA_TEXTURED
in vec2 vUv0;
in vec2 vUv1;
in vec4 vTangent;   // world space; w = 0: the vertex has none

// The maps in SurfaceMap order (engine/gl/surface_map_uniforms.h): 0 base colour,
// 1 metallic-roughness, 2 normal, 3 occlusion, 4 emissive, then KHR_materials_clearcoat's
// 5 coat, 6 coat roughness, 7 coat normal (read only with PATINA_CLEARCOAT), then
// KHR_materials_sheen's 8 sheen colour, 9 sheen roughness (only with PATINA_SHEEN), then
// KHR_materials_transmission's 10 and KHR_materials_volume's 11 (only with PATINA_TRANSMISSION), then
// KHR_materials_specular's 12 specular colour and 13 specular (only with PATINA_SPECULAR), then
// KHR_materials_iridescence's 14 and 15 (only with PATINA_IRIDESCENCE), then KHR_materials_anisotropy's
// 16 (only with PATINA_ANISOTROPY). A sampler array
// could be indexed only by constants in GLSL 3.30, so each has its own name.
uniform sampler2D uBaseColorMap;
uniform sampler2D uMetallicRoughnessMap;
uniform sampler2D uNormalMap;
uniform sampler2D uOcclusionMap;
uniform sampler2D uEmissiveMap;
uniform sampler2D uClearcoatMap;
uniform sampler2D uClearcoatRoughnessMap;
uniform sampler2D uClearcoatNormalMap;
uniform sampler2D uSheenColorMap;
uniform sampler2D uSheenRoughnessMap;
uniform sampler2D uTransmissionMap;
uniform sampler2D uThicknessMap;
uniform sampler2D uSpecularColorMap;
uniform sampler2D uSpecularMap;
uniform sampler2D uIridescenceMap;
uniform sampler2D uIridescenceThicknessMap;
uniform sampler2D uAnisotropyMap;
uniform vec4 uMapPlacement[17];   // KHR_texture_transform: offset (xy), scale (zw)
uniform vec2 uMapRotationSet[17];   // its rotation; the UV set read, -1 where there is no map
uniform float uBaseAlpha;          // baseColorFactor's alpha
uniform float uAlphaCutoff;        // MASK's; negative for OPAQUE and BLEND
uniform float uNormalScale;
uniform float uOcclusionStrength;
uniform vec3 uEmissive;            // emissiveFactor times KHR_materials_emissive_strength

// glTF 2.0 section 3.9.2: COLOR_0 multiplies the base colour factor and its alpha, as a map
// does (PATINA_VERTEX_COLOR, only in a frame with an item that has it; mesh.vert's vColor).
#ifdef PATINA_VERTEX_COLOR
in vec4 vColor;
#define VERTEX_COLOR vColor
#else
#define VERTEX_COLOR vec4(1.0f)
#endif

// PATINA_MAP_SET (the specialised path): the item's maps, a bit each in this order, known when
// compiling, so that a map the item lacks costs nothing (on llvmpipe a branch every lane agrees
// on still runs its body with the lanes off). The uniform still says whether an image is there.
bool hasMap(int map) {
#ifdef PATINA_MAP_SET
    if (((PATINA_MAP_SET >> map) & 1) == 0) {
        return false;
    }
#endif
    return uMapRotationSet[map].y >= 0.0f;
}

vec2 mapCoordinate(int map) {
    vec2 uv = uMapRotationSet[map].y > 0.5f ? vUv1 : vUv0;
    return transformTextureCoordinate(uv, uMapPlacement[map].xy, uMapPlacement[map].zw, uMapRotationSet[map].x);
}

// A map's texel at `coordinate`, at texture.glsl's level of detail (not the texture unit's own
// choice, so that the CPU twin reads the same levels).
vec4 mapTexel(sampler2D map, vec2 coordinate) {
    vec2 size = vec2(textureSize(map, 0));
    return textureLod(map, coordinate, textureLevelOfDetail(dFdx(coordinate), dFdy(coordinate), size));
}

// A map's texel, or `absent` (what multiplies as nothing) where the material has no such map.
// Whether it has one is uniform, so the coordinate's derivatives are defined.
#define MAP_TEXEL(map, sampler, absent) (hasMap(map) ? mapTexel(sampler, mapCoordinate(map)) : (absent))

// glTF 2.0 section 3.9.4: MASK draws a pixel only where the factor's alpha times the base
// colour map's (and the vertex colour's) reaches the cutoff (alpha 1 and a cutoff of 0.5 where
// neither says otherwise).
void discardMasked() {
    if (uAlphaCutoff >= 0.0f && uBaseAlpha * VERTEX_COLOR.w * MAP_TEXEL(0, uBaseColorMap, vec4(1.0f)).w < uAlphaCutoff) {
        discard;
    }
}

// The normal map's normal about N (unit, facing the viewer as shaded): texture.glsl's
// normalMappedNormal in the interpolated tangent frame.
vec3 mappedNormal(vec3 N) {
    if (!hasMap(2)) {
        return N;
    }
    vec3 texel = mapTexel(uNormalMap, mapCoordinate(2)).xyz;
    return normalMappedNormal(N, vTangent, tangentSpaceNormal(texel, uNormalScale));
}

#ifdef PATINA_CLEARCOAT
uniform float uClearcoatNormalScale;

// KHR_materials_clearcoat's maps: the coat's weight times its map's R, its roughness times its
// map's G (the glTF channels), and the coat's own normal map about N, the geometric normal as
// shaded (without its map, the coat follows N: not the base's normal map).
float mappedClearcoat(float factor) {
    return factor * MAP_TEXEL(5, uClearcoatMap, vec4(1.0f)).x;
}
float mappedClearcoatRoughness(float roughness) {
    return roughness * MAP_TEXEL(6, uClearcoatRoughnessMap, vec4(1.0f)).y;
}
vec3 mappedClearcoatNormal(vec3 N) {
    if (!hasMap(7)) {
        return N;
    }
    vec3 texel = mapTexel(uClearcoatNormalMap, mapCoordinate(7)).xyz;
    return normalMappedNormal(N, vTangent, tangentSpaceNormal(texel, uClearcoatNormalScale));
}
#endif

#ifdef PATINA_SHEEN
// KHR_materials_sheen's maps: the sheen's colour times its map's RGB (sRGB, decoded by the
// texture), its roughness times its map's A.
vec3 mappedSheenColor(vec3 factor) {
    return factor * MAP_TEXEL(8, uSheenColorMap, vec4(1.0f)).xyz;
}
float mappedSheenRoughness(float roughness) {
    return roughness * MAP_TEXEL(9, uSheenRoughnessMap, vec4(1.0f)).w;
}
#endif

#ifdef PATINA_TRANSMISSION
// KHR_materials_transmission's map: the factor times its R; KHR_materials_volume's: the
// thickness times its G (the glTF channels).
float mappedTransmission(float factor) {
    return factor * MAP_TEXEL(10, uTransmissionMap, vec4(1.0f)).x;
}
float mappedThickness(float thickness) {
    return thickness * MAP_TEXEL(11, uThicknessMap, vec4(1.0f)).y;
}
#endif

#ifdef PATINA_SPECULAR
// KHR_materials_specular's maps: the tint times its map's RGB (sRGB, decoded by the texture; the
// extension's specularColorTexture multiplies specularColorFactor, which the tint stands for), the
// weight times its map's A.
vec3 mappedSpecularTint(vec3 tint) {
    return tint * MAP_TEXEL(12, uSpecularColorMap, vec4(1.0f)).xyz;
}
float mappedSpecularWeight(float weight) {
    return weight * MAP_TEXEL(13, uSpecularMap, vec4(1.0f)).w;
}
#endif

#ifdef PATINA_IRIDESCENCE
// KHR_materials_iridescence's maps: the strength times its map's R; the thickness between the
// range's minimum (x) and maximum (y) by its map's G, the maximum without one.
float mappedIridescence(float factor) {
    return factor * MAP_TEXEL(14, uIridescenceMap, vec4(1.0f)).x;
}
float mappedIridescenceThickness(vec2 range) {
    return hasMap(15) ? mix(range.x, range.y, mapTexel(uIridescenceThicknessMap, mapCoordinate(15)).y) : range.y;
}
#endif

#ifdef PATINA_ANISOTROPY
// KHR_materials_anisotropy's map: RG a direction in the tangent frame in [-1, 1] (glTF's texel
// (1, 0.5) is +t, the map's absence), turned by the rotation (cos, sin); B scales the strength.
// (cos, sin) of the direction in xy, the strength in z.
vec3 mappedAnisotropy(vec2 direction, float strength) {
    vec3 texel = MAP_TEXEL(16, uAnisotropyMap, vec4(1.0f, 0.5f, 1.0f, 1.0f)).xyz;
    vec2 d = vec2(2.0f * texel.x - 1.0f, 2.0f * texel.y - 1.0f);
    float length2 = dot(d, d);
    d = length2 > 1e-12f ? d * inversesqrt(length2) : vec2(1.0f, 0.0f);
    return vec3(direction.x * d.x - direction.y * d.y, direction.y * d.x + direction.x * d.y, strength * texel.z);
}
#endif

// What reaches the environment's and hemisphere lights' light (1 without an occlusion map).
float surfaceOcclusion() {
    return hasMap(3) ? occlusionFactor(mapTexel(uOcclusionMap, mapCoordinate(3)).x, uOcclusionStrength) : 1.0f;
}

// Linear radiance the surface emits.
vec3 surfaceEmission() {
    return uEmissive * MAP_TEXEL(4, uEmissiveMap, vec4(1.0f)).xyz;
}
#endif
