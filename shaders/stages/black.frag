// Multi-pass depth pre-pass: lays down depth and a black mesh for the additive light passes,
// with the strip's stamp in alpha (RenderTargets::SampleStamp); they add 0 to it. With
// PATINA_TEXTURED after texture.glsl and surface_maps.glsl.
uniform float uSampleStamp;

out vec4 fragColor;

void main() {
#ifdef PATINA_TEXTURED
    discardMasked();   // MASK's cut-outs lay down no depth (surface_maps.glsl)
#endif
    fragColor = vec4(0.0f, 0.0f, 0.0f, uSampleStamp);
}
