// Multi-pass depth pre-pass: lays down depth and a black mesh for the additive light passes.
out vec4 fragColor;

void main() {
    fragColor = vec4(0.0f, 0.0f, 0.0f, 1.0f);
}
