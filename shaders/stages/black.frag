// Multi-pass depth pre-pass: lays down depth and a black mesh for the additive light passes,
// with the strip's stamp in alpha (RenderTargets::SampleStamp); they add 0 to it.
uniform float uSampleStamp;

out vec4 fragColor;

void main() {
    fragColor = vec4(0.0f, 0.0f, 0.0f, uSampleStamp);
}
