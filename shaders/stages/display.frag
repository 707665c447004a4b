// The display pass: linear HDR -> display-referred sRGB values (display.glsl), with the linear
// image written too where the renderer keeps it. With PATINA_MULTISAMPLED it is also the MSAA
// resolve: it reads one strip's samples and writes their mean, so no resolved copy is made
// first (location 0 the linear mean, location 1 its display value, as shade.frag's outputs).
// PATINA_SAMPLE_COUNT: the samples the GL made; a constant, the loop unrolls (llvmpipe runs a
// loop of a uniform count with per-lane masks: 4-8% of a 512x512 frame).
// The flat background is shown as its swatch (srgbColor), not tone-mapped: a pixel
// partly covered shows the drawn samples' display value over it, by their share of the pixel.
// PATINA_CAUGHT_BACKGROUND: the shadow catcher darkened the flat background (alpha the stamp
// negated, or -1 without MSAA): such a sample is background still, shown as its swatch is
// (srgbColor of its darkened value), not tone-mapped.
#ifdef PATINA_MULTISAMPLED
uniform sampler2DMS uSamples;
uniform int uStripTop;   // the strip's first row in the image
// The samples are not cleared: one whose alpha is not this strip's stamp was not drawn in this
// strip and is background (RenderTargets::SampleStamp).
uniform float uSampleStamp;
#else
// Alpha 0 where nothing was drawn (the renderer clears it so), 1 where the mesh or the
// environment background was.
uniform sampler2D uHdr;
#endif
uniform vec3 uBackground;
uniform float uExposure;
uniform int uTonemap;

layout(location = 0) out vec4 linearColor;
layout(location = 1) out vec4 displayColor;

void main() {
#ifdef PATINA_MULTISAMPLED
    ivec2 texel = ivec2(gl_FragCoord.xy) - ivec2(0, uStripTop);
    vec3 sum = vec3(0.0f);     // every sample, the background's included: the linear mean
    vec3 drawn = vec3(0.0f);   // the drawn samples only: what is tone-mapped
    int count = 0;
#ifdef PATINA_CAUGHT_BACKGROUND
    vec3 backdrop = vec3(0.0f);   // the background samples' display values
#endif
    for (int i = 0; i < PATINA_SAMPLE_COUNT; ++i) {
        vec4 value = texelFetch(uSamples, texel, i);
        if (value.a == uSampleStamp) {
            sum += value.rgb;
            drawn += value.rgb;
            count += 1;
#ifdef PATINA_CAUGHT_BACKGROUND
        } else if (value.a == -uSampleStamp) {
            sum += value.rgb;
            backdrop += srgbColor(value.rgb);
        } else {
            sum += uBackground;
            backdrop += srgbColor(uBackground);
#else
        } else {
            sum += uBackground;
#endif
        }
    }
    vec3 linear = sum / float(PATINA_SAMPLE_COUNT);
    float coverage = float(count) / float(PATINA_SAMPLE_COUNT);
    vec3 drawnMean = count > 0 ? drawn / float(count) : vec3(0.0f);
#ifdef PATINA_CAUGHT_BACKGROUND
    vec3 backdropShown = count < PATINA_SAMPLE_COUNT ? backdrop / float(PATINA_SAMPLE_COUNT - count) : vec3(0.0f);
#endif
#else
    vec4 value = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0);
    vec3 linear = value.rgb;
    float coverage = value.a > 0.5f ? 1.0f : 0.0f;
    vec3 drawnMean = value.rgb;
#ifdef PATINA_CAUGHT_BACKGROUND
    vec3 backdropShown = srgbColor(value.a < -0.5f ? value.rgb : uBackground);
#endif
#endif
#ifndef PATINA_CAUGHT_BACKGROUND
    vec3 backdropShown = srgbColor(uBackground);
#endif
    linearColor = vec4(linear, 1.0f);
    displayColor = vec4(mix(backdropShown, displayTransform(drawnMean, uExposure, uTonemap), coverage), 1.0f);
}
