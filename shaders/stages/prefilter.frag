// One face of one level of the prefiltered chain (shaders/shared/ibl.glsl's prefilterEnvironment),
// a texel a fragment: engine/gl/gpu_prefilter.cpp draws it, the CPU's twin is
// engine/environment/prefilter.cpp. Row t of the face is the fragment row y = t.
uniform int uFace;
uniform float uLevelSize;
uniform float uRoughness;
uniform int uSamples;

layout(location = 0) out vec4 fragColor;

void main() {
    vec2 st = gl_FragCoord.xy / uLevelSize * 2.0f - 1.0f;
    vec3 R = normalize(cubeFaceDirection(uFace, st.x, st.y));
    fragColor = vec4(prefilterEnvironment(uEnvironmentSource, R, uRoughness, uint(uSamples), uEnvironmentSourceSize),
                     1.0f);
}
