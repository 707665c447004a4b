// The environment behind the mesh (DisplaySettings::backgroundFromEnvironment): each pixel's
// view ray, turned into the environment's frame as the lighting is, read from the prefiltered
// chain at the blur's roughness. Writes what shade.frag writes, so resolve and display treat
// it as drawn.
uniform mat4 uInverseViewProjection;
uniform vec3 uCameraPosition;
uniform vec4 uViewport;   // x, y, width, height of the whole image's viewport (strips move it)
uniform float uBlur;
// As in shade.frag: the stamp only where MSAA samples need it.
#ifndef PATINA_DISPLAY_OUTPUT
#define PATINA_STAMPED
uniform float uSampleStamp;
#endif

layout(location = 0) out vec4 fragColor;
#ifdef PATINA_DISPLAY_OUTPUT
uniform float uExposure;
uniform int uTonemap;
layout(location = 1) out vec4 displayColor;
#endif

void main() {
    vec2 ndc = (gl_FragCoord.xy - uViewport.xy) / uViewport.zw * 2.0f - 1.0f;
    vec4 far = uInverseViewProjection * vec4(ndc, 1.0f, 1.0f);
    vec3 direction = normalize(far.xyz / far.w - uCameraPosition);
    vec3 d = toEnvironmentFrame(direction, uEnvironmentRotation.x, uEnvironmentRotation.y);
    vec3 radiance = uEnvironmentIntensity * textureLod(uEnvironmentMap, d, roughnessToLod(uBlur, uEnvironmentMaxLod)).rgb;
#ifdef PATINA_STAMPED
    fragColor = vec4(radiance, uSampleStamp);
#else
    fragColor = vec4(radiance, 1.0f);
#endif
#ifdef PATINA_DISPLAY_OUTPUT
    displayColor = vec4(displayTransform(radiance, uExposure, uTonemap), 1.0f);
#endif
}
