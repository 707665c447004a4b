// Linear HDR target -> display-referred sRGB bytes (display.glsl).
uniform sampler2D uHdr;
uniform float uExposure;
uniform int uTonemap;

out vec4 fragColor;

void main() {
    vec3 linear = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0).rgb;
    fragColor = vec4(displayTransform(linear, uExposure, uTonemap), 1.0f);
}
