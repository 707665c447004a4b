// Shades the mesh (or, with PATINA_PROBE, one probe row per pixel) in linear light.
// PATINA_SINGLE_PASS: every light of the block in one pass; otherwise only uLightIndex, and the
// renderer adds the passes with blending (the seed's multi-pass design). PATINA_KARIS_POINTS:
// every point light has KARIS_ATTENUATION, so single need not read the coefficients.
// PATINA_NO_POINT_LIGHTS, PATINA_NO_DIRECTIONAL_LIGHTS, PATINA_NO_HEMISPHERE_LIGHTS: single
// leaves out the loop of a type the scene lacks (ShadingPrograms::singlePassFor).
// PATINA_SPECIALISED: PATINA_LIGHTS lists the scene's enabled lights in order as SHADE_POINT(i,
// windowed, karis), SHADE_DIRECTIONAL(i) and SHADE_HEMISPHERE(i), so the shader has no light
// loop and no code for a type the scene lacks (engine/shader_specialisation.h builds the list).
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

layout(std140) uniform LightBlock {
    PackedLight uLights[MAX_LIGHTS];
    ivec4 uLightCount;   // all, points, directionals, hemispheres
};

#ifndef PATINA_SINGLE_PASS
uniform int uLightIndex;
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
    SurfaceMaterial material = deriveSurfaceMaterial(uBaseColor, uRoughness, uSpecular, uMetallic);
    vec3 N = safeNormalize(vNormal);
#ifdef PATINA_PROBE
    vec3 V = safeNormalize(vView);
#else
    vec3 V = safeNormalize(uCameraPosition - vPosition);
#endif
    vec3 radiance = vec3(0.0f);
#if defined(PATINA_SPECIALISED)
#define SHADE_POINT(i, windowed, karis) radiance += shadePointLight(uLights[i], windowed, karis, material, vPosition, N, V);
#define SHADE_DIRECTIONAL(i) radiance += shadeDirectionalLight(uLights[i], material, N, V);
#define SHADE_HEMISPHERE(i) radiance += shadeHemisphereLight(uLights[i], material, N, V);
// The benchmark's floor (PassMode::BrdfFloor): the BRDF and cosine alone for light i's
// direction, with none of the light handling above (no type, no attenuation, no branch).
// (One line: GLSL 3.30 has no line continuation.)
#define BRDF_ONLY(i) { vec3 L = uLights[i].directionToLight; BrdfValue f = evaluateBrdf(material, N, V, L); radiance += uLights[i].radiance * max(dot(N, L), 0.0f) * (f.diffuse + f.specular); }
    PATINA_LIGHTS
#elif defined(PATINA_SINGLE_PASS)
    // Lights come grouped by type (engine/light_packing.h): a loop per type, no type branch.
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
            radiance += shadePointLight(uLights[i], true, karisPoints, material, vPosition, N, V);
        } while (++i < end);
    }
#endif
    first = end;
    end += uLightCount.z;
#ifndef PATINA_NO_DIRECTIONAL_LIGHTS
    if (first < end) {
        int i = first;
        do {
            radiance += shadeDirectionalLight(uLights[i], material, N, V);
        } while (++i < end);
    }
#endif
    first = end;
    end += uLightCount.w;
#ifndef PATINA_NO_HEMISPHERE_LIGHTS
    if (first < end) {
        int i = first;
        do {
            radiance += shadeHemisphereLight(uLights[i], material, N, V);
        } while (++i < end);
    }
#endif
#else
    radiance = shadeLight(uLights[uLightIndex], material, vPosition, N, V);
#endif
    fragColor = vec4(radiance, 1.0f);
#ifdef PATINA_DISPLAY_OUTPUT
    displayColor = vec4(displayTransform(radiance, uExposure, uTonemap), 1.0f);
#endif
}
