// A draw item's vertices in its primitive's space, placed in the world by uModel; normals go
// through the inverse transpose, uNormalMatrix (model/placement.h; glTF 2.0 §3.7.2.1). Both are
// the identity for a mesh drawn where it is (the built-in meshes), and multiplying by the
// identity is exact: those images are the same bits as before meshes had transforms.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uViewProjection;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vPosition;
out vec3 vNormal;

#ifdef PATINA_TEXTURED
// A model's UV sets and tangents for its maps (surface_maps.glsl); attributes a mesh lacks
// read GL's default (0, 0, 0, 1), a tangent with no direction, which the maps take for none.
layout(location = 2) in vec2 aUv0;
layout(location = 3) in vec2 aUv1;
layout(location = 4) in vec4 aTangent;
out vec2 vUv0;
out vec2 vUv1;
out vec4 vTangent;
#endif

#ifdef PATINA_VERTEX_COLOR
// glTF's COLOR_0 (linear RGBA), handed on for surface_maps.glsl; an item without reads the
// attribute's constant, 1 (the renderer sets it).
layout(location = 6) in vec4 aColor;
out vec4 vColor;
#endif

#if defined(PATINA_ANISOTROPY) && !defined(PATINA_TEXTURED)
// KHR_materials_anisotropy's direction turns from the tangent (shade.frag); without maps only
// the tangent is handed on (a mesh without reads (0, 0, 0, 1): the fallback's).
layout(location = 4) in vec4 aTangent;
out vec4 vTangent;
#endif

#ifdef PATINA_AMBIENT_OCCLUSION
// The item's ambient occlusion baked at its vertices (engine/scene/ambient_occlusion.h), handed
// on for shade.frag; an item without reads the attribute's constant, 1 (the renderer sets it).
layout(location = 5) in float aAmbientOcclusion;
out float vAmbientOcclusion;
#endif

#ifdef PATINA_FLAT_LIGHT_COUNT
// A specialised shader's first lights, handed on unchanged as flat inputs: on llvmpipe a vertex
// shader loads a uniform scalar once per 8 vertices, a fragment shader gathers it lane by lane
// per 8 pixels, and a flat input costs the fragment shader one load per block of pixels
// (docs/PERFORMANCE.md). PATINA_FLAT_LIGHTS lists FLAT_POINT(i), FLAT_DIRECTIONAL(i),
// FLAT_HEMISPHERE(i), FLAT_SPHERE(i) and FLAT_TUBE(i), each light's two rows (shade.frag's
// flatLight unpacks them; a tube's end, a third row, stays in the block).
flat out vec4 vFlatLight[2 * PATINA_FLAT_LIGHT_COUNT];
void writeFlatLight(int i, vec3 first, float firstW, vec3 second, float secondW) {
    vFlatLight[2 * i] = vec4(first, firstW);
    vFlatLight[2 * i + 1] = vec4(second, secondW);
}
#define FLAT_POINT(i) writeFlatLight(i, uLights[i].radiance, uLights[i].inverseRange, uLights[i].position, 0.0f);
#define FLAT_DIRECTIONAL(i) writeFlatLight(i, uLights[i].radiance, 0.0f, uLights[i].directionToLight, 0.0f);
#define FLAT_HEMISPHERE(i) writeFlatLight(i, uLights[i].sky, 0.0f, uLights[i].ground, 0.0f);
#define FLAT_SPHERE(i) \
    writeFlatLight(i, uLights[i].radiance, uLights[i].inverseRange, uLights[i].position, uLights[i].sourceRadius);
#define FLAT_TUBE(i) FLAT_SPHERE(i)
#endif

// The multi-pass path draws the mesh once per light with depth test EQUAL: every pass must
// produce bit-identical depth. Each pass computes it by the same expression from the same
// uniforms (the depth pre-pass and the light passes set one item's uModel alike).
invariant gl_Position;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0f);
    vPosition = world.xyz;
    vNormal = uNormalMatrix * aNormal;
#ifdef PATINA_TEXTURED
    vUv0 = aUv0;
    vUv1 = aUv1;
    // A tangent lies in the surface, so it moves as positions do. Under a mirror the normal
    // (through the inverse transpose) and this tangent make a frame of the other handedness:
    // w turns so that cross(N, T) w stays the bitangent the map was baked with (glTF 2.0
    // section 3.7.2.1 defines it in the mesh's own space).
    mat3 linear = mat3(uModel);
    vTangent = vec4(linear * aTangent.xyz, determinant(linear) < 0.0f ? -aTangent.w : aTangent.w);
#elif defined(PATINA_ANISOTROPY)
    mat3 linear = mat3(uModel);
    vTangent = vec4(linear * aTangent.xyz, determinant(linear) < 0.0f ? -aTangent.w : aTangent.w);
#endif
#ifdef PATINA_VERTEX_COLOR
    vColor = aColor;
#endif
#ifdef PATINA_AMBIENT_OCCLUSION
    vAmbientOcclusion = aAmbientOcclusion;
#endif
#ifdef PATINA_FLAT_LIGHT_COUNT
    PATINA_FLAT_LIGHTS
#endif
    gl_Position = uViewProjection * world;
}
