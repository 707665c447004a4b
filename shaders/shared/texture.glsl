// Texture lookups and the textured material, shared by the GPU and the CPU twin
// (engine/shading/texture_sampling.cpp). GLSL 3.30 and C++ through GLM, as brdf.glsl says:
// no swizzles, no overloads, PATINA_INLINE before each function, no sampler types here (the
// GPU samples with its texture units, the CPU with sampleTexture). UV (0, 0) is the image's
// top-left texel and v grows downward (glTF 2.0, 3.8.3 Images): nothing here flips.
// The sRGB decode of base colour and emissive texels is display.glsl's srgbDecode (the GPU's
// sRGB formats decode before they filter; the CPU decodes once per texel).

// glTF 2.0, 3.8.4.3 Wrapping, in TextureWrap's order (engine/shading/texture.h).
const int TEXTURE_WRAP_REPEAT = 0;
const int TEXTURE_WRAP_CLAMP_TO_EDGE = 1;
const int TEXTURE_WRAP_MIRRORED_REPEAT = 2;

// i mod size in [0, size) for any sign of i: GLSL's % is undefined for a negative operand,
// so the quotient is rounded down by hand.
PATINA_INLINE int floorModulo(int i, int size) {
    int quotient = i >= 0 ? i / size : -((-i - 1) / size) - 1;
    return i - quotient * size;
}

// The texel a wrap mode reads for texel index i of a row `size` long (OpenGL 4.6 core, 8.14.2
// "Coordinate Wrapping and Texel Selection": the modes act on integer texel indices, so
// bilinear filtering wraps each of its two neighbours on its own). Mirrored repeat runs
// 0 .. size-1, size-1 .. 0 with period 2 size.
PATINA_INLINE int wrapTexel(int i, int size, int mode) {
    if (mode == TEXTURE_WRAP_CLAMP_TO_EDGE) {
        return clamp(i, 0, size - 1);
    }
    if (mode == TEXTURE_WRAP_MIRRORED_REPEAT) {
        int m = floorModulo(i, 2 * size);
        return m < size ? m : 2 * size - 1 - m;
    }
    return floorModulo(i, size);
}

// KHR_texture_transform: uv' = offset + R (scale uv), R (u, v) = (cos t u + sin t v,
// -sin t u + cos t v). This is the direction three.js, Babylon.js and the extension's
// TextureTransformTest sample model agree on; the README's GLSL listing, read column-major,
// turns the other way (KhronosGroup/glTF issue 1563).
PATINA_INLINE vec2 transformTextureCoordinate(vec2 uv, vec2 offset, vec2 scale, real rotation) {
    vec2 scaled = scale * uv;
    real c = cos(rotation);
    real s = sin(rotation);
    return offset + vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y);
}

// The level of detail a lookup reads (OpenGL 4.6 core, 8.14.1 "Scale Factor and Level of
// Detail", equations 8.6-8.9 in their isotropic form): rho, the larger of the lengths, in
// texels, of the coordinate's derivatives along the window's x and y, and lambda = log2(rho).
// `size` is level 0's in texels. The GPU passes it to textureLod with dFdx and dFdy of the
// coordinate; the CPU twin with differences of the coordinates at neighbouring pixel centres.
// A coordinate that does not move gives a level far below 0: magnification.
PATINA_INLINE real textureLevelOfDetail(vec2 dUvDx, vec2 dUvDy, vec2 size) {
    vec2 x = dUvDx * size;
    vec2 y = dUvDy * size;
    real rho = max(sqrt(dot(x, x)), sqrt(dot(y, y)));
    return log2(max(rho, 1e-20f));
}

// glTF 2.0, 3.9.3 Additional Textures (normalTexture): the texel's RGB maps [0, 1] to
// [-1, 1]; scale multiplies X and Y, then the vector is normalised.
PATINA_INLINE vec3 tangentSpaceNormal(vec3 texel, real scale) {
    vec3 n = 2.0f * texel - vec3(1.0f);
    return normalize(vec3(n.x * scale, n.y * scale, n.z));
}

// The shading normal from the tangent-space one (glTF 2.0, 3.7.2.1: the bitangent is
// cross(N, T.xyz) * T.w, and the map's +Y points along it). N and T are as interpolated;
// T.w = -1 marks mirrored UVs and turns the bitangent round.
PATINA_INLINE vec3 perturbedNormal(vec3 N, vec4 T, vec3 tangentNormal) {
    vec3 tangent = vec3(T.x, T.y, T.z);
    vec3 bitangent = cross(N, tangent) * T.w;
    return normalize(tangent * tangentNormal.x + bitangent * tangentNormal.y + N * tangentNormal.z);
}

// The normal map's normal about N (unit, as shaded) in the interpolated tangent frame T: the
// tangent is made orthogonal to N first (interpolation leaves it a little off). Where the
// vertex has no tangent (w = 0, or no direction left once orthogonal) N stays: the map has no
// frame to be read in.
PATINA_INLINE vec3 normalMappedNormal(vec3 N, vec4 T, vec3 tangentNormal) {
    vec3 tangent = vec3(T.x, T.y, T.z);
    tangent = tangent - N * dot(N, tangent);
    if (T.w == 0.0f || !(dot(tangent, tangent) > 1e-12f)) {
        return N;
    }
    tangent = normalize(tangent);
    return perturbedNormal(N, vec4(tangent.x, tangent.y, tangent.z, T.w < 0.0f ? -1.0f : 1.0f), tangentNormal);
}

// glTF 2.0, 3.9.3 Additional Textures (occlusionTexture): 1 + strength (R - 1). Patina applies
// it to the environment and hemisphere light only, not to direct lights.
PATINA_INLINE real occlusionFactor(real occlusionTexel, real strength) {
    return 1.0f + strength * (occlusionTexel - 1.0f);
}

// A metallic-roughness material once its maps are read.
struct TexturedMaterial {
    vec3 baseColor;   // linear
    real alpha;
    real roughness;   // perceptual
    real metallic;
};

// glTF 2.0, 3.9.2 Metallic-Roughness Material: each factor times its texel, base colour RGBA
// (the texel already sRGB-decoded, alpha linear), roughness from G, metallic from B of the
// metallicRoughnessTexture (R is unused; ORM packings keep occlusion there).
PATINA_INLINE TexturedMaterial texturedMaterial(vec4 baseColorFactor, vec4 baseColorTexel, real roughnessFactor,
                                                real metallicFactor, vec4 metallicRoughnessTexel) {
    vec4 base = baseColorFactor * baseColorTexel;
    return TexturedMaterial(vec3(base.x, base.y, base.z), base.w, roughnessFactor * metallicRoughnessTexel.y,
                            metallicFactor * metallicRoughnessTexel.z);
}
