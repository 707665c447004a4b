// The display pass: linear HDR -> display-referred sRGB values (display.glsl), with the linear
// image written too where the renderer keeps it. With PATINA_MULTISAMPLED it is also the MSAA
// resolve: it reads one strip's samples and writes their mean, so no resolved copy is made
// first (location 0 the linear mean, location 1 its display value, as shade.frag's outputs).
// PATINA_SAMPLE_COUNT: the samples the GL made; a constant, the loop unrolls (llvmpipe runs a
// loop of a uniform count with per-lane masks: 4-8% of a 512x512 frame).
#ifdef PATINA_MULTISAMPLED
uniform sampler2DMS uSamples;
uniform int uStripTop;   // the strip's first row in the image
// The samples are not cleared: one whose alpha is not this strip's stamp was not drawn in this
// strip and is background (RenderTargets::SampleStamp).
uniform float uSampleStamp;
uniform vec3 uBackground;
#else
uniform sampler2D uHdr;
#endif
uniform float uExposure;
uniform int uTonemap;

layout(location = 0) out vec4 linearColor;
layout(location = 1) out vec4 displayColor;

void main() {
#ifdef PATINA_MULTISAMPLED
    ivec2 texel = ivec2(gl_FragCoord.xy) - ivec2(0, uStripTop);
    vec3 sum = vec3(0.0f);
    for (int i = 0; i < PATINA_SAMPLE_COUNT; ++i) {
        vec4 value = texelFetch(uSamples, texel, i);
        sum += value.a == uSampleStamp ? value.rgb : uBackground;
    }
    vec3 linear = sum / float(PATINA_SAMPLE_COUNT);
#else
    vec3 linear = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0).rgb;
#endif
    linearColor = vec4(linear, 1.0f);
    displayColor = vec4(displayTransform(linear, uExposure, uTonemap), 1.0f);
}
